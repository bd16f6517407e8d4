// The property every fuzz test checks: a reader given a damaged input either
// returns values that are finite and valid, or refuses the input with
// softglass::InputError. Any other exception (std::out_of_range,
// std::invalid_argument, a deal.II or HDF5 error that was not translated) is a
// bug, reported with the input that caused it; a crash ends the test program,
// and SOFTGLASS_FUZZ_VERBOSE=1 then shows the last input tried. fuzz_text runs
// such a campaign over mutations of text seeds.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <string>
#include <typeinfo>
#include <vector>

#include "common/errors.h"
#include "mutation.h"

namespace softglass::testing::fuzz {

/// What one mutated input was, for messages: the iteration, the mutations and
/// (for text) the start of the text itself.
inline std::string describe(std::size_t iteration, const std::string& mutations,
                            const std::string& text = {}) {
  constexpr std::size_t kShown = 1500;
  std::string out = "iteration " + std::to_string(iteration) + ": " + mutations;
  if (!text.empty()) {
    out += "\n---- input" + std::string(text.size() > kShown ? " (start)" : "") + "\n" +
           text.substr(0, kShown) + "\n----";
  }
  if (std::getenv("SOFTGLASS_FUZZ_VERBOSE") != nullptr) std::fprintf(stderr, "%s\n", out.c_str());
  return out;
}

/// What a campaign tried: inputs, and how many of them were refused. After
/// every test that tried any, one line on stdout,
///     fuzz tally: <Suite.Test> tried N refused R defects D
/// (D: the test's failed checks, at most 5: see enough_failures), which
/// scripts/reliability_table.sh gathers into the table of docs/validation.md.
struct Tally {
  std::size_t tried = 0, refused = 0;
};
inline Tally& tally() {
  static Tally t;
  return t;
}
inline void count_input(bool read) {
  ++tally().tried;
  if (!read) ++tally().refused;
}

class TallyPrinter : public ::testing::EmptyTestEventListener {
  void OnTestStart(const ::testing::TestInfo&) override { tally() = {}; }
  void OnTestEnd(const ::testing::TestInfo& test) override {
    if (tally().tried == 0) return;
    int defects = 0;
    for (int k = 0; k < test.result()->total_part_count(); ++k)
      defects += test.result()->GetTestPartResult(k).failed() ? 1 : 0;
    std::printf("fuzz tally: %s.%s tried %zu refused %zu defects %d\n", test.test_suite_name(),
                test.name(), tally().tried, tally().refused, defects);
    std::fflush(stdout);  // kept if a later campaign hangs and is killed
  }
};
// Installed once per test program, before main() runs the tests.
inline const bool kTallyPrinterInstalled = [] {
  ::testing::UnitTest::GetInstance()->listeners().Append(new TallyPrinter);
  return true;
}();

/// A campaign stops after this many failures: one bug tends to fail many
/// mutations alike, and the first few say all.
inline bool enough_failures() {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  return test != nullptr && test->result()->total_part_count() >= 5;
}

/// Calls `read()`. Returns true if it returned (the caller then checks the
/// values), false if it threw InputError; any other exception fails the test.
template <class Read>
bool accepted(Read&& read, const std::string& input) {
  try {
    read();
    count_input(true);
    return true;
  } catch (const InputError& e) {
    if (std::getenv("SOFTGLASS_FUZZ_VERBOSE") != nullptr)
      std::fprintf(stderr, "refused: %s\n", e.what());
    count_input(false);
    return false;
  } catch (const std::exception& e) {
    count_input(false);
    ADD_FAILURE() << "threw " << typeid(e).name() << " instead of InputError: " << e.what() << "\n"
                  << input;
  } catch (...) {
    count_input(false);
    ADD_FAILURE() << "threw something that is not a std::exception\n" << input;
  }
  return false;
}

/// accepted() for a reader that returns what it read: `check(value)` on
/// success. Returns whether the reader accepted the input.
template <class Read, class Check>
bool read_and_check(Read&& read, Check&& check, const std::string& input) {
  std::optional<decltype(read())> value;  // what readers return need not be default-constructible
  if (!accepted([&] { value.emplace(read()); }, input)) return false;
  check(*value);
  return true;
}

/// Expects `value` finite: a validated field never holds NaN or inf.
inline void expect_finite(double value, const std::string& field, const std::string& input) {
  EXPECT_TRUE(std::isfinite(value)) << field << " = " << value << " accepted\n" << input;
}

template <class Range>
void expect_all_finite(const Range& values, const std::string& field, const std::string& input) {
  for (const double v : values) {
    if (!std::isfinite(v)) {
      ADD_FAILURE() << field << " holds " << v << ", accepted\n" << input;
      return;
    }
  }
}

/// Checks that every seed is read (else the campaign would test nothing), then
/// gives `read(text, input)` `budget` mutations of the seeds in turn. `read`
/// returns whether the reader accepted the text (see accepted()); `input`
/// describes the text for its messages.
template <class Read>
void fuzz_text(const std::vector<std::string>& seeds, std::uint64_t seed, std::size_t budget,
               Read read) {
  for (std::size_t k = 0; k < seeds.size(); ++k)
    ASSERT_TRUE(read(seeds[k], describe(k, "seed, unchanged", seeds[k]))) << "seed " << k;
  const std::size_t count = iterations(budget);
  for (std::size_t i = 0; i < count && !enough_failures(); ++i) {
    Mutator mutator(seed, i);
    const std::string text = mutator.mutate_text(seeds[i % seeds.size()]);
    read(text, describe(i, mutator.description(), text));
  }
}

}  // namespace softglass::testing::fuzz
