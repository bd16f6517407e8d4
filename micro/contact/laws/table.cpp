// `table`: a user-measured or computed force law, read from a text file of
// (ε, F = f/(E* R_c²)) rows and interpolated linearly in log–log coordinates,
// i.e. as a power law between consecutive points. Below the first point the first
// segment's power law continues to ε = 0 (so F → 0); above the last point the
// last segment's power law continues. Both columns must increase strictly.
//
// File format: two numbers per line separated by spaces, tabs or a comma; blank
// lines and lines starting with '#' are ignored.
#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "common/errors.h"
#include "micro/contact/contact_law.h"
#include "micro/contact/piecewise_power_law.h"

namespace softglass::micro {
namespace {

struct Point {
  double eps, force;
  int line;  // in the file, for messages
};

std::vector<Point> read_points(const std::string& text, const std::filesystem::path& file) {
  std::istringstream in(text);
  std::vector<Point> points;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    for (char& c : line)
      if (c == ',' || c == '\t' || c == '\r') c = ' ';
    std::istringstream fields(line);
    std::string first;
    if (!(fields >> first) || first.front() == '#') continue;
    Point p{0.0, 0.0, number};
    std::string rest;
    fields.clear();
    fields.str(line);
    if (!(fields >> p.eps >> p.force) || (fields >> rest)) {
      throw InputError(
          fmt::format("contact-law table '{}' line {}: expected two numbers "
                      "(deformation, reduced force), got '{}'",
                      file.string(), number, line));
    }
    if (!std::isfinite(p.eps) || !std::isfinite(p.force) || p.eps <= 0.0 || p.force <= 0.0) {
      throw InputError(
          fmt::format("contact-law table '{}' line {}: deformation and force must "
                      "be positive and finite, got {} {}",
                      file.string(), number, p.eps, p.force));
    }
    if (!points.empty() && (p.eps <= points.back().eps || p.force <= points.back().force)) {
      throw InputError(
          fmt::format("contact-law table '{}' line {}: deformation and force must "
                      "both increase strictly from one row to the next",
                      file.string(), number));
    }
    points.push_back(p);
  }
  if (points.size() < 2) {
    throw InputError(fmt::format("contact-law table '{}' needs at least two rows, has {}",
                                 file.string(), points.size()));
  }
  return points;
}

PiecewisePowerLaw interpolate(const std::vector<Point>& p, const std::filesystem::path& file) {
  std::vector<PiecewisePowerLaw::Branch> branches;
  for (std::size_t k = 0; k + 1 < p.size(); ++k) {
    const double exponent =
        std::log(p[k + 1].force / p[k].force) / std::log(p[k + 1].eps / p[k].eps);
    const double prefactor = p[k].force / std::pow(p[k].eps, exponent);
    // Rows at the ends of the double range (a force of 1e-320, or forces
    // 1e600 apart) give a power law that overflows or underflows.
    if (!(std::isfinite(exponent) && exponent > 0.0 && std::isfinite(prefactor) &&
          prefactor > 0.0)) {
      throw InputError(fmt::format(
          "contact-law table '{}' lines {} and {}: ({}, {}) and ({}, {}) give F = {} eps^{}; "
          "allowed: rows whose power law has a finite, positive prefactor and exponent",
          file.string(), p[k].line, p[k + 1].line, p[k].eps, p[k].force, p[k + 1].eps,
          p[k + 1].force, prefactor, exponent));
    }
    branches.push_back({k == 0 ? 0.0 : p[k].eps, prefactor, exponent});
  }
  return PiecewisePowerLaw(std::move(branches));
}

std::unique_ptr<ContactLaw> make(const ContactLawSpec& spec) {
  const std::string text = spec.table();
  const std::filesystem::path file =
      spec.coefficients.has("file") ? spec.coefficients.text("file") : "(stored table)";
  return make_piecewise_contact_law("table", interpolate(read_points(text, file), file));
}

}  // namespace

ContactLawEntry table_law() {
  return {"table",
          "tabulated (eps, f/(E* R_c^2)), interpolated as a power law between rows",
          {{"file", ComponentParameter::Kind::file, "",
            "Text file of rows (eps, f/(E* R_c^2)), both increasing. Relative to this parameter "
            "file."}},
          make};
}

}  // namespace softglass::micro
