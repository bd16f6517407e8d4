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

// FilmLaw itself, inlined: compiled without trapping math, its two regimes
// become selects, and the loop is vectorised.
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
    const FilmLaw law{a[k], cross[k]};
    const double norm = std::sqrt(w[k]);
    w[k] = norm;
    s[k] = law.secant(norm);
    phi[k] = law.potential(norm);
  }
}

std::string film_velocity_names() {
  return "tangential|full|nonaffine";
}

}  // namespace softglass::micro
