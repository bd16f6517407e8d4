#include "micro/analysis/plug_slip.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "micro/model/film.h"

namespace softglass::micro {

PlugSlipLaw::PlugSlipLaw(const WallContacts& contacts, double area, double rest_thickness)
    : area_(area) {
  if (!(area > 0.0)) throw std::invalid_argument("PlugSlipLaw: the wall area must be positive");
  // At γ̃ = 1 the film's reduced velocity is U itself: a_k √U and U*_k follow
  // from film.h's coefficient and crossover unchanged.
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const double rc = contacts.contact_radius[k], eps = contacts.deformation[k];
    const double a = film_coefficient(1.0, rc, contacts.force[k], eps);
    a_.push_back(a);
    crossover_.push_back(film_crossover(rest_thickness, 1.0, a, rc, eps));
    coefficient_ += a;
  }
  coefficient_ /= 2.0 * area_;  // the mean of the two walls
}

std::vector<double> PlugSlipLaw::crossovers() const {
  std::vector<double> sorted = crossover_;
  std::sort(sorted.begin(), sorted.end());
  return sorted;
}

double PlugSlipLaw::wall_stress(double speed) const {
  double sum = 0.0;
  for (std::size_t k = 0; k < a_.size(); ++k)
    sum += FilmLaw{a_[k], crossover_[k]}.secant(speed) * speed;
  return sum / (2.0 * area_);
}

}  // namespace softglass::micro
