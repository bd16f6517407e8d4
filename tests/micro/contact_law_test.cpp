// Contact laws (micro/contact): continuity, stiffness = dF/dε, energy = ∫F,
// the Hertz limit, the `table` law and its input errors.
//
// Reduced form (contact_law.h): f = E* R_c² F(ε), W(ε) = ∫₀^ε F; the paper's law is
// F = (4/3) C ε^n with the (C, n) branches of docs/physics.md, "Elastic force":
//     ε ≤ 0.1: (1, 3/2);   0.1 < ε ≤ 0.2: (√10, 2);   ε > 0.2: (5√10, 3).
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

#include "common/errors.h"
#include "micro/contact/contact_law.h"
#include "micro_test_support.h"

namespace softglass::micro {
namespace {

namespace fs = std::filesystem;
using testing::TemporaryDirectory;
using testing::write_text;

ContactLawSpec table_spec(const fs::path& table) {
  return {.name = "table", .coefficients = {{"file", table.string()}}};
}

std::unique_ptr<ContactLaw> law(const std::string& name, const fs::path& table = {}) {
  return make_contact_law(name == "table" ? table_spec(table) : ContactLawSpec{.name = name});
}

fs::path hertz_table() {
  return fs::path(SOFTGLASS_SOURCE_DIR) / "cases" / "hertz_table.dat";
}

// One power-law branch F = a ε^n on [start, end).
struct Branch {
  double start, end, a, n;
};

// The seth2011 branches written from the spec table (not from the engine).
std::vector<Branch> seth2011_spec() {
  const double c1 = std::sqrt(10.0), c2 = 5.0 * std::sqrt(10.0);
  return {
      {0.0, 0.1, 4.0 / 3.0, 1.5}, {0.1, 0.2, 4.0 / 3.0 * c1, 2.0}, {0.2, 3.0, 4.0 / 3.0 * c2, 3.0}};
}
std::vector<Branch> hertz_spec() {
  return {{0.0, 3.0, 4.0 / 3.0, 1.5}};
}

const Branch& branch_at(const std::vector<Branch>& branches, double eps) {
  for (const Branch& b : branches)
    if (eps < b.end) return b;
  return branches.back();
}

// Test deformations: every branch, several decades, none within 1e-3 ε of a
// breakpoint (so that the finite-difference stencils below stay in one branch).
const std::vector<double> kSamples = {1e-6, 3e-4, 0.002, 0.03, 0.07, 0.098, 0.102,
                                      0.13, 0.17, 0.199, 0.21, 0.35, 0.8,   1.7};

// ----------------------------------------------------------------- seth2011

TEST(ContactLaw, Seth2011MatchesTheSpecBranches) {
  // F = (4/3) C ε^n with C, n from docs/physics.md, "Elastic force". The engine derives C from
  // continuity (pow(0.1, −1/2) rather than √10): a few ulp, hence 1e-14.
  const auto seth = law("seth2011");
  for (double eps : kSamples) {
    const Branch b = branch_at(seth2011_spec(), eps);
    const double expected = b.a * std::pow(eps, b.n);
    EXPECT_NEAR(seth->force(eps) / expected, 1.0, 1e-14) << "eps " << eps;
    EXPECT_NEAR(seth->stiffness(eps) / (b.a * b.n * std::pow(eps, b.n - 1)), 1.0, 1e-14)
        << "eps " << eps;
  }
}

TEST(ContactLaw, Seth2011IsContinuousAtTheBreakpoints) {
  // Just below and just above ε = 0.1 and 0.2 (one ulp apart): the force may
  // change by the ε step itself (relative n·2⁻⁵² ≈ 1e-15), and by nothing else if
  // the branches join. A jump in C of 1e-12 relative would be caught.
  const auto seth = law("seth2011");
  for (double breakpoint : {0.1, 0.2}) {
    const double below = std::nextafter(breakpoint, 0.0);
    const double above = std::nextafter(breakpoint, 1.0);
    const double f_below = seth->force(below), f_above = seth->force(above);
    EXPECT_NEAR(f_above / f_below, 1.0, 1e-12) << "force jumps at " << breakpoint;
    EXPECT_NEAR(seth->force(breakpoint) / f_below, 1.0, 1e-12);
    EXPECT_NEAR(seth->energy(above) / seth->energy(below), 1.0, 1e-12)
        << "energy jumps at " << breakpoint;
  }
  // The stiffness is not continuous (n changes): check that the test above is
  // probing the right place by seeing the kink, F'₊/F'₋ = n₊/n₋ at the joint.
  EXPECT_NEAR(seth->stiffness(std::nextafter(0.1, 1.0)) / seth->stiffness(std::nextafter(0.1, 0.0)),
              2.0 / 1.5, 1e-12);
  EXPECT_NEAR(seth->stiffness(std::nextafter(0.2, 1.0)) / seth->stiffness(std::nextafter(0.2, 0.0)),
              3.0 / 2.0, 1e-12);
}

// Central difference (g(x+h) − g(x−h))/2h of a function g = a x^m approximates
// g' with truncation error (h²/6)|g'''(ξ)|, i.e. relative to g' at most
//     h² |(m−1)(m−2)| / (6 (x−h)²)          (for m ≤ 3, |g'''| decreases with x),
// plus the rounding of g (a few ulp each, divided by 2h):  ≈ 4·2⁻⁵² x / (m h).
double central_difference_tolerance(double x, double h, double m) {
  const double truncation = h * h * std::abs((m - 1.0) * (m - 2.0)) / (6.0 * (x - h) * (x - h));
  const double rounding = 4.0 * DBL_EPSILON * x / (m * h);
  return 2.0 * (truncation + rounding);  // factor 2 of safety on a bound
}

void expect_stiffness_is_derivative(const ContactLaw& l, const std::vector<Branch>& branches) {
  for (double eps : kSamples) {
    const double h = 1e-4 * eps;  // within one branch: samples are ≥ 1e-3 ε from a joint
    const double fd = (l.force(eps + h) - l.force(eps - h)) / (2.0 * h);
    const double n = branch_at(branches, eps).n;  // F ∝ ε^n
    EXPECT_NEAR(fd / l.stiffness(eps), 1.0, central_difference_tolerance(eps, h, n))
        << l.name() << " at eps " << eps;
  }
}

void expect_energy_derivative_is_force(const ContactLaw& l, const std::vector<Branch>& branches) {
  for (double eps : kSamples) {
    const double h = 1e-4 * eps;
    const double fd = (l.energy(eps + h) - l.energy(eps - h)) / (2.0 * h);
    const double n = branch_at(branches, eps).n;  // W ∝ ε^{n+1} on the branch, up to a constant
    // W has an additive constant on later branches: the rounding term then
    // scales with W/F ≤ ε/(n+1) + const, still ≲ ε; keep the m = n+1 formula.
    EXPECT_NEAR(fd / l.force(eps), 1.0, central_difference_tolerance(eps, h, n + 1.0))
        << l.name() << " at eps " << eps;
  }
}

// W(ε) = ∫₀^ε F by composite Simpson in t = √ε (W = ∫₀^{√ε} 2t F(t²) dt): on a
// branch the integrand is g = 2a t^{2n+1}, smooth even at ε = 0 (where F'' is
// not), so Simpson's bound applies: |error| ≤ (b−a) h⁴ max|g''''| / 180, with
// g'''' = 2a (2n+1)(2n)(2n−1)(2n−2) t^{2n−3}. The integral is split at the
// branch joints so that each piece is one smooth branch.
void expect_energy_is_integral(const ContactLaw& l, const std::vector<Branch>& branches) {
  for (double eps : {0.05, 0.1, 0.15, 0.2, 0.6, 2.0}) {
    double integral = 0.0, bound = 0.0;
    for (const Branch& b : branches) {
      const double lo = std::sqrt(b.start), hi = std::sqrt(std::min(b.end, eps));
      if (hi <= lo) continue;
      constexpr int m = 400;  // even
      const double h = (hi - lo) / m;
      const auto g = [&](double t) { return 2.0 * t * l.force(t * t); };
      double sum = g(lo) + g(hi);
      for (int k = 1; k < m; ++k) sum += (k % 2 ? 4.0 : 2.0) * g(lo + k * h);
      integral += sum * h / 3.0;
      const double n = b.n;
      const double g4 = 2.0 * b.a * std::abs((2 * n + 1) * (2 * n) * (2 * n - 1) * (2 * n - 2)) *
                        std::max(std::pow(lo, 2 * n - 3), std::pow(hi, 2 * n - 3));
      bound += (hi - lo) * std::pow(h, 4) * g4 / 180.0;
    }
    // plus the rounding of ~m summed terms (relative 1e-13 is ≫ 400 ulp)
    EXPECT_NEAR(l.energy(eps), integral, bound + 1e-13 * integral) << l.name() << " at eps " << eps;
  }
}

TEST(ContactLaw, StiffnessIsTheDerivativeOfTheForce) {
  expect_stiffness_is_derivative(*law("seth2011"), seth2011_spec());
  expect_stiffness_is_derivative(*law("hertz"), hertz_spec());
  expect_stiffness_is_derivative(*law("table", hertz_table()), hertz_spec());
}

TEST(ContactLaw, EnergyDerivativeIsTheForce) {
  expect_energy_derivative_is_force(*law("seth2011"), seth2011_spec());
  expect_energy_derivative_is_force(*law("hertz"), hertz_spec());
  expect_energy_derivative_is_force(*law("table", hertz_table()), hertz_spec());
}

TEST(ContactLaw, EnergyIsTheIntegralOfTheForce) {
  expect_energy_is_integral(*law("seth2011"), seth2011_spec());
  expect_energy_is_integral(*law("hertz"), hertz_spec());
  expect_energy_is_integral(*law("table", hertz_table()), hertz_spec());
}

// -------------------------------------------------------------------- Hertz

TEST(ContactLaw, HertzIsFourThirdsEpsilonToTheThreeHalves) {
  // F = (4/3) ε^{3/2}, F' = 2 ε^{1/2}, W = (8/15) ε^{5/2}: exact formulas, so
  // only rounding (a few ulp ≈ 1e-15) separates engine and test.
  const auto hertz = law("hertz");
  EXPECT_EQ(hertz->name(), "hertz");
  for (double eps : kSamples) {
    EXPECT_NEAR(hertz->force(eps) / (4.0 / 3.0 * std::pow(eps, 1.5)), 1.0, 1e-15) << eps;
    EXPECT_NEAR(hertz->stiffness(eps) / (2.0 * std::sqrt(eps)), 1.0, 1e-15) << eps;
    EXPECT_NEAR(hertz->energy(eps) / (8.0 / 15.0 * std::pow(eps, 2.5)), 1.0, 1e-15) << eps;
  }
}

TEST(ContactLaw, Seth2011IsHertzUpToTenPercentDeformation) {
  // Same formula evaluated in another order: equal to a few ulp. Force and
  // energy up to and including ε = 0.1 (they are continuous there); the
  // stiffness strictly below 0.1 (at the joint it is one-sided, see below).
  const auto seth = law("seth2011");
  const auto hertz = law("hertz");
  for (double eps : {1e-9, 1e-5, 0.001, 0.01, 0.05, 0.09, 0.0999, std::nextafter(0.1, 0.0), 0.1}) {
    EXPECT_NEAR(seth->force(eps) / hertz->force(eps), 1.0, 1e-15) << eps;
    EXPECT_NEAR(seth->energy(eps) / hertz->energy(eps), 1.0, 1e-14) << eps;
    if (eps < 0.1) {
      EXPECT_NEAR(seth->stiffness(eps) / hertz->stiffness(eps), 1.0, 1e-15) << eps;
    }
  }
  // and stiffer beyond: the reconstructed branches only ever add force
  for (double eps : {0.11, 0.15, 0.2, 0.3, 1.0})
    EXPECT_GT(seth->force(eps), hertz->force(eps)) << eps;
}

// docs/physics.md, "Elastic force" assigns ε = 0.1 to the Hertz branch (ε ≤ 0.1) and ε = 0.2 to the
// n = 2 branch (0.1 < ε ≤ 0.2). F and W are continuous at the joints, so only
// the stiffness F' tells which branch is used there (the next branch's is 4/3
// and 3/2 times larger).
TEST(ContactLaw, Seth2011StiffnessAtTheJointsFollowsTheSpecBranches) {
  const auto seth = law("seth2011");
  EXPECT_NEAR(seth->stiffness(0.1), 2.0 * std::sqrt(0.1), 1e-15);  // (4/3)·(3/2) ε^{1/2}
  EXPECT_NEAR(seth->stiffness(0.2), 4.0 / 3.0 * std::sqrt(10.0) * 2.0 * 0.2,
              1e-14);  // (4/3) C n ε^{n−1}
}

// -------------------------------------------------------------------- table

TEST(ContactLawTable, HertzTableReproducesHertzAtAndBetweenPoints) {
  // cases/hertz_table.dat samples (4/3) ε^{3/2} at ε = 1e-3, 1e-2, 0.1, 1 to 16
  // digits. Log–log interpolation of a power law is the power law itself, so
  // the table law is Hertz everywhere up to rounding: the fitted exponent is
  // off by ~1e-16, which moves F by ~1e-16·|ln(ε/ε_k)| ≤ 1e-14 over the
  // decades tested (below the first and above the last point included).
  const auto table = law("table", hertz_table());
  const auto hertz = law("hertz");
  EXPECT_EQ(table->name(), "table");
  std::vector<double> points = {0.001, 0.01, 0.1, 1.0};                        // at the rows
  for (double eps : {0.002, 0.0031, 0.05, 0.099, 0.5}) points.push_back(eps);  // between
  for (double eps : {1e-6, 1e-4, 5e-4}) points.push_back(eps);  // below the first row
  for (double eps : {1.5, 3.0, 10.0}) points.push_back(eps);    // above the last row
  for (double eps : points) {
    EXPECT_NEAR(table->force(eps) / hertz->force(eps), 1.0, 1e-13) << "eps " << eps;
    EXPECT_NEAR(table->stiffness(eps) / hertz->stiffness(eps), 1.0, 1e-13) << "eps " << eps;
    EXPECT_NEAR(table->energy(eps) / hertz->energy(eps), 1.0, 1e-13) << "eps " << eps;
  }
}

TEST(ContactLawTable, BundledElasticSphereLawIsHertzAtSmallStrainAndStiffensMildly) {
  // cases/contact_law_neohookean.dat, computed by macro's sphere_compression
  // (docs/physics.md): an elastic sphere follows Hertz where the contact is
  // small (to its mesh's ±0.5 %) and stiffens beyond it, without reaching
  // the n = 2 and 3 branches of seth2011 (its F'·ε/F, the local exponent,
  // stays below 1.8 up to ε = 1).
  const auto table = law("table", fs::path(SOFTGLASS_SOURCE_DIR) / "cases" /
                                      "contact_law_neohookean.dat");
  const auto hertz = law("hertz");
  for (double eps : {0.003, 0.005, 0.01})
    EXPECT_NEAR(table->force(eps) / hertz->force(eps), 1.0, 0.01) << "eps " << eps;
  double last = 1.0;
  for (double eps : {0.05, 0.2, 0.4, 0.8, 1.0}) {
    const double ratio = table->force(eps) / hertz->force(eps);
    EXPECT_GT(ratio, last) << "eps " << eps;
    const double exponent = table->stiffness(eps) * eps / table->force(eps);
    EXPECT_GT(exponent, 1.45) << "eps " << eps;
    EXPECT_LT(exponent, 1.8) << "eps " << eps;
    last = ratio;
  }
}

TEST(ContactLawTable, InterpolatesLinearlyInLogLog) {
  // A table that is not a single power law: between (0.1, 1) and (0.2, 8) the
  // law is F = 1·(ε/0.1)^3; between (0.2, 8) and (0.4, 16) F = 8·(ε/0.2)^1.
  // Below 0.1 the first segment continues (ε^3), above 0.4 the last (ε^1).
  TemporaryDirectory dir;
  const fs::path file = dir / "two_segments.dat";
  write_text(file, "# eps, F\n0.1 1\n\n0.2, 8\n0.4\t16\n");
  const auto table = law("table", file);
  const auto expected = [](double eps) {
    return eps < 0.2 ? std::pow(eps / 0.1, 3.0) : 8.0 * (eps / 0.2);
  };
  for (double eps : {0.01, 0.1, 0.13, 0.2, 0.3, 0.4, 0.9}) {
    EXPECT_NEAR(table->force(eps) / expected(eps), 1.0, 1e-13) << eps;
  }
  // Energy: ∫₀^0.2 (ε/0.1)³ = 0.1/4 · 2⁴ = 0.4; then ∫_0.2^0.4 40 ε = 20 (0.16 − 0.04) = 2.4.
  EXPECT_NEAR(table->energy(0.2), 0.4, 1e-13);
  EXPECT_NEAR(table->energy(0.4), 2.8, 1e-13);
}

// Message of the InputError thrown by make_contact_law, or a marker if none.
std::string input_error(const ContactLawSpec& spec) {
  try {
    make_contact_law(spec);
  } catch (const InputError& e) {
    return e.what();
  }
  return "<no InputError>";
}

struct MalformedTable {
  const char* what;
  const char* contents;
  int line;  // expected line number in the message, 0 if none applies
};

TEST(ContactLawTable, MalformedTablesAreRejectedWithFileAndLine) {
  const std::vector<MalformedTable> cases = {
      {"decreasing deformation", "0.1 1\n0.05 2\n", 2},
      {"repeated deformation", "0.1 1\n0.2 2\n0.2 3\n", 3},
      {"decreasing force", "0.1 1\n0.2 0.5\n", 2},
      {"single row", "0.1 1\n", 0},
      {"no rows at all", "# only a comment\n\n", 0},
      {"text instead of numbers", "0.1 1\nabc def\n", 2},
      {"number followed by text", "0.1 1\n0.2 2x\n", 2},
      {"three columns", "0.1 1\n0.2 2 3\n", 2},
      {"one column", "0.1 1\n0.2\n", 2},
      {"negative deformation", "-0.1 1\n0.2 2\n", 1},
      {"negative force", "0.1 -1\n0.2 2\n", 1},
      {"zero deformation", "0 0\n0.2 2\n", 1},
      // comments and blank lines count in the line numbers users see in an editor
      {"error after a header", "# eps F\n\n0.1 1\n0.2 2\n0.3 oops\n", 5},
  };
  TemporaryDirectory dir;
  int index = 0;
  for (const MalformedTable& c : cases) {
    const fs::path file = dir / ("bad_" + std::to_string(index++) + ".dat");
    write_text(file, c.contents);
    const std::string message = input_error(table_spec(file));
    EXPECT_NE(message.find(file.string()), std::string::npos) << c.what << ": " << message;
    if (c.line > 0) {
      EXPECT_NE(message.find("line " + std::to_string(c.line)), std::string::npos)
          << c.what << ": " << message;
    }
  }
}

TEST(ContactLawTable, MissingFileIsAnInputErrorNamingIt) {
  TemporaryDirectory dir;
  const fs::path file = dir / "no_such_table.dat";
  const std::string message = input_error(table_spec(file));
  EXPECT_NE(message.find(file.string()), std::string::npos) << message;
}

TEST(ContactLawTable, TableLawWithoutFileIsAnInputError) {
  const std::string message = input_error({.name = "table"});
  EXPECT_NE(message.find("table file"), std::string::npos) << message;
}

TEST(ContactLaw, UnknownNameListsTheAllowedNames) {
  const std::string message = input_error({.name = "kelvin-voigt"});
  EXPECT_NE(message.find("kelvin-voigt"), std::string::npos) << message;
  const std::vector<std::string> names = contact_laws().names();
  for (const std::string& name : names) EXPECT_NE(message.find(name), std::string::npos) << message;
  // and every registered law is accepted at its default coefficients (table
  // needs its file), under its own name
  for (const std::string& name : names) {
    const auto made = law(name, hertz_table());
    EXPECT_EQ(made->name(), name);
  }
}

// Every registered law at its defaults (table: the Hertz table): continuous,
// F' = dF/dε and W' = F by central differences, F increasing from F(0+) = 0.
// A new law is checked here without editing the test.
TEST(ContactLaw, EveryRegisteredLawIsConsistent) {
  for (const std::string& name : contact_laws().names()) {
    const auto l = law(name, hertz_table());
    EXPECT_LT(l->force(1e-9), 1e-9) << name;
    double previous = 0.0;
    for (double eps : kSamples) {
      const double h = 1e-6 * eps;
      const double f = l->force(eps);
      EXPECT_GT(f, previous) << name << " at " << eps;
      previous = f;
      const double df = (l->force(eps + h) - l->force(eps - h)) / (2 * h);
      EXPECT_NEAR(l->stiffness(eps) / df, 1.0, 1e-6) << name << " at " << eps;
      const double dw = (l->energy(eps + h) - l->energy(eps - h)) / (2 * h);
      EXPECT_NEAR(dw / f, 1.0, 1e-6) << name << " at " << eps;
    }
  }
  // (h = 1e-6 ε keeps every stencil inside one branch; the rounding of the
  // differences, ≈ 4·2⁻⁵²/(n·1e-6) ≈ 1e-9, and the truncation, ≈ 1e-12, are far
  // below the 1e-6 allowed.)
}

// -------------------------------------------------------------------- power

// (4/3) C ε^n with the user's C and n, written here from the definition.
TEST(ContactLawPower, IsFourThirdsCEpsilonToTheN) {
  const auto l = make_contact_law({.name = "power", .coefficients = {{"C", "2"}, {"n", "2.5"}}});
  const std::vector<Branch> spec = {{0.0, 3.0, 8.0 / 3.0, 2.5}};
  for (double eps : kSamples)
    EXPECT_NEAR(l->force(eps) / (8.0 / 3.0 * std::pow(eps, 2.5)), 1.0, 1e-14) << eps;
  expect_stiffness_is_derivative(*l, spec);
  expect_energy_is_integral(*l, spec);
  // the defaults are Hertz
  const auto hertz = law("hertz");
  const auto defaults = make_contact_law({.name = "power"});
  for (double eps : kSamples) EXPECT_NEAR(defaults->force(eps) / hertz->force(eps), 1.0, 1e-14);
}

// ---------------------------------------------------------------- piecewise

ContactLawSpec piecewise(const std::string& breakpoints, const std::string& exponents,
                         const std::string& c = "1") {
  return {.name = "piecewise",
          .coefficients = {{"breakpoints", breakpoints}, {"exponents", exponents}, {"C", c}}};
}

TEST(ContactLawPiecewise, DefaultsAreSeth2011) {
  const auto defaults = make_contact_law({.name = "piecewise"});
  const auto seth = law("seth2011");
  for (double eps : kSamples) EXPECT_EQ(defaults->force(eps), seth->force(eps)) << eps;
}

// Breakpoints moved to ε = 0.4 and 0.9 (away from kSamples, as the stencils of
// the helpers need): C from continuity, written here from the definition:
// (4/3) ε^{3/2} = (4/3) C₁ ε² at 0.4 → C₁ = 0.4^{-1/2}; C₁ ε² = C₂ ε³ at 0.9.
TEST(ContactLawPiecewise, CoefficientsFromTheParameterFileKeepTheLawContinuous) {
  const auto l = make_contact_law(piecewise("0.4, 0.9", "1.5, 2, 3"));
  const double c1 = 1.0 / std::sqrt(0.4), c2 = c1 / 0.9;
  const std::vector<Branch> spec = {
      {0.0, 0.4, 4.0 / 3.0, 1.5}, {0.4, 0.9, 4.0 / 3.0 * c1, 2.0}, {0.9, 3.0, 4.0 / 3.0 * c2, 3.0}};
  for (double eps : {0.05, 0.3, 0.399, 0.401, 0.6, 0.899, 0.901, 1.5}) {
    const Branch& b = branch_at(spec, eps);
    EXPECT_NEAR(l->force(eps) / (b.a * std::pow(eps, b.n)), 1.0, 1e-14) << eps;
  }
  expect_stiffness_is_derivative(*l, spec);
  expect_energy_is_integral(*l, spec);
  // a first prefactor C scales the whole law
  const auto doubled = make_contact_law(piecewise("0.4, 0.9", "1.5, 2, 3", "2"));
  for (double eps : {0.05, 0.6, 1.5}) EXPECT_NEAR(doubled->force(eps) / l->force(eps), 2.0, 1e-14);
}

TEST(ContactLawPiecewise, BadCoefficientsAreInputErrorsNamingThem) {
  struct Case {
    ContactLawSpec spec;
    const char* expected;
  };
  const std::vector<Case> cases = {
      {piecewise("0.1, 0.2", "1.5, 2"), "2 exponents for 2 breakpoints"},
      {piecewise("0.2, 0.1", "1.5, 2, 3"), "breakpoints must be positive and increase"},
      {piecewise("0.1", "1.5, 0.5"), "'exponents' = 0.5 is outside"},
      {piecewise("0.1", "1.5, 2", "-1"), "'C' = -1 is outside"},
      {piecewise("0.1, x", "1.5, 2, 3"), "'x' is not a number"},
      {{.name = "piecewise", .coefficients = {{"slope", "2"}}}, "has no coefficient 'slope'"},
      {{.name = "hertz", .coefficients = {{"C", "2"}}},
       "contact law 'hertz' has no coefficient 'C'"},
  };
  for (const Case& c : cases) {
    const std::string message = input_error(c.spec);
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace softglass::micro
