#include "micro/model/film.h"

#include <fmt/format.h>

#include "common/errors.h"

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

std::string film_velocity_names() {
  return "tangential|full|nonaffine";
}

}  // namespace softglass::micro
