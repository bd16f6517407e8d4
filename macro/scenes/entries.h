// Reading scene entries with the checks every one of them needs: the value
// must be finite and inside its physical range; otherwise one InputError
// naming the subsection, the entry, its value, its unit and what is allowed.
// (ParameterHandler's own patterns catch text that is not a number, such as a
// value with a unit attached, at parse time.)
#pragma once

#include <string>

namespace dealii {
class ParameterHandler;
}

namespace softglass::macro::entries {

/// Inside the current subsection `scene`: the entry's value, required > 0.
double positive(const dealii::ParameterHandler& prm, const std::string& scene,
                const std::string& entry, const std::string& unit);
/// Required ≥ 0.
double non_negative(const dealii::ParameterHandler& prm, const std::string& scene,
                    const std::string& entry, const std::string& unit);
/// Required in (lo, hi).
double between(const dealii::ParameterHandler& prm, const std::string& scene,
               const std::string& entry, const std::string& unit, double lo, double hi);

}  // namespace softglass::macro::entries
