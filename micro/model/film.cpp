#include "micro/model/film.h"

#include <fmt/format.h>

#include "common/errors.h"
#include "micro/numerics/vector_clones.h"

namespace softglass::micro {

FilmVelocity parse_film_velocity(const std::string& name) {
  if (name == "tangential") return FilmVelocity::tangential;
  if (name == "full") return FilmVelocity::full;
  if (name == "nonaffine") return FilmVelocity::nonaffine;
  throw InputError(
      fmt::format("EHD velocity '{}' is unknown; allowed: {}", name, film_velocity_names()));
}

std::string to_string(FilmVelocity velocity) {
  switch (velocity) {
    case FilmVelocity::full:
      return "full";
    case FilmVelocity::nonaffine:
      return "nonaffine";
    default:
      return "tangential";
  }
}

// Both regimes from one root: r = √max(|w|, w*), so that s = a/r, and on the
// EHD branch (|w| ≥ w*) r = √|w| in ⅔ a |w|^{3/2}. The constant ⅙ a w*^{3/2}
// is taken as FilmLaw::potential takes it; for w* = 0 it is 0 and leaves the
// first term as it is.
SOFTGLASS_VECTOR_CLONES void evaluate_films(std::span<const double> coefficient,
                                            std::span<const double> crossover,
                                            std::span<double> speed, std::span<double> secant,
                                            std::span<double> potential) {
  const std::size_t n = speed.size();
  const double* a = coefficient.data();
  const double* cross = crossover.data();
  double* w = speed.data();
  double* s = secant.data();
  double* phi = potential.data();
  for (std::size_t k = 0; k < n; ++k) {
    const double norm = std::sqrt(w[k]);
    const bool linear = norm < cross[k];
    const double at = linear ? cross[k] : norm;
    const double root = std::sqrt(at);
    // (The divisor is never 0, so the division need not be guarded by a branch.)
    const double quotient = a[k] / (at > 0.0 ? root : 1.0);
    const double sec = at > 0.0 ? quotient : 0.0;
    const double quadratic = 0.5 * sec * norm * norm;
    const double ehd = (2.0 / 3.0) * a[k] * norm * root -
                       (1.0 / 6.0) * a[k] * cross[k] * std::sqrt(cross[k]);
    w[k] = norm;
    s[k] = sec;
    phi[k] = linear ? quadratic : ehd;
  }
}

std::string film_velocity_names() {
  return "tangential|full|nonaffine";
}

}  // namespace softglass::micro
