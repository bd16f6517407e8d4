// Structure analysis (analysis/structure.h): the stress–structure identities of
// docs/structure.md, isotropy, and exact values on a constructed configuration.
#include <gtest/gtest.h>

#include <numbers>

#include "micro/analysis/pair_search.h"
#include "micro/analysis/structure.h"
#include "micro_test_support.h"

namespace softglass::micro {
namespace {

constexpr double kPi = std::numbers::pi;

// A relaxed packing sheared affinely by 0.05 without relaxation: anisotropic
// contact forces, so that σ_xy, N1 and N2 are all far from zero.
struct Sheared {
  LeesEdwardsBox box;
  std::vector<Vec3> x;
  std::vector<double> radius;
};
Sheared affinely_sheared_packing(double polydispersity, std::uint64_t seed) {
  PackingSpec spec;
  spec.particles = 500;
  spec.volume_fraction = 0.75;
  spec.skin = 0.3;
  spec.seed = seed;
  spec.radii.polydispersity = polydispersity;
  const Packing p = make_packing(spec, testing::named_law("hertz"));
  Sheared s{p.box, p.particles.position, p.particles.radius};
  const double strain = 0.05;
  s.box.set_strain(strain);
  for (Vec3& x : s.x) x.x() += strain * x.y();
  return s;
}

StructureResult one_snapshot(const Sheared& s, const StructureSettings& settings) {
  const auto law = testing::named_law("hertz");
  const StructureSample sample = sample_structure(s.box, s.x, s.radius, *law, settings);
  // Two copies make the two batches the averaging needs; the mean is unchanged.
  const std::vector<StructureSample> samples = {sample, sample};
  return average_structure(samples, s.x.size(), s.box.volume(), *law, settings);
}

TEST(Structure, ForceWeightedMomentsRebuildTheVirialToRoundOff) {
  // Polydisperse (δ = 0.1): the force is not a function of r, yet the
  // force-weighted moments carry each pair's force and distance, so the
  // formulas of docs/structure.md give the virial exactly — up to the order in
  // which the sums are taken, a few ulp of the largest terms.
  const Sheared s = affinely_sheared_packing(0.1, 3);
  const StructureResult r = one_snapshot(s, {});
  ASSERT_GT(std::abs(r.sigma_virial.value), 1e-4);
  EXPECT_NEAR(r.sigma_rebuilt.value, r.sigma_virial.value, 1e-12 * std::abs(r.sigma_virial.value));
  EXPECT_NEAR(r.n1_rebuilt.value, r.n1_virial.value, 1e-12 * std::abs(r.n1_virial.value));
  EXPECT_NEAR(r.n2_rebuilt.value, r.n2_virial.value, 1e-12 * std::abs(r.n2_virial.value));
}

TEST(Structure, MonodisperseGlmIntegralsGiveTheVirialToWithinTheBinning) {
  // Equal radii: the force is f(r) alone, and the histogram turns
  // −n²√(π/15)∫ r³ f g_{2,−2} dr into −(1/V)√(π/15) Σ_ordered pairs r_b f(r_b) Y_{2,−2}(r̂),
  // with r_b the centre of the pair's bin, where the virial has r f(r). The
  // binning error is therefore exactly
  //     −(1/V)√(π/15) Σ_ordered [r_b f(r_b) − r f(r)] Y_{2,−2}(r̂),
  // bounded by (1/V)√(π/15) Σ |r_b f(r_b) − r f(r)| |Y_{2,−2}| (likewise for N1 with
  // 2√(π/15)Y_{2,2}, N2 with √(π/5)Y_{2,0} + √(π/15)Y_{2,2}). The test computes
  // that bound for this configuration and requires the error to be within it.
  // Each pair's term is first order in Δr, so the bound must shrink about 4×
  // from Δr = 0.008 to 0.002, and be small there (below 3 % of σ; the actual
  // error, whose terms have random signs, is far smaller).
  const Sheared s = affinely_sheared_packing(0.0, 5);
  const auto law = testing::named_law("hertz");
  const double s15 = std::sqrt(kPi / 15.0), s5 = std::sqrt(kPi / 5.0);
  std::vector<double> bounds;
  for (double width : {0.008, 0.002}) {
    StructureSettings settings;
    settings.bin_width = width;
    const StructureResult r = one_snapshot(s, settings);
    double bound_sigma = 0.0, bound_n1 = 0.0, bound_n2 = 0.0;
    for_each_pair_within(s.box, s.x, s.radius, 2.0, [&](std::size_t, std::size_t, const Vec3& d) {
      const double dist = d.norm();
      const double centre = (std::floor(dist / width) + 0.5) * width;
      const auto f = [&](double rr) { return rr < 2.0 ? 0.25 * law->force(2.0 * (2.0 - rr)) : 0.0; };
      const double miss = 2.0 * std::abs(centre * f(centre) - dist * f(dist)) / s.box.volume();  // 2 ordered
      const Vec3 u = d / dist;
      const double y2m2 = 0.5 * std::sqrt(15.0 / kPi) * u.x() * u.y();
      const double y20 = 0.25 * std::sqrt(5.0 / kPi) * (3.0 * u.z() * u.z() - 1.0);
      const double y22 = 0.25 * std::sqrt(15.0 / kPi) * (u.x() * u.x() - u.y() * u.y());
      bound_sigma += miss * s15 * std::abs(y2m2);
      bound_n1 += miss * 2.0 * s15 * std::abs(y22);
      bound_n2 += miss * std::abs(s5 * y20 + s15 * y22);
    });
    EXPECT_LE(std::abs(r.sigma_law.value - r.sigma_virial.value), bound_sigma * (1 + 1e-9)) << "Δr " << width;
    EXPECT_LE(std::abs(r.n1_law.value - r.n1_virial.value), bound_n1 * (1 + 1e-9)) << "Δr " << width;
    EXPECT_LE(std::abs(r.n2_law.value - r.n2_virial.value), bound_n2 * (1 + 1e-9)) << "Δr " << width;
    bounds.push_back(bound_sigma);
    if (width == 0.002) {
      EXPECT_LT(bound_sigma, 0.03 * std::abs(r.sigma_virial.value));
    }
  }
  EXPECT_GT(bounds[0] / bounds[1], 3.0);
}

TEST(Structure, UnshearedPackingsAreIsotropic) {
  // At rest no direction is preferred: every g_2m integrated over the first
  // shell (r < 2.4) has zero mean over packings. Eight independent packings
  // give the mean and its standard error; |mean| < 3 SE for all five m
  // (a false alarm has probability ~1 % in all).
  const auto law = testing::named_law("hertz");
  StructureSettings settings;
  std::array<std::vector<double>, 5> shell;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    PackingSpec spec;
    spec.particles = 400;
    spec.volume_fraction = 0.8;
    spec.skin = 0.3;
    spec.seed = seed;
    const Packing p = make_packing(spec, law);
    const StructureSample sample =
        sample_structure(p.box, p.particles.position, p.particles.radius, *law, settings);
    const std::vector<StructureSample> two = {sample, sample};
    const StructureResult r = average_structure(two, spec.particles, p.box.volume(), *law, settings);
    for (int m = 0; m < 5; ++m) {
      double sum = 0.0;
      for (std::size_t b = 0; b < r.r.size() && r.r[b] < 2.4; ++b) sum += r.g[m + 1][b] * settings.bin_width;
      shell[m].push_back(sum);
    }
    // and the isotropic part is not zero: it counts the neighbours
    double g00 = 0.0;
    for (std::size_t b = 0; b < r.r.size() && r.r[b] < 2.4; ++b) g00 += r.g[0][b] * settings.bin_width;
    EXPECT_GT(g00, 1.0);
  }
  for (int m = 0; m < 5; ++m) {
    double mean = 0.0, var = 0.0;
    for (double v : shell[m]) mean += v / 8.0;
    for (double v : shell[m]) var += (v - mean) * (v - mean) / 7.0;
    EXPECT_LT(std::abs(mean), 3.0 * std::sqrt(var / 8.0)) << kHarmonicNames[m + 1];
  }
}

TEST(Structure, DimersAlongTheCompressionalAxisGiveTheExactG2m2) {
  // M dimers of unit spheres at distance d along (1, −1, 0)/√2, far apart in a
  // large cell: the only pairs in range. With N = 2M, n = N/V and the 2M
  // ordered pairs in the bin of d,
  //     g_{2,−2} = 2M Y_{2,−2}/(N n v),  Y_{2,−2} = ½√(15/π) x̂ŷ = −¼√(15/π) < 0,
  //     g_{2,0} = 2M · ¼√(5/π)(3·0 − 1)/(N n v),  g_{2,2} = 0 (x̂² = ŷ²).
  const double side = 40.0, d = 1.905;  // inside a bin, not on its edge
  const Vec3 axis = Vec3(1.0, -1.0, 0.0).normalized();
  std::vector<Vec3> x;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int c = 0; c < 2; ++c) {
        const Vec3 centre(5.0 + 9.0 * a, 5.0 + 9.0 * b, 5.0 + 18.0 * c);
        x.push_back(centre);
        x.push_back(centre + d * axis);
      }
  const std::vector<double> radius(x.size(), 1.0);
  const auto law = testing::named_law("hertz");
  StructureSettings settings;
  const LeesEdwardsBox box(side);
  const StructureSample sample = sample_structure(box, x, radius, *law, settings);
  const std::vector<StructureSample> two = {sample, sample};
  const StructureResult r = average_structure(two, x.size(), box.volume(), *law, settings);

  const auto bin = static_cast<std::size_t>(d / settings.bin_width);
  const double lo = bin * settings.bin_width, hi = lo + settings.bin_width;
  const double shell = (hi * hi * hi - lo * lo * lo) / 3.0;
  const double n = static_cast<double>(x.size()) / box.volume();
  const double pairs = static_cast<double>(x.size());  // 2M ordered pairs
  const double expected = pairs * (-0.25 * std::sqrt(15.0 / kPi)) / (static_cast<double>(x.size()) * n * shell);
  EXPECT_LT(r.g[1][bin], 0.0);
  EXPECT_NEAR(r.g[1][bin], expected, 1e-12 * std::abs(expected));
  const double expected_20 = pairs * (-0.25 * std::sqrt(5.0 / kPi)) / (static_cast<double>(x.size()) * n * shell);
  EXPECT_NEAR(r.g[3][bin], expected_20, 1e-12 * std::abs(expected_20));
  EXPECT_NEAR(r.g[5][bin], 0.0, 1e-12 * std::abs(expected));
  EXPECT_NEAR(r.r_m.value, d, settings.bin_width);  // the minimum is that bin
  // and nothing elsewhere
  for (std::size_t b = 0; b < r.r.size(); ++b) {
    if (b != bin) {
      EXPECT_EQ(r.g[0][b], 0.0) << "bin " << b;
    }
  }
}

}  // namespace
}  // namespace softglass::micro
