#include "micro/analysis/structure.h"

#include <fmt/format.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/errors.h"
#include "micro/analysis/pair_search.h"

namespace softglass::micro {

namespace {

constexpr double kPi = std::numbers::pi;
// Half-width of the parabola fitted around the minimum of g_{2,−2}, units of R.
constexpr double kMinimumWindow = 0.06;

// Real orthonormal spherical harmonics l = 0, 2 of the unit vector u, in the
// order of kHarmonicNames.
std::array<double, 6> harmonics(const Vec3& u) {
  const double c2 = 0.5 * std::sqrt(15.0 / kPi);
  return {0.5 / std::sqrt(kPi),
          c2 * u.x() * u.y(),
          c2 * u.y() * u.z(),
          0.25 * std::sqrt(5.0 / kPi) * (3.0 * u.z() * u.z() - 1.0),
          c2 * u.x() * u.z(),
          0.5 * c2 * (u.x() * u.x() - u.y() * u.y())};
}

struct Bins {
  std::size_t radial, map_radial, angles;
};

Bins bins_of(const StructureSettings& s) {
  return {static_cast<std::size_t>(std::ceil(s.range / s.bin_width - 1e-9)),
          static_cast<std::size_t>(std::ceil(s.range / s.map_bin_width - 1e-9)),
          static_cast<std::size_t>(s.angle_bins)};
}

// (r_hi³ − r_lo³)/3: the shell volume over 4π, ≈ r²Δr.
double shell(std::size_t b, double width) {
  const double lo = b * width, hi = (b + 1) * width;
  return (hi * hi * hi - lo * lo * lo) / 3.0;
}

}  // namespace

void StructureSettings::validate() const {
  require(bin_width > 0.0 && bin_width <= 0.5, fmt::format("bin width = {} is outside (0, 0.5]", bin_width));
  require(range > 2.0 && range <= 10.0, fmt::format("range = {} is outside (2, 10]", range));
  require(slab > 0.0 && slab <= 1.0, fmt::format("slab half-width = {} is outside (0, 1]", slab));
  require(map_bin_width > 0.0 && map_bin_width <= 0.5,
          fmt::format("map bin width = {} is outside (0, 0.5]", map_bin_width));
  require(angle_bins >= 8 && angle_bins <= 720, fmt::format("angle bins = {} is outside [8, 720]", angle_bins));
  require(batches >= 2 && batches <= 1000, fmt::format("batches = {} is outside [2, 1000]", batches));
}

StructureSample& StructureSample::operator+=(const StructureSample& other) {
  const auto add = [](std::vector<double>& a, const std::vector<double>& b) {
    if (a.empty()) a.assign(b.size(), 0.0);
    for (std::size_t k = 0; k < b.size(); ++k) a[k] += b[k];
  };
  add(harmonics, other.harmonics);
  add(forces, other.forces);
  add(map, other.map);
  virial += other.virial;
  return *this;
}

StructureSample sample_structure(const LeesEdwardsBox& box, std::span<const Vec3> x,
                                 std::span<const double> radius, const ContactLaw& law,
                                 const StructureSettings& settings) {
  settings.validate();
  const Bins n = bins_of(settings);
  const double dtheta = 2.0 * kPi / static_cast<double>(n.angles);
  StructureSample s;
  s.harmonics.assign(6 * n.radial, 0.0);
  s.forces.assign(6 * n.radial, 0.0);
  s.map.assign(n.map_radial * n.angles, 0.0);

  for_each_pair_within(box, x, radius, settings.range, [&](std::size_t i, std::size_t j, const Vec3& d) {
    const double r = d.norm();
    const Vec3 u = d / r;
    const auto y = harmonics(u);  // even in u: the two ordered pairs count the same
    const auto b = static_cast<std::size_t>(r / settings.bin_width);
    const double sum = radius[i] + radius[j];
    const double f = r < sum ? [&] {
      const double rc = radius[i] * radius[j] / sum;
      return rc * rc * law.force((sum - r) / rc);
    }()
                             : 0.0;
    if (b < n.radial) {
      for (int k = 0; k < 6; ++k) {
        s.harmonics[6 * b + k] += 2.0 * y[k];
        s.forces[6 * b + k] += 2.0 * f * r * y[k];
      }
    }
    if (f > 0.0) s.virial += (f / r) * d * d.transpose();
    if (std::abs(d.z()) < settings.slab) {
      const auto mb = static_cast<std::size_t>(r / settings.map_bin_width);
      if (mb < n.map_radial) {
        double theta = std::atan2(d.y(), d.x());
        if (theta < 0.0) theta += 2.0 * kPi;
        for (double t : {theta, std::fmod(theta + kPi, 2.0 * kPi)}) {
          const auto tb = std::min(static_cast<std::size_t>(t / dtheta), n.angles - 1);
          s.map[mb * n.angles + tb] += 1.0;
        }
      }
    }
  });
  return s;
}

namespace {

// Everything derived from a sum of `count` snapshot samples.
struct Derived {
  std::array<std::vector<double>, 6> g, fg;
  double r_m = 0, f_m = 0, sigma_m = 0;
  double sigma_virial = 0, n1_virial = 0, n2_virial = 0;
  double sigma_rebuilt = 0, n1_rebuilt = 0, n2_rebuilt = 0;
  double sigma_law = 0, n1_law = 0, n2_law = 0;
};

// The force between two particles of the mean radius at distance r:
// R_c = ½, ε = (2 − r)/R_c, f = R_c² F(ε).
double mean_pair_force(const ContactLaw& law, double r) { return r < 2.0 ? 0.25 * law.force(2.0 * (2.0 - r)) : 0.0; }

Derived derive(const StructureSample& sum, double count, std::size_t particles, double volume,
               const ContactLaw& law, const StructureSettings& settings) {
  const Bins nb = bins_of(settings);
  const double n = static_cast<double>(particles) / volume;
  const double norm = count * static_cast<double>(particles) * n;
  const double dr = settings.bin_width;
  Derived d;
  std::vector<double> weight(nb.radial);  // r v(r): the discrete ∫ r³ … dr
  for (int k = 0; k < 6; ++k) {
    d.g[k].resize(nb.radial);
    d.fg[k].resize(nb.radial);
  }
  for (std::size_t b = 0; b < nb.radial; ++b) {
    const double rb = (b + 0.5) * dr, v = shell(b, dr);
    weight[b] = rb * v;
    for (int k = 0; k < 6; ++k) {
      d.g[k][b] = sum.harmonics[6 * b + k] / (norm * v);
      d.fg[k][b] = sum.forces[6 * b + k] / (norm * rb * v);
    }
  }
  const auto integral = [&](const std::vector<double>& h) {
    double total = 0.0;
    for (std::size_t b = 0; b < nb.radial; ++b) total += weight[b] * h[b];
    return total;
  };
  const double s15 = std::sqrt(kPi / 15.0), s5 = std::sqrt(kPi / 5.0);
  d.sigma_rebuilt = -n * n * s15 * integral(d.fg[1]);
  d.n1_rebuilt = -2.0 * n * n * s15 * integral(d.fg[5]);
  d.n2_rebuilt = n * n * (s5 * integral(d.fg[3]) + s15 * integral(d.fg[5]));
  std::array<std::vector<double>, 6> with_law = d.g;
  for (std::size_t b = 0; b < nb.radial; ++b) {
    const double f = mean_pair_force(law, (b + 0.5) * dr);
    for (auto& h : with_law) h[b] *= f;
  }
  d.sigma_law = -n * n * s15 * integral(with_law[1]);
  d.n1_law = -2.0 * n * n * s15 * integral(with_law[5]);
  d.n2_law = n * n * (s5 * integral(with_law[3]) + s15 * integral(with_law[5]));

  const Eigen::Matrix3d sigma = -sum.virial / (count * volume);
  d.sigma_virial = sigma(1, 0);
  d.n1_virial = sigma(0, 0) - sigma(1, 1);
  d.n2_virial = sigma(1, 1) - sigma(2, 2);

  // r_m: minimum of g_{2,−2}, refined by the vertex of a least-squares parabola
  // over ±kMinimumWindow around the lowest bin (a 3-point parabola follows the
  // noise of single bins when the minimum is broad).
  const std::vector<double>& g = d.g[1];
  const auto lowest = static_cast<std::size_t>(std::min_element(g.begin(), g.end()) - g.begin());
  d.r_m = (lowest + 0.5) * dr;
  const auto half = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(kMinimumWindow / dr)));
  if (lowest >= half && lowest + half < g.size()) {
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    for (std::size_t b = lowest - half; b <= lowest + half; ++b) {
      const double t = (static_cast<double>(b) - static_cast<double>(lowest)) * dr;  // centred
      const Eigen::Vector3d basis(1.0, t, t * t);
      normal += basis * basis.transpose();
      rhs += basis * g[b];
    }
    const Eigen::Vector3d c = normal.ldlt().solve(rhs);
    if (c(2) > 0.0) d.r_m += std::clamp(-c(1) / (2.0 * c(2)), -kMinimumWindow, kMinimumWindow);
  }
  d.f_m = mean_pair_force(law, d.r_m);
  std::size_t lo = lowest, hi = lowest;
  while (lo > 0 && g[lo - 1] < 0.0) --lo;
  while (hi + 1 < g.size() && g[hi + 1] < 0.0) ++hi;
  double negative = 0.0;
  for (std::size_t b = lo; b <= hi; ++b) negative += weight[b] * std::min(g[b], 0.0);
  d.sigma_m = -n * n * s15 * negative;
  return d;
}

// Jackknife over batches: value from all, error from the leave-one-out spread.
template <class Get>
Estimate jackknife(const Derived& all, const std::vector<Derived>& left_out, Get get) {
  const double b = static_cast<double>(left_out.size());
  double mean = 0.0;
  for (const auto& d : left_out) mean += get(d) / b;
  double spread = 0.0;
  for (const auto& d : left_out) spread += (get(d) - mean) * (get(d) - mean);
  return {get(all), std::sqrt((b - 1.0) / b * spread)};
}

}  // namespace

StructureResult average_structure(std::span<const StructureSample> samples, std::size_t particles,
                                  double volume, const ContactLaw& law,
                                  const StructureSettings& settings) {
  settings.validate();
  const std::size_t k = samples.size();
  require(k >= 2, fmt::format("structure analysis needs at least 2 snapshots, got {}", k));
  const std::size_t batches = std::min<std::size_t>(settings.batches, k);

  // Batch sums of consecutive snapshots, and their total.
  std::vector<StructureSample> batch(batches);
  std::vector<double> count(batches, 0.0);
  for (std::size_t s = 0; s < k; ++s) {
    const std::size_t b = s * batches / k;
    batch[b] += samples[s];
    count[b] += 1.0;
  }
  StructureSample total;
  for (const auto& b : batch) total += b;
  const Derived all = derive(total, static_cast<double>(k), particles, volume, law, settings);

  std::vector<Derived> left_out, per_batch;
  for (std::size_t b = 0; b < batches; ++b) {
    StructureSample rest;
    for (std::size_t c = 0; c < batches; ++c)
      if (c != b) rest += batch[c];
    left_out.push_back(derive(rest, static_cast<double>(k) - count[b], particles, volume, law, settings));
    per_batch.push_back(derive(batch[b], count[b], particles, volume, law, settings));
  }

  StructureResult r;
  r.settings = settings;
  r.snapshots = k;
  r.number_density = static_cast<double>(particles) / volume;
  const Bins nb = bins_of(settings);
  for (std::size_t b = 0; b < nb.radial; ++b) r.r.push_back((b + 0.5) * settings.bin_width);
  const double nbatch = static_cast<double>(batches);
  for (int h = 0; h < 6; ++h) {
    r.g[h] = all.g[h];
    r.fg[h] = all.fg[h];
    r.g_error[h].assign(nb.radial, 0.0);
    r.fg_error[h].assign(nb.radial, 0.0);
    // Per-bin error: spread of the batch means (the batch sizes differ by at
    // most one snapshot).
    for (std::size_t b = 0; b < nb.radial; ++b) {
      double gm = 0, fm = 0, g2 = 0, f2 = 0;
      for (const auto& d : per_batch) {
        gm += d.g[h][b] / nbatch, fm += d.fg[h][b] / nbatch;
        g2 += d.g[h][b] * d.g[h][b] / nbatch, f2 += d.fg[h][b] * d.fg[h][b] / nbatch;
      }
      r.g_error[h][b] = std::sqrt(std::max(0.0, g2 - gm * gm) / (nbatch - 1.0));
      r.fg_error[h][b] = std::sqrt(std::max(0.0, f2 - fm * fm) / (nbatch - 1.0));
    }
  }

  // g(r, θ): ordered pairs per slab volume 2w r Δr Δθ, per particle and density.
  const double dtheta = 2.0 * kPi / static_cast<double>(nb.angles);
  const double norm = static_cast<double>(k) * static_cast<double>(particles) * r.number_density;
  for (std::size_t b = 0; b < nb.map_radial; ++b) r.map_r.push_back((b + 0.5) * settings.map_bin_width);
  for (std::size_t t = 0; t < nb.angles; ++t) r.map_theta.push_back((t + 0.5) * dtheta);
  r.map.resize(total.map.size());
  for (std::size_t b = 0; b < nb.map_radial; ++b) {
    const double element = 2.0 * settings.slab * r.map_r[b] * settings.map_bin_width * dtheta;
    for (std::size_t t = 0; t < nb.angles; ++t)
      r.map[b * nb.angles + t] = total.map[b * nb.angles + t] / (norm * element);
  }

  r.r_m = jackknife(all, left_out, [](const Derived& d) { return d.r_m; });
  r.f_m = jackknife(all, left_out, [](const Derived& d) { return d.f_m; });
  r.sigma_m = jackknife(all, left_out, [](const Derived& d) { return d.sigma_m; });
  r.fm_sigma_m = jackknife(all, left_out, [](const Derived& d) { return d.f_m * d.sigma_m; });
  r.sigma_virial = jackknife(all, left_out, [](const Derived& d) { return d.sigma_virial; });
  r.n1_virial = jackknife(all, left_out, [](const Derived& d) { return d.n1_virial; });
  r.n2_virial = jackknife(all, left_out, [](const Derived& d) { return d.n2_virial; });
  r.sigma_rebuilt = jackknife(all, left_out, [](const Derived& d) { return d.sigma_rebuilt; });
  r.n1_rebuilt = jackknife(all, left_out, [](const Derived& d) { return d.n1_rebuilt; });
  r.n2_rebuilt = jackknife(all, left_out, [](const Derived& d) { return d.n2_rebuilt; });
  r.sigma_law = jackknife(all, left_out, [](const Derived& d) { return d.sigma_law; });
  r.n1_law = jackknife(all, left_out, [](const Derived& d) { return d.n1_law; });
  r.n2_law = jackknife(all, left_out, [](const Derived& d) { return d.n2_law; });
  return r;
}

std::vector<NamedEstimate> named_estimates(const StructureResult& s) {
  return {
      {"r_m", s.r_m, "R", "radius of the minimum of g_{2,-2}"},
      {"f_m", s.f_m, "E* R^2", "elastic force at r_m between two particles of the mean radius"},
      {"sigma_m", s.sigma_m, "1/R^2", "Sigma_m = -n^2 sqrt(pi/15) int r^3 g_{2,-2} dr where g_{2,-2} < 0"},
      {"fm_sigma_m", s.fm_sigma_m, "E*", "f_m Sigma_m, the paper's estimate of sigma^e"},
      {"sigma_virial", s.sigma_virial, "E*", "elastic shear stress, virial"},
      {"sigma_rebuilt", s.sigma_rebuilt, "E*", "elastic shear stress from the force-weighted moments"},
      {"N1_virial", s.n1_virial, "E*", "elastic N1, virial"},
      {"N1_rebuilt", s.n1_rebuilt, "E*", "elastic N1 from the force-weighted moments"},
      {"N2_virial", s.n2_virial, "E*", "elastic N2, virial"},
      {"N2_rebuilt", s.n2_rebuilt, "E*", "elastic N2 from the force-weighted moments"},
      {"sigma_law", s.sigma_law, "E*", "elastic shear stress from g_lm with the mean-radius force f(r)"},
      {"N1_law", s.n1_law, "E*", "elastic N1 from g_lm with the mean-radius force f(r)"},
      {"N2_law", s.n2_law, "E*", "elastic N2 from g_lm with the mean-radius force f(r)"},
  };
}

}  // namespace softglass::micro
