// Oscillatory shear (micro/protocol/oscillatory_run.h) against what can be
// computed by hand.
//
// A face-centred cubic lattice of equal spheres deforms affinely under any
// homogeneous shear: every particle is a centre of inversion of the lattice,
// so the elastic forces of its pairs ±b cancel, and so do their EHD drags
// (their affine sliding velocities are opposite). With v = 0 the stress at
// strain γ and rate c is a sum over the six nearest-neighbour directions of
// closed-form pair forces (Hertz, and the √u∥ drag of the tangential affine
// sliding), evaluated here independently of the engine; the run must
// reproduce it sample by sample, and its moduli must be that signal's
// harmonics. A disordered packing at vanishing amplitude and frequency must
// give its static linear modulus, and a run resumed from a checkpoint the
// uninterrupted run's numbers bit for bit.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <stdexcept>

#include "common/errors.h"
#include "micro/analysis/shear_modulus.h"
#include "micro/io/checkpoint_file.h"
#include "micro/protocol/oscillatory_run.h"
#include "micro_test_support.h"

namespace softglass::micro {
namespace {

constexpr double kPi = std::numbers::pi;

// FCC lattice of unit spheres: `cells`³ cubic cells of edge a, four per cell.
Particles fcc(int cells, double a) {
  const Vec3 basis[4] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  std::vector<Vec3> x;
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)
      for (int k = 0; k < cells; ++k)
        for (const Vec3& b : basis) x.push_back(a * (Vec3(i, j, k) + b + Vec3::Constant(0.25)));
  return Particles(x, std::vector<double>(x.size(), 1.0));
}

// The stress of the affinely sheared lattice by hand: σ_yx = −(N/V) Σ_b d_y f_x
// over the six nearest-neighbour directions b (one of each ±b pair), d = b +
// γ b_y e_x. Elastic: Hertz, f = (4/3) R_c² ε^{3/2} d/r with R_c = ½, ε = (2 −
// r)/R_c. Films: f = −a √|w| ŵ, w = (I − n nᵀ)(c d_y e_x), a² = ¾ γ̃ R_c |f^e| √ε.
struct LatticeStress {
  double elastic, film;
};
LatticeStress lattice_stress(double a, double gamma, double rate, double gamma_tilde) {
  const double h = 0.5 * a;
  const Vec3 directions[6] = {{h, h, 0}, {h, -h, 0}, {h, 0, h}, {h, 0, -h}, {0, h, h}, {0, h, -h}};
  const double rc = 0.5, density = 4.0 / (a * a * a);
  LatticeStress s{0.0, 0.0};
  for (const Vec3& b : directions) {
    const Vec3 d(b.x() + gamma * b.y(), b.y(), b.z());
    const double r = d.norm(), eps = (2.0 - r) / rc;
    const double force = 4.0 / 3.0 * rc * rc * std::pow(eps, 1.5);
    const Vec3 n = d / r;
    s.elastic -= density * d.y() * force * n.x();
    const Vec3 affine(rate * d.y(), 0, 0);
    const Vec3 w = affine - n * n.dot(affine);
    if (w.norm() > 0) {
      const double coefficient = std::sqrt(0.75 * gamma_tilde * rc * force * std::sqrt(eps));
      s.film -= density * d.y() * (-coefficient * std::sqrt(w.norm()) * w.x() / w.norm());
    }
  }
  return s;
}

class LatticeOscillation : public ::testing::TestWithParam<double> {};

// Two frequencies: the peak rate 2e-6 runs the implicit scheme, 2e-10 too but
// with the drag far below the forces; 0.01 at the fastest rate runs `euler`.
TEST_P(LatticeOscillation, ReproducesTheAffineStressSampleBySample) {
  omp_set_num_threads(1);
  const double a = 2.75, gamma0 = 2e-3, omega = GetParam();
  const int cells = 3;
  OscillationProtocol protocol;
  protocol.amplitude = gamma0;
  protocol.frequency = omega;
  protocol.samples_per_cycle = 32;
  protocol.min_cycles = 4;
  protocol.max_cycles = 6;
  ShearModel model;
  model.gamma_tilde = protocol.peak_gamma_tilde();
  const Particles lattice = fcc(cells, a);
  LeesEdwardsBox box(cells * a);
  OverdampedShear flow(ContactSystem(lattice, box, testing::named_law("hertz"), 0.6), model,
                       ShearDrive::oscillatory(gamma0));
  const IntegratorSpec scheme = oscillation_integrator({}, protocol, model.drag.stokes.reference);
  const auto integrator = make_integrator(scheme);
  const OscillationResult r = run_oscillation(flow, *integrator, protocol);

  ASSERT_TRUE(r.converged) << r.stop_reason;
  EXPECT_EQ(r.summary.transient_cycles, 1u) << "an affine lattice is periodic from its 2nd cycle";
  const std::vector<double> elastic = r.series.component("sigma_elastic"),
                            film = r.series.component("sigma_film");
  const double scale = std::abs(lattice_stress(a, gamma0, 0, 0).elastic);
  const double film_scale = std::abs(lattice_stress(a, 0, 1, model.gamma_tilde).film);
  std::vector<double> hand_elastic, hand_film;
  for (std::size_t k = 0; k < r.series.size(); ++k) {
    const double phase = 2 * kPi * double(k) / protocol.samples_per_cycle;
    EXPECT_NEAR(r.series.strain[k], gamma0 * std::sin(phase), 1e-12) << k;
    const LatticeStress s =
        lattice_stress(a, gamma0 * std::sin(phase), std::cos(phase), model.gamma_tilde);
    ASSERT_NEAR(elastic[k], s.elastic, 1e-9 * scale) << "sample " << k;
    ASSERT_NEAR(film[k], s.film, 1e-6 * film_scale) << "sample " << k;
    if (k < protocol.samples_per_cycle) {
      hand_elastic.push_back(s.elastic);
      hand_film.push_back(s.film);
    }
  }
  // The moduli are the harmonics of that signal.
  const FourierSeries e = fourier_series(hand_elastic, 1), f = fourier_series(hand_film, 1);
  EXPECT_NEAR(r.summary["storage_elastic"].mean, e.sine[1] / gamma0, 1e-9 * scale / gamma0);
  EXPECT_NEAR(r.summary["loss_film"].mean, f.cosine[1] / gamma0, 1e-6 * film_scale / gamma0);
  // Small amplitude: G′ is the lattice's static (Born) modulus, and the √u∥
  // drag σ^film ∝ sign(c)|c|^{1/2} has the first harmonic
  // (2/√π) Γ(5/4)/Γ(7/4) of its peak.
  ContactSystem at_rest(lattice, box, testing::named_law("hertz"), 0.6);
  const double born = shear_modulus(at_rest).flow_gradient_modulus;
  EXPECT_NEAR(r.summary["storage"].mean, born, 1e-4 * born);
  const double first_harmonic = 2.0 / std::sqrt(kPi) * std::tgamma(1.25) / std::tgamma(1.75);
  EXPECT_NEAR(r.summary["loss_film"].mean, first_harmonic * film_scale / gamma0,
              0.01 * film_scale / gamma0);
}

INSTANTIATE_TEST_SUITE_P(Frequencies, LatticeOscillation, ::testing::Values(1e-2, 1e-3, 1e-7));

// A disordered packing in oscillation at small amplitude (the model preset
// `literal` on a packing of N = 200 at φ = 0.80), returning the run.
OscillationResult oscillate_packing(const Packing& packing, double skin, bool ehd, double amplitude,
                                    double frequency) {
  OscillationProtocol protocol;
  protocol.amplitude = amplitude;
  protocol.frequency = frequency;
  protocol.samples_per_cycle = 16;
  ShearModel model;
  model.gamma_tilde = protocol.peak_gamma_tilde();
  model.drag.enabled = ehd;
  OverdampedShear flow(
      ContactSystem(packing.particles, packing.box, testing::named_law("seth2011"), skin), model,
      ShearDrive::oscillatory(amplitude));
  const auto integrator =
      make_integrator(oscillation_integrator({}, protocol, model.drag.stokes.reference));
  OscillationResult r = run_oscillation(flow, *integrator, protocol);
  EXPECT_TRUE(r.converged) << r.stop_reason;
  return r;
}

Packing small_packing(unsigned seed) {
  return make_packing(testing::small_packing_spec(seed), testing::named_law("seth2011"));
}

// With the Stokes friction alone (no EHD films) the dynamics are linear at
// small amplitude: G′ is the packing's static linear modulus when every
// non-affine relaxation keeps up with the strain, and G″ grows like ω̃
// (a Kelvin–Voigt-like network of relaxing modes far below their rates).
TEST(DisorderedOscillation, WithoutFilmsTheLinearLimitIsTheStaticModulus) {
  omp_set_num_threads(1);
  const Packing packing = small_packing(4);
  ContactSystem at_rest(packing.particles, packing.box, testing::named_law("seth2011"), 0.3);
  const double static_modulus = shear_modulus(at_rest).flow_gradient_modulus;
  const OscillationResult slow = oscillate_packing(packing, 0.3, false, 1e-5, 1e-9);
  const OscillationResult fast = oscillate_packing(packing, 0.3, false, 1e-5, 1e-8);
  std::printf(
      "[ measured ] G' = %.7g against static %.7g; G'' = %.4g, %.4g at omega~ = 1e-9, 1e-8\n",
      slow.summary["storage"].mean, static_modulus, slow.summary["loss"].mean,
      fast.summary["loss"].mean);
  EXPECT_NEAR(slow.summary["storage"].mean, static_modulus, 1e-3 * static_modulus);
  EXPECT_NEAR(fast.summary["loss"].mean / slow.summary["loss"].mean, 10.0, 0.3);
  EXPECT_LT(slow.summary["loss"].mean, 0.01 * static_modulus);
}

// The EHD drag f ∝ √u∥ has no linear limit: at small amplitude the films'
// stress scales like the square root of the peak rate, σ^v ∝ (γ0 ω̃)^{1/2},
// so G″ ∝ (ω̃/γ0)^{1/2}: equal at equal ω̃/γ0, and √10 larger for ten times
// the frequency — a prediction of the paper's film law for the amplitude
// sweep (docs/oscillation.md compares it with a measured one).
TEST(DisorderedOscillation, FilmDragMakesTheLossModulusScaleWithTheRootOfFrequencyOverAmplitude) {
  omp_set_num_threads(1);
  const Packing packing = small_packing(1);
  const double base = oscillate_packing(packing, 0.3, true, 1e-4, 1e-9).summary["loss"].mean;
  const double same_ratio = oscillate_packing(packing, 0.3, true, 1e-3, 1e-8).summary["loss"].mean;
  const double faster = oscillate_packing(packing, 0.3, true, 1e-4, 1e-8).summary["loss"].mean;
  std::printf("[ measured ] G'' = %.4g (1e-4, 1e-9), %.4g (1e-3, 1e-8), %.4g (1e-4, 1e-8)\n", base,
              same_ratio, faster);
  EXPECT_NEAR(same_ratio / base, 1.0, 0.05);
  EXPECT_NEAR(faster / base, std::sqrt(10.0), 0.15 * std::sqrt(10.0));
}

struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted") {}
};

// Checkpoints of an oscillatory run restore its time as well as its cell: the
// resumed run continues the same cycles bit for bit.
TEST(OscillationCheckpoints, ResumedRunIsBitIdenticalToTheUninterruptedOne) {
  omp_set_num_threads(1);
  const PackingSpec spec = testing::small_packing_spec(7);
  const auto law = testing::named_law("seth2011");
  const Packing packing = make_packing(spec, law);
  OscillationProtocol protocol;
  protocol.amplitude = 0.05;
  protocol.frequency = 1e-3;
  protocol.samples_per_cycle = 16;
  protocol.min_cycles = protocol.max_cycles = 4;
  const auto run = [&](const std::function<void(const ShearCheckpoint&)>& save,
                       const ShearCheckpoint* resume) {
    ShearModel model;
    model.gamma_tilde = protocol.peak_gamma_tilde();
    OverdampedShear flow(ContactSystem(packing.particles, packing.box, law, spec.skin), model,
                         ShearDrive::oscillatory(protocol.amplitude));
    const IntegratorSpec scheme = oscillation_integrator({}, protocol, model.drag.stokes.reference);
    const auto integrator = make_integrator(scheme);
    ShearCheckpointing checkpointing{200, save, [&] { return make_integrator(scheme); }, resume};
    return run_oscillation(flow, *integrator, protocol, {}, checkpointing);
  };
  int saved = 0;
  const OscillationResult whole = run([&](const ShearCheckpoint&) { ++saved; }, nullptr);
  ASSERT_GE(saved, 3) << "the run must pass several checkpoints";
  testing::TemporaryDirectory dir;
  const auto file = dir.path() / "oscillation.checkpoint.h5";
  int written = 0;
  EXPECT_THROW(run(
                   [&](const ShearCheckpoint& c) {
                     write_checkpoint(file, c);
                     if (++written == 2) throw Interrupted();
                   },
                   nullptr),
               Interrupted);
  const ShearCheckpoint stored = read_checkpoint(file);
  ASSERT_TRUE(stored.time.has_value());
  EXPECT_GT(*stored.time, 0.0);
  EXPECT_EQ(stored.amplitude, protocol.amplitude);
  const OscillationResult resumed = run({}, &stored);
  ASSERT_EQ(whole.series.size(), resumed.series.size());
  for (std::size_t k = 0; k < whole.series.size(); ++k) {
    ASSERT_EQ(whole.series.strain[k], resumed.series.strain[k]) << k;
    ASSERT_EQ(std::memcmp(whole.series.elastic[k].data(), resumed.series.elastic[k].data(),
                          9 * sizeof(double)),
              0)
        << k;
  }
  EXPECT_EQ(whole.summary["storage"].mean, resumed.summary["storage"].mean);

  // A checkpoint of another drive is refused rather than resumed.
  ShearCheckpoint other = stored;
  other.amplitude = 0.1;
  EXPECT_THROW(run({}, &other), InputError);
  other = stored;
  other.time.reset();
  EXPECT_THROW(run({}, &other), InputError);
}

// The protocol refuses what it cannot run, naming the entry.
TEST(OscillationProtocol, RefusesBadSettings) {
  const auto refused = [](auto change, const std::string& word) {
    OscillationProtocol p;
    change(p);
    try {
      p.validate();
      ADD_FAILURE() << "accepted: " << word;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  refused([](auto& p) { p.samples_per_cycle = 30; }, "samples per cycle");
  refused([](auto& p) { p.amplitude = -1; }, "amplitude");
  refused([](auto& p) { p.amplitude = std::nan(""); }, "amplitude");
  refused([](auto& p) { p.frequency = 0; }, "frequency");
  refused([](auto& p) { p.amplitude = 1e-6, p.frequency = 1e-10; }, "peak shear rate");
  refused([](auto& p) { p.min_cycles = 3; }, "min cycles");
  refused([](auto& p) { p.max_cycles = 2; }, "max cycles");
}

}  // namespace
}  // namespace softglass::micro
