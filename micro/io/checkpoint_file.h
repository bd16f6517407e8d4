// A running case's checkpoint (protocol/shear_run.h: ShearCheckpoint, or
// protocol/quasi_static_run.h: QuasiStaticCheckpoint) as an HDF5 file: written
// whole under a temporary name and renamed over the last one, so a kill at any
// moment leaves the previous checkpoint intact. The file's `kind` says which.
// A checkpoint also keeps the parameter text of its run's record
// (`parameters`, as a run file does), so that a run resumes from it only
// under the same computation (input/finished_work.h).
#pragma once

#include <filesystem>
#include <string>

#include "micro/protocol/quasi_static_run.h"
#include "micro/protocol/shear_run.h"

namespace softglass::micro {

void write_checkpoint(const std::filesystem::path& path, const ShearCheckpoint& checkpoint,
                      const std::string& parameters = {});
/// InputError naming the file if it is not a checkpoint or is inconsistent.
ShearCheckpoint read_checkpoint(const std::filesystem::path& path);

void write_checkpoint(const std::filesystem::path& path, const QuasiStaticCheckpoint& checkpoint,
                      const std::string& parameters = {});
/// InputError naming the file if it is not a quasi-static checkpoint or is inconsistent.
QuasiStaticCheckpoint read_quasi_static_checkpoint(const std::filesystem::path& path);

}  // namespace softglass::micro
