// Deterministic mutations of valid inputs, shared by every fuzz test.
//
// A fuzz test starts from a valid seed input (a file of cases/, or one the
// project's own writer made) and lets a Mutator damage it the way files get
// damaged or mistyped: flipped bytes, cut-off files, lost or repeated lines,
// numbers replaced by nan, inf, -1, 0, 1e308 or nothing, stray tokens, unknown
// entries. Each iteration gets a Mutator seeded from a fixed seed and its own
// index, so a failure reported for "iteration 137" replays alone and the same
// on every machine (the engine below is std::mt19937_64, whose output the
// standard fixes; distributions are not used because theirs is not fixed).
#pragma once

#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace softglass::testing::fuzz {

/// Mutations per reader: `budget` (small enough for CI), or the value of the
/// environment variable SOFTGLASS_FUZZ_ITERATIONS for longer local runs.
inline std::size_t iterations(std::size_t budget) {
  const char* value = std::getenv("SOFTGLASS_FUZZ_ITERATIONS");
  if (value == nullptr || *value == '\0') return budget;
  return static_cast<std::size_t>(std::strtoull(value, nullptr, 10));
}

/// Values that break readers: not numbers, not finite, out of every range,
/// denormal, negative, zero, empty, overflowing an integer.
inline const std::vector<std::string>& hostile_numbers() {
  static const std::vector<std::string> values = {"nan",
                                                  "-nan",
                                                  "inf",
                                                  "-inf",
                                                  "NaN",
                                                  "Infinity",
                                                  "-1",
                                                  "0",
                                                  "-0",
                                                  "1e308",
                                                  "-1e308",
                                                  "1e999",
                                                  "1e-320",
                                                  "4.9e-324",
                                                  "",
                                                  " ",
                                                  "abc",
                                                  "1,5",
                                                  "1..2",
                                                  "0x1p3",
                                                  "+",
                                                  "-",
                                                  "99999999999999999999",
                                                  "-99999999999999999999",
                                                  "2147483648",
                                                  "4294967296",
                                                  "1e18"};
  return values;
}

/// Lines a file should not hold: unknown entries, unbalanced sections, stray
/// quotes, includes of nothing, rows of the wrong width.
inline const std::vector<std::string>& hostile_lines() {
  static const std::vector<std::string> lines = {"set no such entry = 1",
                                                 "subsection no such subsection",
                                                 "end",
                                                 "set = 3",
                                                 "set",
                                                 "include /nonexistent/softglass-fuzz.prm",
                                                 "\"unterminated, quote",
                                                 "# a comment",
                                                 ",,,,,,,,,,,,,,,,",
                                                 "1,2,3,4,5,6,7,8,9,10,11,12,13,14,15",
                                                 "nan,nan,nan,nan",
                                                 "\xEF\xBB\xBF",
                                                 "\t\r",
                                                 std::string("nul\0byte", 8)};
  return lines;
}

class Mutator {
 public:
  Mutator(std::uint64_t seed, std::uint64_t iteration)
      : rng_(seed * 0x9E3779B97F4A7C15ull + iteration) {}

  /// A number in [0, n), n > 0.
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(rng_() % n); }
  template <class T>
  const T& pick(const std::vector<T>& items) {
    return items[below(items.size())];
  }

  /// `text` with one to three edits of a text file.
  std::string mutate_text(std::string text) {
    const std::size_t edits = 1 + below(3);
    for (std::size_t k = 0; k < edits; ++k) text = edit_text(std::move(text));
    return text;
  }

  /// `bytes` of a binary file cut short or with some bytes overwritten.
  std::string mutate_bytes(std::string bytes) {
    if (bytes.empty()) return bytes;
    if (below(3) == 0) {
      log("truncated to ", std::to_string(bytes.size()), " -> ");
      bytes.resize(below(bytes.size()));
      log(std::to_string(bytes.size()), " bytes; ");
      return bytes;
    }
    const std::size_t count = 1 + below(16);
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t at = below(bytes.size());
      bytes[at] = static_cast<char>(rng_());
      log("byte ", std::to_string(at), " overwritten; ");
    }
    return bytes;
  }

  /// What was done, for failure messages.
  const std::string& description() const { return log_; }
  // Pieces appended one by one: GCC 12 warns falsely (-Wrestrict) about
  // chains of std::string operator+ at -O3.
  template <class... Parts>
  void log(const Parts&... parts) {
    (log_.append(std::string_view(parts)), ...);
  }

 private:
  std::string edit_text(std::string text) {
    switch (below(9)) {
      case 0:
        return flip_bit(std::move(text));
      case 1:
        log("truncated; ");
        return text.substr(0, text.empty() ? 0 : below(text.size()));
      case 2:
        return edit_line(std::move(text), Line::erase);
      case 3:
        return edit_line(std::move(text), Line::duplicate);
      case 4:
        return edit_line(std::move(text), Line::insert);
      case 5:
        return edit_line(std::move(text), Line::swap);
      case 6:
        return replace_word(std::move(text));
      default:  // the most telling edit gets the most weight
        return replace_number(std::move(text));
    }
  }

  std::string flip_bit(std::string text) {
    if (text.empty()) return text;
    const std::size_t at = below(text.size());
    text[at] = static_cast<char>(text[at] ^ (1 << below(8)));
    log("bit flipped at byte ", std::to_string(at), "; ");
    return text;
  }

  enum class Line { erase, duplicate, insert, swap };

  std::string edit_line(const std::string& text, Line edit) {
    std::vector<std::string> lines;
    for (std::size_t begin = 0; begin < text.size();) {
      const std::size_t end = text.find('\n', begin);
      const std::size_t stop = end == std::string::npos ? text.size() : end + 1;
      lines.push_back(text.substr(begin, stop - begin));
      begin = stop;
    }
    if (lines.empty()) lines.emplace_back();
    const std::size_t at = below(lines.size());
    switch (edit) {
      case Line::erase:
        log("line ", std::to_string(at + 1), " deleted; ");
        lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(at));
        break;
      case Line::duplicate:
        log("line ", std::to_string(at + 1), " duplicated; ");
        lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(at), lines[at]);
        break;
      case Line::insert: {
        const std::string& line = pick(hostile_lines());
        log("line inserted before line ", std::to_string(at + 1), "; ");
        lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(at), line + "\n");
        break;
      }
      case Line::swap: {
        const std::size_t other = below(lines.size());
        log("lines ", std::to_string(at + 1), " and ", std::to_string(other + 1), " swapped; ");
        std::swap(lines[at], lines[other]);
        break;
      }
    }
    std::string out;
    for (const std::string& line : lines) out += line;
    return out;
  }

  // Spans [begin, end) of the tokens `is_start`/`is_part` describe, each
  // starting where the previous character cannot continue a token.
  template <class Start, class Part>
  static std::vector<std::pair<std::size_t, std::size_t>> tokens(const std::string& text,
                                                                 Start is_start, Part is_part) {
    std::vector<std::pair<std::size_t, std::size_t>> spans;
    for (std::size_t i = 0; i < text.size();) {
      const bool fresh = i == 0 || !is_part(text, i - 1);
      if (!fresh || !is_start(text, i)) {
        ++i;
        continue;
      }
      std::size_t j = i + 1;
      while (j < text.size() && is_part(text, j)) ++j;
      spans.emplace_back(i, j);
      i = j;
    }
    return spans;
  }

  static bool digit(const std::string& s, std::size_t i) {
    return std::isdigit(static_cast<unsigned char>(s[i])) != 0;
  }

  std::string replace_number(std::string text) {
    // A number: an optional sign, then digits, points and exponents.
    const auto start = [](const std::string& s, std::size_t i) {
      const bool sign = (s[i] == '-' || s[i] == '+') && i + 1 < s.size() && digit(s, i + 1);
      return digit(s, i) || sign;
    };
    const auto part = [](const std::string& s, std::size_t i) {
      const char c = s[i];
      const bool exponent_sign =
          (c == '-' || c == '+') && i > 0 && (s[i - 1] == 'e' || s[i - 1] == 'E');
      return digit(s, i) || c == '.' || c == 'e' || c == 'E' || exponent_sign ||
             std::isalpha(static_cast<unsigned char>(c)) || c == '_';
    };
    const auto spans = tokens(text, start, part);
    if (spans.empty()) return replace_word(std::move(text));
    const auto [begin, end] = pick(spans);
    const std::string& value = pick(hostile_numbers());
    log("'", text.substr(begin, end - begin), "' at byte ", std::to_string(begin), " -> '", value,
        "'; ");
    return text.replace(begin, end - begin, value);
  }

  std::string replace_word(std::string text) {
    const auto letter = [](const std::string& s, std::size_t i) {
      return std::isalpha(static_cast<unsigned char>(s[i])) != 0 || s[i] == '_';
    };
    const auto spans = tokens(text, letter, letter);
    if (spans.empty()) return flip_bit(std::move(text));
    static const std::vector<std::string> garbage = {
        "",  "x", "subsection", "end",  "set",  "include", "true", "\"",       ",",     "=",
        "#", "[", "]",          "[E*]", "[Pa]", "[1/s]",   "nan",  "\xC3\xA9", "sigma", "phi"};
    const auto [begin, end] = pick(spans);
    const std::string& token = pick(garbage);
    log("'", text.substr(begin, end - begin), "' at byte ", std::to_string(begin), " -> '", token,
        "'; ");
    return text.replace(begin, end - begin, token);
  }

  std::mt19937_64 rng_;
  std::string log_;
};

}  // namespace softglass::testing::fuzz
