// Fuzzing the input gate (common/input_file.h) together with the readers behind
// it: mutated instrument exports saved in the encodings instrument PCs write —
// UTF-8 with and without a mark, UTF-16 of either byte order with its mark,
// Windows-1252, and the same damaged (a stray NUL, an odd UTF-16 byte count, a
// lost mark) — written to a real file and read through the gate, then as a
// table of measured curves. Accepted text is valid UTF-8 (the readers never
// see another encoding) and its curves hold finite values.
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "common/input_file.h"
#include "common/measured_curves.h"
#include "fuzz_check.h"
#include "tests/common/test_files.h"

namespace softglass {
namespace {

using namespace softglass::testing::fuzz;

const std::string kExport =
    "Stress [Pa],Shear rate [1/s],Temperature [\xC2\xB0" "C]\n"
    "260.59,1000.0,25\n20.0,1.0,25\n78.1,100.0,25\n33.6,10.0,25\n";
const std::string kComma =
    "Stress [Pa],Shear rate [1/s],Gap [\xC2\xB5m]\n260.59,1000.0,500\n20.0,1.0,500\n"
    "78.1,100.0,500\n33.6,10.0,500\n";

std::string utf16(const std::string& utf8, bool little_endian) {
  std::string out = little_endian ? "\xFF\xFE" : "\xFE\xFF";
  for (std::size_t k = 0; k < utf8.size(); ++k) {
    auto c = static_cast<unsigned char>(utf8[k]);
    char16_t unit = c;
    if (c >= 0xC0 && k + 1 < utf8.size()) {  // the two-byte forms the seeds hold
      unit = static_cast<char16_t>(((c & 0x1F) << 6) | (static_cast<unsigned char>(utf8[++k]) & 0x3F));
    }
    const char lo = static_cast<char>(unit & 0xFF), hi = static_cast<char>(unit >> 8);
    out += little_endian ? std::string{lo, hi} : std::string{hi, lo};
  }
  return out;
}

std::string windows1252(const std::string& utf8) {
  std::string out;
  for (std::size_t k = 0; k < utf8.size(); ++k) {
    const auto c = static_cast<unsigned char>(utf8[k]);
    if (c == 0xC2 && k + 1 < utf8.size()) out += utf8[++k];  // ° and µ: one byte each
    else out += utf8[k];
  }
  return out;
}

// The text as saved in one of the encodings (or damaged), chosen by `variant`.
std::string encoded(const std::string& text, std::size_t variant) {
  switch (variant % 8) {
    case 0: return text;
    case 1: return "\xEF\xBB\xBF" + text;
    case 2: return utf16(text, true);
    case 3: return utf16(text, false);
    case 4: return windows1252(text);
    case 5: return utf16(text, true).substr(2);         // the mark lost
    case 6: return utf16(text, true).substr(0, 2 * text.size() / 3 * 2 + 1);  // odd bytes
    default: return text.substr(0, text.size() / 2) + std::string(1, '\0') + text.substr(text.size() / 2);
  }
}

bool valid_utf8(const std::string& s) {
  for (std::size_t k = 0; k < s.size();) {
    const auto c = static_cast<unsigned char>(s[k]);
    const std::size_t n = c < 0x80 ? 1 : c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 ? 2 : 0;
    if (n == 0 || k + n > s.size()) return false;
    for (std::size_t i = 1; i < n; ++i)
      if ((static_cast<unsigned char>(s[k + i]) & 0xC0) != 0x80) return false;
    k += n;
  }
  return true;
}

TEST(InputFileFuzz, RefusesOrReadsEveryEncodingOfAMutatedExport) {
  testing::TemporaryDirectory dir;
  std::size_t variant = 0;
  fuzz_text({kExport, kComma}, 61, 1200, [&](const std::string& text, const std::string& input) {
    const std::string bytes = encoded(text, variant++);
    testing::write_text(dir / "export.csv", bytes);
    std::optional<std::string> read;
    if (!accepted([&] { read = read_input_text(dir / "export.csv", "measured data"); }, input))
      return false;
    EXPECT_TRUE(valid_utf8(*read)) << "the gate passed on text that is not UTF-8\n" << input;
    std::optional<CsvTable> csv;
    if (!accepted([&] { csv = CsvTable::parse(*read, "export.csv"); }, input)) return false;
    return read_and_check([&] { return read_measured_curves(*csv, {}); },
                          [&](const std::vector<MeasuredCurve>& curves) {
                            for (const MeasuredCurve& c : curves) {
                              expect_all_finite(c.shear_rate, "a shear rate", input);
                              expect_all_finite(c.stress, "a stress", input);
                            }
                          },
                          input);
  });
}

}  // namespace
}  // namespace softglass
