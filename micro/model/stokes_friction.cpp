#include "micro/model/stokes_friction.h"

#include <fmt/format.h>

#include "common/errors.h"

namespace softglass::micro {

StokesReference parse_stokes_reference(const std::string& name) {
  if (name == "affine") return StokesReference::affine;
  if (name == "neighbours") return StokesReference::neighbours;
  throw InputError(
      fmt::format("Stokes reference '{}' is unknown; allowed: {}", name, stokes_reference_names()));
}

std::string to_string(StokesReference reference) {
  return reference == StokesReference::affine ? "affine" : "neighbours";
}

std::string stokes_reference_names() {
  return "affine|neighbours";
}

void StokesFriction::pair_coefficients(const ContactList& c, std::span<const double> zeta,
                                       std::vector<double>& out) const {
  out.assign(c.size(), 0.0);
  if (!has_pairs()) return;
  std::vector<unsigned> contacts(zeta.size(), 0);
  for (std::size_t k = 0; k < c.size(); ++k) ++contacts[c.i[k]], ++contacts[c.j[k]];
  for (std::size_t k = 0; k < c.size(); ++k) {
    out[k] = (1.0 - reservoir_share) * 0.5 *
             (zeta[c.i[k]] / contacts[c.i[k]] + zeta[c.j[k]] / contacts[c.j[k]]);
  }
}

}  // namespace softglass::micro
