// The steps of a run, shared by `micro pack`, `micro run` and `micro sweep`:
// make (or read) a packing and measure it, shear it, analyse its structure,
// write the record. The commands add what they print around them.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "common/atomic_output.h"
#include "micro/input/parameter_file.h"
#include "micro/io/run_file.h"
#include "micro/protocol/oscillatory_run.h"
#include "micro/protocol/quasi_static_run.h"

namespace softglass::micro {

/// The packing of `prm` (made and relaxed, or read from its `packing_input`)
/// with its G0, in a record for `command`. A progress bar unless `quiet`.
RunRecord pack_and_measure(const MicroParameters& prm, std::shared_ptr<const ContactLaw> law,
                           const std::string& command, bool quiet);

/// Checkpoints of a long run: every `every_steps` accepted steps into `file`;
/// a run whose checkpoint file exists goes on from it.
struct CheckpointSettings {
  std::filesystem::path file;  // empty: none
  std::size_t every_steps = 0;
};

/// Shears the packing of `record` at the state of `prm` until its stopping rule,
/// then analyses the structure of the stationary part (when it stored
/// snapshots). `progress` gets (strain, worst relative error).
void shear_and_analyse(RunRecord& record, const MicroParameters& prm,
                       std::shared_ptr<const ContactLaw> law,
                       const std::function<void(double, double)>& progress,
                       const CheckpointSettings& checkpoints = {});

/// Shears the packing of `record` quasi-statically (AQS, γ̃ = 0) until the
/// stopping rule of `prm.protocol`, then analyses the structure as above.
/// `progress` gets (strain, worst relative error). A checkpoint file of a
/// sheared run is refused (InputError).
void shear_quasi_statically_and_analyse(RunRecord& record, const MicroParameters& prm,
                                        std::shared_ptr<const ContactLaw> law,
                                        const QuasiStaticSettings& settings,
                                        const std::function<void(double, double)>& progress,
                                        const CheckpointSettings& checkpoints = {});

/// Shears the packing of `record` in oscillation (`protocol`, at the model of
/// `prm` with γ̃ = γ0 ω̃) until periodic. `progress` gets (cycles run, worst
/// relative error of G′, G″).
void oscillate(RunRecord& record, const MicroParameters& prm, std::shared_ptr<const ContactLaw> law,
               const OscillationProtocol& protocol,
               const std::function<void(double, double)>& progress,
               const CheckpointSettings& checkpoints = {});

/// Writes `record` into `out`'s temporary file and renames it into place.
void write_record(AtomicOutput& out, RunRecord& record, double total_seconds);

/// The wall time of a written record as a log line ends: "268.7 s", or for a
/// run resumed from a checkpoint "268.7 s, resumed from its checkpoint (164.4 s
/// of it before)" — the whole run's time, as the record keeps it, so that a
/// resumed case does not look short beside the others.
std::string logged_time(const RunRecord& record);

}  // namespace softglass::micro
