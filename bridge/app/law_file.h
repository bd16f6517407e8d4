// Reading law files (law/law.h; written by `bridge fit`) with deal.II's
// ParameterHandler, the parser of every softglass parameter file.
#pragma once

#include <filesystem>

#include "bridge/law/law.h"

namespace softglass::bridge {

/// Reads and validates `file`. Unknown entries, unparsable values, missing
/// required entries and inconsistent lists raise InputError naming the entry.
Law read_law_file(const std::filesystem::path& file);

}  // namespace softglass::bridge
