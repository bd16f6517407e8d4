// A sweep reuses the files it finds finished (micro/app/sweep_command.cpp) only
// for the same computation: every packing and run file stores its complete
// parameters, and a rerun compares them with what the sweep file now gives.
// A running case's checkpoint stores them too, and resumes only under them.
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

/// InputError unless the checkpoint `file` was written by a run of `expected`
/// (compared as above), naming the first entry that differs: a run goes on
/// from a checkpoint only under the parameters that made it, so that its
/// record's parameters are those of every step it took. A checkpoint written
/// before checkpoints kept their run's parameters passes.
void require_checkpoint_of_same_computation(const std::filesystem::path& file,
                                            const std::string& expected);

}  // namespace softglass::micro
