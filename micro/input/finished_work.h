// A sweep reuses the files it finds finished (micro/app/sweep_command.cpp) only
// for the same computation: every packing and run file stores its complete
// parameters, and a rerun compares them with what the sweep file now gives.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace softglass::micro {

/// InputError unless the packing or run `file` was computed with `expected`
/// (its parameter text, as micro prints it). Entries that only say where files
/// are (`file`, `input file`) may differ: a folder may be moved. The message
/// names the first entry that differs, its stored and its new value. With
/// `subsections` given, only their entries are compared (a packing does not
/// depend on the shear that follows it).
void require_same_computation(const std::filesystem::path& file, const std::string& expected,
                              const std::vector<std::string>& subsections = {});

}  // namespace softglass::micro
