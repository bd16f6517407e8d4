// A running case's checkpoint (protocol/shear_run.h: ShearCheckpoint, or
// protocol/quasi_static_run.h: QuasiStaticCheckpoint) as an HDF5 file: written
// whole under a temporary name and renamed over the last one, so a kill at any
// moment leaves the previous checkpoint intact. The file's `kind` says which.
#pragma once

#include <filesystem>

#include "micro/protocol/quasi_static_run.h"
#include "micro/protocol/shear_run.h"

namespace softglass::micro {

void write_checkpoint(const std::filesystem::path& path, const ShearCheckpoint& checkpoint);
/// InputError naming the file if it is not a checkpoint or is inconsistent.
ShearCheckpoint read_checkpoint(const std::filesystem::path& path);

void write_checkpoint(const std::filesystem::path& path, const QuasiStaticCheckpoint& checkpoint);
/// InputError naming the file if it is not a quasi-static checkpoint or is inconsistent.
QuasiStaticCheckpoint read_quasi_static_checkpoint(const std::filesystem::path& path);

}  // namespace softglass::micro
