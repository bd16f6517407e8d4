// The flow-curve table and its per-packing companion: a synthetic sweep read
// back exactly, and degenerate input — missing columns and values, NaN,
// negative values, mixed units, too few points, mismatched companions —
// refused with a message naming what is wrong.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>

#include "bridge/io/flow_curve_table.h"
#include "bridge/sweep/resampling.h"
#include "bridge/sweep/sweep.h"
#include "bridge_test_support.h"
#include "common/errors.h"
#include "synthetic_sweep.h"

namespace softglass::bridge {
namespace {

using testing::expect_contains;

FlowCurveTable parse_table(const std::string& text) {
  return read_flow_curve_table(CsvTable::parse(text, "sweep.csv"));
}

// The synthetic table as CSV, with `from` replaced by `to` once.
std::string edited(const std::string& from, const std::string& to) {
  std::string text = testing::table_csv(testing::make_synthetic_sweep({}, 1));
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

// The message of the InputError that reading `text` (table, grouped) raises.
std::string refusal(const std::string& text) {
  try {
    make_sweep(parse_table(text));
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted:\n" << text.substr(0, 400);
  return "";
}

TEST(FlowCurveTable, ReadsTheSyntheticSweepBack) {
  const testing::SyntheticSweep s = testing::make_synthetic_sweep({}, 3);
  const FlowCurveTable t = parse_table(testing::table_csv(s));
  ASSERT_EQ(t.points.size(), s.table.points.size());
  EXPECT_EQ(t.present, (std::array<bool, kQuantities>{true, true, true, true}));
  EXPECT_EQ(t.comments.size(), 1u);
  for (std::size_t i = 0; i < t.points.size(); ++i) {
    const StatePoint &a = t.points[i], &b = s.table.points[i];
    EXPECT_EQ(a.phi, b.phi);
    EXPECT_NEAR(a.gamma_tilde, b.gamma_tilde, 1e-6 * b.gamma_tilde);  // 7 digits written
    for (Quantity q : kAllQuantities)
      EXPECT_NEAR(a.values[index(q)]->value, b.values[index(q)]->value,
                  1e-9 * std::abs(b.values[index(q)]->value));  // 11 digits written
  }
  EXPECT_LT(t.points[0].values[index(Quantity::N2)]->value, 0) << "N2 may be negative";
  const Sweep sweep = make_sweep(t);
  ASSERT_EQ(sweep.groups.size(), 5u);
  EXPECT_EQ(sweep.points(), t.points.size());
  EXPECT_EQ(sweep.groups[2].phi, 0.8);
  EXPECT_TRUE(
      std::is_sorted(sweep.groups[2].curves[0]->x.begin(), sweep.groups[2].curves[0]->x.end()));
}

TEST(FlowCurveTable, RefusesDegenerateTablesNamingTheProblem) {
  const std::string header = testing::table_csv(testing::make_synthetic_sweep({}, 1));
  const struct {
    const char* what;
    std::string text;
    std::vector<std::string> message;
  } cases[] = {
      {"missing column", edited(",G0_se [E*]", ",G0_error [E*]"), {"G0_se [E*]", "missing"}},
      {"column without units", edited("sigma [E*],", "sigma,"), {"'sigma'", "no units"}},
      {"mixed units",
       edited("N1 [E*],", "N1 [Pa],"),
       {"'N1 [Pa]'", "'Pa'", "expected 'E*'", "reduced"}},
      {"dimensionless phi in percent", edited("phi [1]", "phi [%]"), {"'phi [%]'", "expected '1'"}},
      {"NaN", edited(",5,1.2868314229e-03", ",5,nan"), {"line 3", "'sigma [E*]'", "not finite"}},
      {"empty cell", edited(",5,1.2868314229e-03", ",5,"), {"line 3", "'sigma [E*]'", "empty"}},
      {"negative stress",
       edited(",5,1.2868314229e-03", ",5,-1.2868314229e-03"),
       {"line 3", "'sigma [E*]'", "must be > 0"}},
      {"negative rate",
       edited("0.7,1.000000e-09", "0.7,-1.000000e-09"),
       {"'gamma_tilde [1]'", "must be >= 0"}},
      {"zero standard error",
       edited("1.2868314229e-03,1.222923e-05", "1.2868314229e-03,0"),
       {"'sigma_se [E*]'", "must be > 0"}},
      {"phi above one", edited("0.7,1.000000e-09", "1.7,1.000000e-09"), {"'phi [1]'", "(0, 1)"}},
      {"fractional packings",
       edited("0.7,1.000000e-09,5", "0.7,1.000000e-09,4.5"),
       {"'packings [1]'", "whole number"}},
      {"duplicate state point",
       edited("0.7,3.162278e-09", "0.7,1.000000e-09"),
       {"already on line 3"}},
      {"N1 without its error", edited(",N1_se [E*]", ",N1_sd [E*]"), {"N1_se [E*]", "missing"}},
      {"no rows", header.substr(0, header.find("\n0.7")), {"no rows"}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.what);
    const std::string message = refusal(c.text);
    for (const std::string& part : c.message)
      EXPECT_NE(message.find(part), std::string::npos) << message;
  }
}

// The synthetic table with the first data row's `column` set to `value`.
std::string with_first_row(const std::string& column, const std::string& value) {
  std::string text = testing::table_csv(testing::make_synthetic_sweep({}, 1));
  const auto header_start = text.find("phi [1]");
  const auto header_end = text.find('\n', header_start);
  const std::string header = text.substr(header_start, header_end - header_start);
  std::size_t field = 0;
  for (std::size_t at = 0; at < header.find(column); ++at) field += header[at] == ',';
  const auto row_start = header_end + 1, row_end = text.find('\n', row_start);
  std::string row = text.substr(row_start, row_end - row_start);
  std::size_t begin = 0;
  for (std::size_t k = 0; k < field; ++k) begin = row.find(',', begin) + 1;
  const std::size_t end = std::min(row.find(',', begin), row.size());
  row.replace(begin, end - begin, value);
  return text.replace(row_start, row_end - row_start, row);
}

// f_m = 0 is a value (the minimum of g_{2,-2} beyond contact, no force there);
// a negative f_m is not.
TEST(FlowCurveTable, ForceAtMaximumAccumulationMayBeZeroNotNegative) {
  const FlowCurveTable t = parse_table(with_first_row("f_m [E*R^2]", "0"));
  EXPECT_EQ(t.points[0].values[index(Quantity::force)]->value, 0.0);
  expect_contains(refusal(with_first_row("f_m [E*R^2]", "-0.01")),
                  {"'f_m [E*R^2]'", "must be >= 0"});
}

// A sweep's quasi-static rows (γ̃ = 0, one per φ) are read, kept out of the
// curves and of G0 — the sweep is that of the table without them — and their
// stresses kept beside the curves; the companion's quasi-static runs are
// checked against them but not resampled.
TEST(FlowCurveTable, SetsQuasiStaticRowsApartFromTheCurves) {
  const testing::SyntheticTruth truth;
  const testing::SyntheticSweep plain = testing::make_synthetic_sweep(truth, 1);
  const testing::SyntheticSweep s = testing::with_quasi_static(plain, truth, 2);
  const std::string text = testing::table_csv(s);
  const FlowCurveTable table = parse_table(text);
  ASSERT_EQ(table.points.size(), plain.table.points.size() + truth.phi.size());
  const Sweep with = make_sweep(table),
              without = make_sweep(parse_table(testing::table_csv(plain)));
  EXPECT_EQ(with.points(), without.points());
  EXPECT_EQ(with.quasi_static_points(), truth.phi.size());
  EXPECT_EQ(without.quasi_static_points(), 0u);
  for (std::size_t j = 0; j < with.groups.size(); ++j) {
    const PhiGroup &a = with.groups[j], &b = without.groups[j];
    EXPECT_EQ(a.modulus.value, b.modulus.value);
    EXPECT_EQ(a.modulus.error, b.modulus.error);
    EXPECT_EQ(a.lines.size(), b.lines.size());
    for (Quantity q : kAllQuantities) {
      EXPECT_EQ(a.curves[index(q)]->x, b.curves[index(q)]->x);
      EXPECT_EQ(a.curves[index(q)]->y, b.curves[index(q)]->y);
      EXPECT_EQ(a.curves[index(q)]->se, b.curves[index(q)]->se);
    }
    ASSERT_TRUE(a.quasi_static.has_value());
    EXPECT_FALSE(b.quasi_static.has_value());
    const Estimate sigma = *a.quasi_static->values[index(Quantity::sigma)];
    EXPECT_NEAR(sigma.value, truth.sigma_yield(j), 5 * sigma.error) << "the yield stress";
  }
  const std::vector<PackingRun> runs =
      read_packing_runs(CsvTable::parse(testing::runs_csv(s), "runs.csv"));
  EXPECT_NO_THROW(make_packing_resampler(with, runs, "runs.csv"));
  const auto refusal_of = [&](const Sweep& sweep, const std::vector<PackingRun>& companion) {
    try {
      make_packing_resampler(sweep, companion, "runs.csv");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    ADD_FAILURE() << "companion accepted";
    return std::string();
  };
  const auto at_rest = [](const PackingRun& r) { return r.gamma_tilde == 0.0; };
  const std::size_t first =
      static_cast<std::size_t>(std::find_if(runs.begin(), runs.end(), at_rest) - runs.begin());
  ASSERT_LT(first, runs.size());
  std::vector<PackingRun> shifted = runs;
  *shifted[first].values[index(Quantity::sigma)] *= 1.5;
  expect_contains(refusal_of(with, shifted),
                  {"quasi-static run(s) at phi = 0.7", "average sigma", "same sweep"});
  std::vector<PackingRun> missing = runs;
  missing.erase(missing.begin() + static_cast<std::ptrdiff_t>(first));
  expect_contains(refusal_of(with, missing), {"quasi-static run(s) at phi = 0.7", "same sweep"});
  expect_contains(refusal_of(without, runs), {"gamma~ = 0 is not a state point"});

  // φ within 1e-9 are one φ: a second row of it at the same γ̃, quasi-static
  // or not, is one too many.
  for (const char* rate : {"0.000000e+00", "1.000000e-09"}) {
    const std::string row = text.substr(text.find(std::string("\n0.7,") + rate + ",") + 1);
    const std::string twin = "0.7000000001" + row.substr(3, row.find('\n') - 2);
    expect_contains(refusal(text + twin),
                    {"state point phi = 0.7000000001, gamma~ = ", "already on line"});
  }
}

TEST(FlowCurveTable, RefusesTooFewShearRatesPerVolumeFraction) {
  testing::SyntheticTruth truth;
  truth.gamma_tilde = {1e-8, 1e-7, 1e-6};
  const std::string message = refusal(testing::table_csv(testing::make_synthetic_sweep(truth, 1)));
  expect_contains(message, {"phi = 0.7", "3 shear rate", "at least 4"});
}

// The per-packing companion must be the runs behind the table.
TEST(FlowCurveTable, RefusesCompanionsThatDoNotMatchTheTable) {
  const testing::SyntheticSweep s = testing::make_synthetic_sweep({}, 1);
  const Sweep sweep = make_sweep(s.table);
  const auto refusal_of = [&](std::vector<PackingRun> runs) -> std::string {
    try {
      make_packing_resampler(sweep, runs, "runs.csv");
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "companion accepted";
    return "";
  };
  EXPECT_NO_THROW(make_packing_resampler(sweep, s.runs, "runs.csv"));

  std::vector<PackingRun> stray = s.runs;
  stray[7].gamma_tilde *= 2;
  expect_contains(refusal_of(stray), {"runs.csv", "not a state point"});

  std::vector<PackingRun> missing = s.runs;
  missing.pop_back();
  expect_contains(refusal_of(missing), {"4 run(s)", "averages 5 packings"});

  std::vector<PackingRun> shifted = s.runs;
  *shifted[0].values[index(Quantity::sigma)] *= 1.5;
  expect_contains(refusal_of(shifted), {"average sigma", "same sweep"});

  std::vector<PackingRun> no_n1 = s.runs;
  for (PackingRun& r : no_n1) r.values[index(Quantity::N1)].reset();
  expect_contains(refusal_of(no_n1), {"'N1'", "flow-curve table only"});

  // Read from CSV, the companion needs its seed column.
  const std::string text = testing::runs_csv(s);
  EXPECT_THROW(read_packing_runs(CsvTable::parse(
                   std::regex_replace(text, std::regex("seed"), "sead"), "runs.csv")),
               InputError);
  EXPECT_EQ(read_packing_runs(CsvTable::parse(text, "runs.csv")).size(), s.runs.size());
}

TEST(FlowCurveTable, RefusesAPackingBootstrapOverASinglePacking) {
  testing::SyntheticTruth truth;
  truth.packings = 2;
  testing::SyntheticSweep s = testing::make_synthetic_sweep(truth, 1);
  for (PackingRun& r : s.runs) r.seed = 1;  // both runs of every point from one packing
  EXPECT_THROW(make_packing_resampler(make_sweep(s.table), s.runs, "runs.csv"), InputError);
}

// Structure from a companion table: merged into the state points, refused when
// it does not match them or when the table has structure columns already.
TEST(FlowCurveTable, MergesACompanionStructureTable) {
  const testing::SyntheticSweep with = testing::make_synthetic_sweep({}, 1);
  const std::string structure = testing::structure_csv(with);
  const testing::SyntheticSweep without = testing::without_structure(with);
  // Both tables as read from their files, with the precision the files carry.
  const FlowCurveTable bare = parse_table(testing::table_csv(without)),
                       full = parse_table(testing::table_csv(with));
  const auto merged = [&](const std::string& text) {
    FlowCurveTable table = bare;
    merge_structure(table, CsvTable::parse(text, "structure.csv"));
    return table;
  };
  const FlowCurveTable table = merged(structure);
  ASSERT_TRUE(table.present[index(Quantity::force)]);
  for (std::size_t i = 0; i < table.points.size(); ++i) {
    const Estimate &got = *table.points[i].values[index(Quantity::force)],
                   &want = *full.points[i].values[index(Quantity::force)];
    EXPECT_NEAR(got.value, want.value, 1e-9 * want.value);
    EXPECT_NEAR(got.error, want.error, 1e-6 * want.error);
  }
  // The packing bootstrap redraws f_m from its standard errors, the rest by packing.
  const Sweep sweep = make_sweep(table);
  const auto resampler = make_packing_resampler(
      sweep, read_packing_runs(CsvTable::parse(testing::runs_csv(without), "runs.csv")),
      "runs.csv");
  expect_contains(resampler->description(), {"packing bootstrap", "f_m: Gaussian redraws"});

  const auto refusal_of = [&](const std::string& text, FlowCurveTable target) -> std::string {
    try {
      merge_structure(target, CsvTable::parse(text, "structure.csv"));
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "structure accepted";
    return "";
  };
  expect_contains(refusal_of(structure, full), {"f_m columns already"});
  const std::string last_row = structure.substr(structure.rfind('\n', structure.size() - 2) + 1);
  expect_contains(refusal_of(structure.substr(0, structure.size() - last_row.size()), bare),
                  {"no row for phi = 0.9", "every state point"});
  expect_contains(refusal_of(structure + last_row, bare), {"already on line"});
  std::string stray = structure;
  stray.replace(stray.find("\n0.7,1.000000e-09"), 17, "\n0.7,2.000000e-09");
  expect_contains(refusal_of(stray, bare), {"structure.csv, line 3", "not a state point"});
  std::string pascals = structure;
  pascals.replace(pascals.find("f_m [E*R^2]"), 11, "f_m [N]");
  expect_contains(refusal_of(pascals, bare), {"'f_m [N]'", "expected 'E*R^2'"});
}

// The columns `micro sweep` writes (micro/results/flow_curve_table.cpp): the
// documented ones in its order, with the elastic/viscous parts, pressure, Z,
// converged, and the structure columns r_m (ignored) and f_m (the force law).
TEST(FlowCurveTable, ReadsTheTableMicroSweepWrites) {
  const testing::SyntheticSweep s = testing::make_synthetic_sweep({}, 3);
  std::string text =
      "# softglass micro 0.1.0, written 2026-11-21T09:02:15Z\nphi [1],gamma_tilde [1],packings [1]";
  for (const char* q : {"sigma", "N1", "N2"})
    for (const char* part : {"", "_elastic", "_viscous"})
      text += fmt::format(",{0}{1} [E*],{0}{1}_se [E*]", q, part);
  text +=
      ",pressure [E*],pressure_se [E*],Z [1],G0 [E*],G0_se [E*],converged [1],r_m [R],"
      "r_m_se [R],f_m [E*R^2],f_m_se [E*R^2]\n";
  for (const StatePoint& p : s.table.points) {
    text += fmt::format("{},{:.10g},{}", p.phi, p.gamma_tilde, p.packings);
    for (Quantity q : {Quantity::sigma, Quantity::N1, Quantity::N2}) {
      const Estimate& e = *p.values[index(q)];
      // The elastic part carries nearly all of the stress (σ^e ≥ 100 σ^v).
      text += fmt::format(",{:.10g},{:.6g},{:.10g},{:.6g},{:.10g},{:.6g}", e.value, e.error,
                          0.99 * e.value, e.error, 0.01 * e.value, 0.01 * e.error);
    }
    const Estimate& f = *p.values[index(Quantity::force)];
    text += fmt::format(",0.05,0.001,8.1,{:.10g},{:.6g},{},1.76,0.008,{:.10g},{:.6g}\n",
                        p.modulus.value, p.modulus.error, p.packings, f.value, f.error);
  }
  const FlowCurveTable table = parse_table(text);
  EXPECT_EQ(table.points.size(), s.table.points.size());
  for (Quantity q : kAllQuantities) EXPECT_TRUE(table.present[index(q)]) << column_name(q);
  EXPECT_NEAR(table.points[7].values[index(Quantity::force)]->value,
              s.table.points[7].values[index(Quantity::force)]->value,
              1e-9 * s.table.points[7].values[index(Quantity::force)]->value);
  EXPECT_EQ(make_sweep(table).groups.size(), 5u);
  EXPECT_EQ(table.points[0].converged, 5u);
  std::string too_many = text;
  too_many.replace(too_many.find(",5,1.76,"), 8, ",6,1.76,");
  expect_contains(refusal(too_many), {"'converged [1]'", "at most packings = 5"});
}

}  // namespace
}  // namespace softglass::bridge
