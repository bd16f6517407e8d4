#include <cmath>

#include "common/csv_writer.h"
#include "bridge/output/tables.h"

namespace softglass::bridge {

std::string rescaled_points_table(const std::vector<MeasuredCurve>& curves,
                                  const std::vector<RescaledCurve>& rescaled,
                                  const std::vector<std::string>& comments) {
  bool normal = false;
  for (const RescaledCurve& r : rescaled) normal = normal || r.N1_ratio.has_value();
  std::vector<std::string> header = {"curve",       "shear_rate [1/s]",  "stress [Pa]",
                                     "used [1]",    "collapse_rate [1]", "stress_ratio [1]",
                                     "residual [1]"};
  if (normal) {
    for (const char* name : {"N1 [Pa]", "N1_ratio [1]", "N1_residual [1]"}) header.push_back(name);
  }
  CsvWriter w("the rescaled points table", header, comments);
  for (std::size_t j = 0; j < curves.size(); ++j) {
    const MeasuredCurve& c = curves[j];
    const RescaledCurve& r = rescaled[j];
    for (std::size_t i = 0; i < c.shear_rate.size(); ++i) {
      w << c.label << c.shear_rate[i] << c.stress[i] << (r.used[i] ? 1.0 : 0.0)
        << r.collapse_rate[i] << r.stress_ratio[i] << r.residual[i];
      if (normal) {
        // Curves without an N1 law get zeros: N1/τ_y and its residual are undefined there.
        const bool own = r.N1_ratio.has_value();
        w << (own ? (*c.N1)[i] : 0.0) << (own ? (*r.N1_ratio)[i] : 0.0)
          << (own ? (*r.N1_residual)[i] : 0.0);
      }
      w.end_row();
    }
  }
  return w.text();
}

std::string rescaled_curves_table(const std::vector<RescaledCurve>& rescaled,
                                  const RescaleSettings& settings,
                                  const std::vector<std::string>& comments) {
  CsvWriter w("the rescaled curves table", {"curve", "tau_y [Pa]", "tau_y_se [Pa]", "E* [Pa]", "E*_se [Pa]", "E*_shared [1]",
               "gamma_y [1]", "gamma_y_se [1]", "k [1]", "k_N1 [1]", "N1_y [Pa]", "N1_y_se [Pa]",
               "rms_residual [1]", "hb_tau_y [Pa]", "hb_tau_y_se [Pa]", "hb_K [Pa s^n]",
               "hb_K_se [Pa s^n]", "hb_n [1]", "hb_n_se [1]"}, comments);
  for (const RescaledCurve& r : rescaled) {
    const HerschelBulkleyFit& hb = r.herschel_bulkley;
    const Estimate n1 = r.N1_yield.value_or(Estimate{0.0, 0.0});
    w << r.label << r.yield_stress.value << r.yield_stress.error << r.modulus.value
      << r.modulus.error << (r.modulus_shared ? 1.0 : 0.0) << r.yield_strain.value
      << r.yield_strain.error << settings.k << settings.k_N1 << n1.value << n1.error
      << r.rms_residual << hb.parameters.yield << std::sqrt(hb.covariance(0, 0))
      << hb.parameters.consistency << std::sqrt(hb.covariance(1, 1)) << hb.parameters.exponent
      << std::sqrt(hb.covariance(2, 2));
    w.end_row();
  }
  return w.text();
}

}  // namespace softglass::bridge
