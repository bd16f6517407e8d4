// The law as a .prm fragment (law/law.h). Written as text rather than through
// ParameterHandler so that the provenance and the explanations sit next to the
// numbers; app/law_file.cpp reads it back with ParameterHandler.
#include <fmt/format.h>

#include <cmath>

#include "bridge/law/law.h"

namespace softglass::bridge {

namespace {

template <class T, class F>
std::string list(const std::vector<T>& values, F&& format) {
  std::string text;
  for (const T& v : values) text += (text.empty() ? "" : ", ") + format(v);
  return text;
}
std::string values(const std::vector<Estimate>& e) {
  return list(e, [](const Estimate& x) { return fmt::format("{:.10g}", x.value); });
}
// An error that cannot be estimated (NaN) is written 0: the reader knows it
// from the packings (law_file.cpp), and a parameter file holds no NaN.
std::string errors(const std::vector<Estimate>& e) {
  return list(e, [](const Estimate& x) {
    return fmt::format("{:.4g}", std::isnan(x.error) ? 0.0 : x.error);
  });
}

// "  set name = value", names aligned.
void set(std::string& out, const std::string& indent, const std::string& name,
         const std::string& value) {
  out += fmt::format("{}set {:<19} = {}\n", indent, name, value);
}

void estimates(std::string& out, const std::string& indent, const std::string& name,
               const std::vector<Estimate>& e) {
  set(out, indent, name, values(e));
  set(out, indent, name + " error", errors(e));
}

// Rows of a [φ][amplitude] table, φ after φ.
std::vector<Estimate> flattened(const std::vector<std::vector<Estimate>>& rows) {
  std::vector<Estimate> flat;
  for (const auto& row : rows) flat.insert(flat.end(), row.begin(), row.end());
  return flat;
}

void amplitude_sweep_text(std::string& out, const AmplitudeSweepLaw& a) {
  const auto numbers = [](const std::vector<double>& v) {
    return list(v, [](double x) { return fmt::format("{:.10g}", x); });
  };
  out += fmt::format(
      "  subsection amplitude sweep\n"
      "    # micro oscillate at omega~ = omega eta_s / E* = {:.6g}: G' and G'' of sigma in E*,\n"
      "    # one row of amplitudes per volume fraction (its own list of volume fractions).\n"
      "    # plateau: at the smallest amplitude; softening strain: G' = 0.9 of its plateau;\n"
      "    # crossover strain: G' = G'' (0: not reached within the sweep).\n",
      a.frequency);
  set(out, "    ", "frequency", fmt::format("{:.10g}", a.frequency));
  set(out, "    ", "volume fractions", numbers(a.phi));
  set(out, "    ", "amplitudes", numbers(a.amplitudes));
  if (!a.packings.empty()) {
    out += "    # the fewest packings of each volume fraction's rows; with one, its errors\n"
           "    # cannot be estimated (written 0, read as n/a)\n";
    set(out, "    ", "packings", numbers(a.packings));
  }
  estimates(out, "    ", "storage", flattened(a.storage));
  estimates(out, "    ", "loss", flattened(a.loss));
  estimates(out, "    ", "plateau storage", a.plateau_storage);
  estimates(out, "    ", "plateau loss", a.plateau_loss);
  estimates(out, "    ", "softening strain", a.softening_strain);
  estimates(out, "    ", "crossover strain", a.crossover_strain);
  out += "  end\n";
}

}  // namespace

std::string law_text(const Law& law) {
  std::string out;
  for (const std::string& line : law.provenance) out += "# " + line + "\n";
  out +=
      "# Reduced units: stresses in E*, forces in E* R^2, rates gamma~ = gamma_dot eta_s / E*.\n"
      "# Every 'error' is one standard deviation; lists run over the volume fractions.\n"
      "subsection law\n";
  set(out, "  ", "volume fractions", list(law.phi, [](double p) { return fmt::format("{}", p); }));
  set(out, "  ", "gamma tilde range",
      fmt::format("{:.6g}, {:.6g}", law.gamma_tilde_min, law.gamma_tilde_max));
  if (!law.packings.empty()) {
    out += "  # the fewest packings any state point averages, per volume fraction; with one,\n"
           "  # the error of G0 cannot be estimated (written 0, read as n/a)\n";
    set(out, "  ", "packings", list(law.packings, [](double p) { return fmt::format("{}", p); }));
  }
  out += "  # G0/E*: the linear shear modulus of the packings\n";
  estimates(out, "  ", "shear modulus", law.modulus);
  out += "  # gamma_y = sigma_y / G0, with the Herschel-Bulkley sigma_y\n";
  estimates(out, "  ", "yield strain", law.yield_strain);

  out +=
      "  subsection universal\n"
      "    # sigma/sigma_y = 1 + k (gamma~/gamma_y^2)^(1/2), one k for every volume fraction;\n"
      "    # N1/sigma_y = N1_y/sigma_y + k N1 (...)^(1/2) (the paper's k'), and -N2/sigma_y\n"
      "    # = -N2_y/sigma_y + k N2 (...)^(1/2) (k''), with one plateau N_y per volume fraction.\n"
      "    # The paper (Seth et al. 2011): k = 80 +- 3, k' = 20 +- 2, k'' = 26 +- 2.\n";
  const std::pair<Quantity, const char*> constants[] = {
      {Quantity::sigma, "k"}, {Quantity::N1, "k N1"}, {Quantity::N2, "k N2"}};
  for (const auto& [q, name] : constants) {
    if (const auto& k = law.k[index(q)]) {
      set(out, "    ", name, fmt::format("{:.10g}", k->value));
      set(out, "    ", std::string(name) + " error", fmt::format("{:.4g}", k->error));
    }
  }
  out +=
      "    # mean over the volume fractions of the sigma exponents m (the paper: 0.50 +- 0.02)\n";
  set(out, "    ", "mean exponent", fmt::format("{:.10g}", law.mean_exponent.value));
  set(out, "    ", "mean exponent error", fmt::format("{:.4g}", law.mean_exponent.error));
  out += "  end\n";

  for (Quantity q : kAllQuantities) {
    const auto& hb = law.hb[index(q)];
    const bool force = q == Quantity::force && law.force;
    if (!hb && !force) continue;
    out += fmt::format("  subsection {}\n", law_subsection(q));
    if (hb) {
      out += fmt::format("    # {}/{} = yield + consistency gamma~^exponent, per volume fraction\n",
                         column_name(q), reduced_units(q));
      estimates(out, "    ", "yield", hb->yield);
      estimates(out, "    ", "consistency", hb->consistency);
      estimates(out, "    ", "exponent", hb->exponent);
      out += "    # correlation of ln|consistency| and exponent over the bootstrap replicates\n";
      set(out, "    ", "correlation",
          list(hb->correlation, [](double r) { return fmt::format("{:.4f}", r); }));
    }
    if (force) {
      out += "    # the paper's force law f_m = f_y + k_f gamma~^(1/2), exponent fixed at 1/2\n";
      estimates(out, "    ", "f_y", law.force->yield);
      estimates(out, "    ", "k_f", law.force->slope);
    }
    out += "  end\n";
  }
  if (law.amplitude_sweep) amplitude_sweep_text(out, *law.amplitude_sweep);
  out += "end\n";
  return out;
}

}  // namespace softglass::bridge
