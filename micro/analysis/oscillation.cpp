#include "micro/analysis/oscillation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "common/oscillation_columns.h"

namespace softglass::micro {

namespace {

// |z| of a significant drift; the change over the window below which a drift
// is negligible, relative to the target error.
constexpr double kMaxDrift = 3.0;
constexpr double kNegligibleDrift = 0.1;

// Harmonics analysed: the first, third and fifth (odd harmonics carry the
// shear stress of a symmetric material; the even ones vanish).
constexpr int kMaxHarmonic = 5;

double hypot_of(const FourierSeries& s, int n) {
  return std::hypot(s.sine[n], s.cosine[n]);
}

MeanEstimate mean_and_error(std::span<const double> x) {
  MeanEstimate e;
  e.samples = x.size();
  for (double v : x) e.mean += v / static_cast<double>(x.size());
  double ss = 0.0;
  for (double v : x) ss += (v - e.mean) * (v - e.mean);
  e.standard_error =
      x.size() > 1
          ? std::sqrt(ss / static_cast<double>(x.size() - 1) / static_cast<double>(x.size()))
          : 0.0;
  e.reliable = x.size() > 1;
  return e;
}

// Least-squares slope of x against its index, and its standard error.
struct Slope {
  double value, error;
};
Slope slope_of(std::span<const double> x) {
  const auto n = static_cast<double>(x.size());
  const double tm = 0.5 * (n - 1.0);
  double xm = 0.0;
  for (double v : x) xm += v / n;
  double stt = 0.0, stx = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double t = static_cast<double>(k) - tm;
    stt += t * t;
    stx += t * (x[k] - xm);
  }
  const double b = stx / stt;
  double rss = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double r = x[k] - xm - b * (static_cast<double>(k) - tm);
    rss += r * r;
  }
  const double error = x.size() > 2 ? std::sqrt(rss / (n - 2.0) / stt) : 0.0;
  return {b, error};
}

}  // namespace

FourierSeries fourier_series(std::span<const double> period, int max_harmonic) {
  const std::size_t n = period.size();
  if (max_harmonic < 1 || 2 * static_cast<std::size_t>(max_harmonic) >= n)
    throw std::invalid_argument(
        fmt::format("fourier_series: harmonic {} needs more than {} samples per period",
                    max_harmonic, 2 * max_harmonic));
  FourierSeries s;
  s.sine.assign(static_cast<std::size_t>(max_harmonic) + 1, 0.0);
  s.cosine.assign(static_cast<std::size_t>(max_harmonic) + 1, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(period[k]))
      throw std::invalid_argument("fourier_series: a sample is not finite");
    s.mean += period[k] / static_cast<double>(n);
    const double theta = 2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    for (int h = 1; h <= max_harmonic; ++h) {
      s.sine[h] += 2.0 / static_cast<double>(n) * period[k] * std::sin(h * theta);
      s.cosine[h] += 2.0 / static_cast<double>(n) * period[k] * std::cos(h * theta);
    }
  }
  return s;
}

const std::vector<std::string>& oscillation_observable_names() {
  static const std::vector<std::string> names(oscillation_table::responses.begin(),
                                              oscillation_table::responses.end());
  return names;
}

std::vector<double> cycle_response(const CycleSamples& c, double amplitude, double frequency) {
  if (!(amplitude > 0.0) || !(frequency > 0.0))
    throw std::invalid_argument("cycle_response: amplitude and frequency must be positive");
  const FourierSeries s = fourier_series(c.sigma, kMaxHarmonic);
  const FourierSeries e = fourier_series(c.elastic, 1), v = fourier_series(c.viscous, 1),
                      f = fourier_series(c.film, 1);
  const double first = hypot_of(s, 1);
  const auto relative = [&](int n) { return first > 0.0 ? hypot_of(s, n) / first : 0.0; };
  const auto mean = [](std::span<const double> x) {
    double m = 0.0;
    for (double value : x) m += value / static_cast<double>(x.size());
    return m;
  };
  // G′_n = σ′_n/γ0, G″_n = σ″_n/γ0; e_n = G′_n (−1)^{(n−1)/2}, v_n = G″_n/ω̃.
  return {s.sine[1] / amplitude,
          s.cosine[1] / amplitude,
          e.sine[1] / amplitude,
          e.cosine[1] / amplitude,
          v.sine[1] / amplitude,
          v.cosine[1] / amplitude,
          f.sine[1] / amplitude,
          f.cosine[1] / amplitude,
          relative(3),
          relative(5),
          s.sine[1] / amplitude,
          -s.sine[3] / amplitude,
          s.cosine[1] / amplitude / frequency,
          s.cosine[3] / amplitude / frequency,
          mean(c.n1),
          mean(c.n2),
          mean(c.pressure)};
}

const MeanEstimate& PeriodicSummary::operator[](const std::string& name) const {
  return find_estimate(observables, name);
}

double PeriodicSummary::complex_modulus() const {
  return std::hypot((*this)["storage"].mean, (*this)["loss"].mean);
}

double PeriodicSummary::worst_relative_error() const {
  const double g = complex_modulus();
  if (!(g > 0.0)) return std::numeric_limits<double>::infinity();
  return std::max((*this)["storage"].standard_error, (*this)["loss"].standard_error) / g;
}

PeriodicSummary summarise_cycles(const std::vector<std::vector<double>>& cycles,
                                 std::size_t min_periodic_cycles, double target_relative_error) {
  const std::vector<std::string>& names = oscillation_observable_names();
  if (min_periodic_cycles < 2)
    throw std::invalid_argument("summarise_cycles: at least two periodic cycles are needed");
  for (const auto& c : cycles) {
    if (c.size() != names.size())
      throw std::invalid_argument("summarise_cycles: a cycle has the wrong number of observables");
    for (double v : c)
      if (!std::isfinite(v)) throw std::invalid_argument("summarise_cycles: a value is not finite");
  }
  PeriodicSummary summary;
  summary.cycles = cycles.size();
  const std::size_t n = cycles.size();
  // The start-up cycle never counts; what is left needs its minimum.
  if (n < 1 + min_periodic_cycles) {
    summary.transient_cycles = std::min<std::size_t>(n, 1);
  } else {
    std::vector<double> modulus;
    for (std::size_t k = 1; k < n; ++k) modulus.push_back(std::hypot(cycles[k][0], cycles[k][1]));
    std::size_t cut = 0;
    if (modulus.size() >= kMserMinBatches)
      cut = std::min(mser_truncation(modulus, 1), modulus.size() - min_periodic_cycles);
    summary.transient_cycles = 1 + cut;
  }
  const std::size_t first = summary.transient_cycles;
  const std::size_t kept = n - first;
  for (std::size_t o = 0; o < names.size(); ++o) {
    std::vector<double> x;
    for (std::size_t k = first; k < n; ++k) x.push_back(cycles[k][o]);
    summary.observables.push_back({names[o], x.empty() ? MeanEstimate{} : mean_and_error(x)});
  }
  if (kept < min_periodic_cycles) return summary;

  std::vector<double> modulus;
  for (std::size_t k = first; k < n; ++k) modulus.push_back(std::hypot(cycles[k][0], cycles[k][1]));
  const Slope s = slope_of(modulus);
  const double g = summary.complex_modulus();
  summary.drift = s.error > 0.0 ? std::abs(s.value) / s.error
                                : (s.value != 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
  summary.drift_change = g > 0.0 ? std::abs(s.value) * static_cast<double>(kept - 1) / g : 0.0;
  summary.periodic = summary.drift <= kMaxDrift ||
                     summary.drift_change <= kNegligibleDrift * target_relative_error;
  return summary;
}

}  // namespace softglass::micro
