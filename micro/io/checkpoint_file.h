// A running case's checkpoint (protocol/shear_run.h: ShearCheckpoint) as an
// HDF5 file: written whole under a temporary name and renamed over the last
// one, so a kill at any moment leaves the previous checkpoint intact.
#pragma once

#include <filesystem>

#include "micro/protocol/shear_run.h"

namespace softglass::micro {

void write_checkpoint(const std::filesystem::path& path, const ShearCheckpoint& checkpoint);
/// InputError naming the file if it is not a checkpoint or is inconsistent.
ShearCheckpoint read_checkpoint(const std::filesystem::path& path);

}  // namespace softglass::micro
