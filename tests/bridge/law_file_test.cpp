// The law file: written by law_text, read back by ParameterHandler (the
// command line's reader), with every malformed variant refused naming the entry.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "bridge/app/law_file.h"
#include "bridge/law/law.h"
#include "bridge_test_support.h"
#include "common/errors.h"
#include "synthetic_sweep.h"

namespace softglass::bridge {
namespace {

using testing::expect_contains;

SweepAnalysis synthetic_analysis(bool normal = true) {
  testing::SyntheticTruth t;
  t.normal = normal;
  const testing::SyntheticSweep s = testing::make_synthetic_sweep(t, 1);
  const Sweep sweep = make_sweep(s.table);
  return analyse_sweep(sweep, *make_packing_resampler(sweep, s.runs, "runs"), {100, 1});
}

Law synthetic_law(bool normal = true) {
  return make_law(synthetic_analysis(normal), {"test law", "second line"});
}

TEST(LawFile, RoundTripsThroughParameterHandler) {
  testing::TemporaryDirectory dir;
  for (bool normal : {true, false}) {
    const Law law = synthetic_law(normal);
    testing::write_text(dir / "law.prm", law_text(law));
    const Law back = read_law_file(dir / "law.prm");
    ASSERT_EQ(back.phi, law.phi);
    EXPECT_NEAR(back.gamma_tilde_min, law.gamma_tilde_min, 1e-6 * law.gamma_tilde_min);
    EXPECT_EQ(back.hb[index(Quantity::N1)].has_value(), normal);
    EXPECT_EQ(back.k[index(Quantity::N2)].has_value(), normal);
    for (Quantity q : kAllQuantities) {
      if (!law.hb[index(q)]) continue;
      for (std::size_t j = 0; j < law.phi.size(); ++j) {
        // Values are written to 10 significant digits, errors to 4.
        const HbLaw &a = *law.hb[index(q)], &b = *back.hb[index(q)];
        EXPECT_NEAR(b.yield[j].value, a.yield[j].value, 1e-9 * std::abs(a.yield[j].value));
        EXPECT_NEAR(b.exponent[j].error, a.exponent[j].error, 1e-3 * a.exponent[j].error);
        EXPECT_NEAR(b.correlation[j], a.correlation[j], 1e-4);
      }
    }
    EXPECT_NEAR(back.k[0]->value, law.k[0]->value, 1e-8 * law.k[0]->value);
    expect_contains(law_text(law), {"# test law\n", "subsection law", "set k ", "80 +- 3"});
  }
}

// G0's error from one packing is no number: n/a in memory (NaN), 0 in the file
// beside `packings` = 1, and n/a again when read back; with several packings
// it is the bootstrap's.
TEST(LawFile, TheErrorOfG0FromOnePackingIsNotANumber) {
  Law law = synthetic_law();
  ASSERT_EQ(law.packings.size(), law.phi.size());
  for (std::size_t j = 0; j < law.phi.size(); ++j) {
    EXPECT_GE(law.packings[j], 2.0);
    EXPECT_GT(law.modulus[j].error, 0.0);
  }
  law.packings[0] = 1;
  law.modulus[0].error = NAN;
  testing::TemporaryDirectory dir;
  testing::write_text(dir / "law.prm", law_text(law));
  const Law back = read_law_file(dir / "law.prm");
  EXPECT_TRUE(std::isnan(back.modulus[0].error));
  EXPECT_NEAR(back.modulus[1].error, law.modulus[1].error, 1e-3 * law.modulus[1].error);
  EXPECT_EQ(back.packings, law.packings);
  expect_contains(law_text(law), {"set packings", "read as n/a"});
  std::string text = law_text(law);
  text.replace(text.find("set packings            = 1"), 28, "set packings            = 0.5");
  testing::write_text(dir / "bad.prm", text);
  EXPECT_THROW(read_law_file(dir / "bad.prm"), InputError);
}

// The amplitude-sweep law reads back with its rows per volume fraction; a
// list of the wrong length is refused naming it.
TEST(LawFile, RoundTripsTheAmplitudeSweepLaw) {
  testing::TemporaryDirectory dir;
  Law law = synthetic_law();
  OscillationTable table;
  table.source = "t.csv";
  for (double phi : {0.8, 0.85})
    for (double g : {1e-4, 1e-2, 1.0})
      table.points.push_back({phi, 2e-7, g, phi < 0.82 ? 1u : 3u, {phi / (1 + 10 * g), 1e-5},
                              {0.2 * phi, 2e-5}, {phi, 0.0}, 0});
  law.amplitude_sweep = make_amplitude_sweep_law(table, {});
  const std::string text = law_text(law);
  testing::write_text(dir / "law.prm", text);
  const Law back = read_law_file(dir / "law.prm");
  ASSERT_TRUE(back.amplitude_sweep.has_value());
  const AmplitudeSweepLaw &a = *law.amplitude_sweep, &b = *back.amplitude_sweep;
  EXPECT_EQ(b.phi, a.phi);
  EXPECT_EQ(b.amplitudes, a.amplitudes);
  EXPECT_DOUBLE_EQ(b.frequency, a.frequency);
  for (std::size_t i = 0; i < a.phi.size(); ++i) {
    for (std::size_t k = 0; k < a.amplitudes.size(); ++k)
      EXPECT_NEAR(b.storage[i][k].value, a.storage[i][k].value, 1e-9 * a.storage[i][k].value);
    EXPECT_NEAR(b.crossover_strain[i].value, a.crossover_strain[i].value, 1e-9);
    // φ = 0.8 is one packing's: its errors are n/a, written 0 and read back n/a.
    for (const AmplitudeSweepLaw* sweep : {&a, &b}) {
      EXPECT_EQ(std::isnan(sweep->storage[i][1].error), i == 0) << "phi " << a.phi[i];
      EXPECT_EQ(std::isnan(sweep->softening_strain[i].error), i == 0) << "phi " << a.phi[i];
    }
  }
  EXPECT_EQ(b.packings, (std::vector<double>{1, 3}));
  std::string broken = text;
  const auto at = broken.find("set storage ");
  broken.replace(at, broken.find('\n', at) - at, "set storage = 1, 2, 3");
  testing::write_text(dir / "broken.prm", broken);
  expect_contains(
      [&] {
        try {
          read_law_file(dir / "broken.prm");
        } catch (const InputError& e) {
          return std::string(e.what());
        }
        return std::string();
      }(),
      {"amplitude sweep/storage", "expected 6"});
}

// A failed N1 fit (NaN in its numbers, warned about by `fit`) and a failed
// force-law error are left out of the law, with a note, and the law file that
// results reads back.
TEST(LawFile, LeavesOutFailedPartsSoThatEveryWrittenLawReadsBack) {
  SweepAnalysis a = synthetic_analysis();
  a.estimate.fit.groups[2].hb[index(Quantity::N1)]->exponent = std::nan("");
  a.uncertainty.error.groups[1].force_slope = std::nan("");
  const Law law = make_law(a, {"test law"});
  EXPECT_FALSE(law.hb[index(Quantity::N1)].has_value());
  EXPECT_TRUE(law.hb[index(Quantity::N2)].has_value());
  EXPECT_TRUE(law.hb[index(Quantity::force)].has_value());
  EXPECT_FALSE(law.force.has_value());
  const std::string text = law_text(law);
  expect_contains(text, {"# N1 Herschel-Bulkley law: left out",
                         "# force law f_m = f_y + k_f "
                         "gamma~^(1/2): left out"});
  testing::TemporaryDirectory dir;
  testing::write_text(dir / "law.prm", text);
  const Law back = read_law_file(dir / "law.prm");
  EXPECT_FALSE(back.hb[index(Quantity::N1)].has_value());
  EXPECT_TRUE(back.k[index(Quantity::N1)].has_value()) << "k' itself did not fail";
  EXPECT_FALSE(back.force.has_value());
}

TEST(LawFile, RefusesMalformedFilesNamingTheEntry) {
  testing::TemporaryDirectory dir;
  const std::string good = law_text(synthetic_law());
  const auto refusal = [&](const std::string& text) -> std::string {
    testing::write_text(dir / "bad.prm", text);
    try {
      read_law_file(dir / "bad.prm");
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "accepted";
    return "";
  };
  const auto replaced = [&](const std::string& pattern, const std::string& by) {
    const std::string text =
        std::regex_replace(good, std::regex(pattern), by, std::regex_constants::format_first_only);
    EXPECT_NE(text, good) << pattern;
    return text;
  };
  expect_contains(refusal(replaced("  set k error[^\n]*\n", "")),
                  {"subsection law/universal: entry 'k error' missing"});
  expect_contains(refusal(good + "subsection law\n  set colour = red\nend\n"), {"colour"});
  expect_contains(refusal(replaced("(set yield +=) [^,]*,", "$1")),
                  {"sigma/yield", "one per volume fraction"});
  expect_contains(refusal(replaced("(set exponent +=) [^,]*,", "$1 2.5,")),
                  {"sigma/exponent", "(0, 2]"});
  expect_contains(refusal(replaced("(set volume fractions +=) 0.7,", "$1 0.95,")), {"increase"});
  expect_contains(refusal(replaced("(set k +=) [^\n]*", "$1 eighty")), {"k"});
  expect_contains(refusal(replaced("  subsection sigma\n[^]*?  end\n", "")), {"sigma"});
  // Required entries set to nothing (found by reading the reader for the fuzz
  // tests: the empty mean exponent was read from a disengaged optional).
  expect_contains(
      refusal(
          replaced("(set mean exponent +=)[^\n]*\n( *set mean exponent error +=)[^\n]*", "$1\n$2")),
      {"'universal/mean exponent' and 'universal/mean exponent error' must hold one "
       "value each (they hold 0 and 0)"});
  expect_contains(refusal(replaced("(set k +=)[^\n]*\n( *set k error +=)[^\n]*", "$1\n$2")),
                  {"'universal/k' and 'universal/k error'"});
  expect_contains(refusal(replaced("(set k error +=)[^\n]*", "$1 -1")),
                  {"'universal/k'", "non-negative error"});
  EXPECT_THROW(read_law_file(dir / "no_such.prm"), InputError);
  // A law that includes itself: an error naming the nesting, not a stack
  // overflow inside deal.II's reader (common/parameter_input.h).
  expect_contains(refusal("include bad.prm\n" + good), {"law file", "includes nest deeper than 8"});
}

}  // namespace
}  // namespace softglass::bridge
