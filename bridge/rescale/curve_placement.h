// One measured curve placed on the universal law (rescale.h): its own
// Herschel–Bulkley fit, τ_y and E* fitted where not given, the rescaled points,
// the residuals and the N1 law. `rescale()` calls it per curve, and repeatedly
// at trial values of a shared E*.
#pragma once

#include <cstddef>

#include "bridge/rescale/rescale.h"

namespace softglass::bridge {

/// Curve `index` of the set (it picks the per-curve entries of `settings`);
/// `settings` checked by rescale(). InputError / NumericalError as rescale().
RescaledCurve place_curve(const MeasuredCurve& curve, std::size_t index,
                          const RescaleSettings& settings);

}  // namespace softglass::bridge
