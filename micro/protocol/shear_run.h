// Steady shear at fixed γ̃ (the paper's protocol, docs/physics.md): overdamped
// dynamics sampled every `sample_interval` of strain until the stresses are
// stationary and known to the requested accuracy (shear_protocol.h), or the
// sample has layered. The stepping, sampling and checkpoints are the sampled
// run's (sampled_run.h).
#pragma once

#include <functional>

#include "micro/protocol/sampled_run.h"

namespace softglass::micro {

ShearResult run_shear(OverdampedShear& flow, Integrator& integrator, const ShearProtocol& protocol,
                      const std::function<void(const ShearProgress&)>& progress = {},
                      const ShearCheckpointing& checkpointing = {});

}  // namespace softglass::micro
