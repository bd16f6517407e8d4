// `paired`: a header that labels pairs of columns ("0.68,,0.70,,..."), each
// pair one curve (shear rate, stress), no units in the header (they come from
// the command line); rows may be shorter for some pairs (both cells empty).
#include <fmt/format.h>

#include "common/errors.h"
#include "common/measured/columns.h"
#include "common/measured/layout.h"

namespace softglass::measured {
namespace {

bool recognises(const std::vector<std::string>& header) {
  if (header.size() < 2 || header.size() % 2 != 0) return false;
  for (std::size_t c = 0; c < header.size(); ++c)
    if (header[c].empty() != (c % 2 == 1)) return false;
  return true;
}

std::vector<RheometerCurve> read_paired(const CsvTable& csv, const MeasuredReading& fallback) {
  if (fallback.rate.empty() || fallback.stress.empty()) {
    throw InputError(
        fmt::format("{}: the header labels pairs of columns (shear rate, stress) but "
                    "gives no units; pass --rate-unit and --stress-unit",
                    csv.source()));
  }
  const double rate = rate_factor(fallback.rate, "--rate-unit");
  const double stress = stress_factor(fallback.stress, "--stress-unit");
  std::vector<RheometerCurve> curves;
  for (std::size_t c = 0; c < csv.columns(); c += 2) {
    RheometerCurve& curve = curves.emplace_back();
    curve.label = csv.header()[c];
    std::vector<double>& x = curve.values[Measured::shear_rate];
    std::vector<double>& y = curve.values[Measured::stress];
    for (std::size_t r = 0; r < csv.rows(); ++r) {
      if (csv.text(r, c).empty() && csv.text(r, c + 1).empty()) continue;  // a shorter curve
      x.push_back(value(csv, r, {c, rate}));
      y.push_back(value(csv, r, {c + 1, stress}));
    }
  }
  finish(curves, csv.source());
  return curves;
}

}  // namespace

LayoutEntry paired_layout() {
  return {"paired", "pairs of columns (shear rate, stress) under one label each", recognises,
          read_paired};
}

}  // namespace softglass::measured
