#include "common/input_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>
#include <system_error>

#include "common/errors.h"

namespace softglass {

namespace {

void append_utf8(std::string& out, char32_t c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

// UTF-16 (after its byte-order mark) to UTF-8; surrogate pairs joined, a lone
// surrogate becomes U+FFFD as Unicode prescribes.
std::string utf16_to_utf8(std::string_view bytes, bool little_endian, const std::string& where) {
  if (bytes.size() % 2 != 0)
    throw InputError(where + ": UTF-16 text with an odd number of bytes (a truncated file?)");
  const auto unit = [&](std::size_t k) {
    const auto lo = static_cast<unsigned char>(bytes[k + (little_endian ? 0 : 1)]);
    const auto hi = static_cast<unsigned char>(bytes[k + (little_endian ? 1 : 0)]);
    return static_cast<char32_t>(hi << 8 | lo);
  };
  std::string out;
  out.reserve(bytes.size() / 2);
  for (std::size_t k = 0; k < bytes.size(); k += 2) {
    char32_t c = unit(k);
    if (c >= 0xD800 && c < 0xDC00 && k + 2 < bytes.size()) {
      const char32_t low = unit(k + 2);
      if (low >= 0xDC00 && low < 0xE000) {
        c = 0x10000 + ((c - 0xD800) << 10) + (low - 0xDC00);
        k += 2;
      }
    }
    if (c >= 0xD800 && c < 0xE000) c = 0xFFFD;
    append_utf8(out, c);
  }
  return out;
}

// The length of the UTF-8 sequence starting at `k`, or 0 if it is not one
// (overlong forms, surrogates and values above U+10FFFF included).
std::size_t utf8_sequence(std::string_view s, std::size_t k) {
  const auto b = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
  const unsigned char lead = b(k);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  char32_t c = 0;
  if (lead >= 0xC2 && lead < 0xE0) length = 2, c = lead & 0x1F;
  else if (lead >= 0xE0 && lead < 0xF0) length = 3, c = lead & 0x0F;
  else if (lead >= 0xF0 && lead < 0xF5) length = 4, c = lead & 0x07;
  else return 0;
  if (k + length > s.size()) return 0;
  for (std::size_t i = 1; i < length; ++i) {
    if ((b(k + i) & 0xC0) != 0x80) return 0;
    c = c << 6 | (b(k + i) & 0x3F);
  }
  const bool overlong = (length == 3 && c < 0x800) || (length == 4 && c < 0x10000);
  if (overlong || (c >= 0xD800 && c < 0xE000) || c > 0x10FFFF) return 0;
  return length;
}

bool valid_utf8(std::string_view s) {
  for (std::size_t k = 0; k < s.size();) {
    const std::size_t n = utf8_sequence(s, k);
    if (n == 0) return false;
    k += n;
  }
  return true;
}

// Windows-1252: Latin-1 but for 0x80–0x9F, where it has printable characters
// (€, quotes, dashes); its five unassigned bytes become U+FFFD.
std::string windows1252_to_utf8(std::string_view s) {
  static constexpr std::array<char32_t, 32> kHigh = {
      0x20AC, 0xFFFD, 0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
      0x2039, 0x0152, 0xFFFD, 0x017D, 0xFFFD, 0xFFFD, 0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
      0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0xFFFD, 0x017E, 0x0178};
  std::string out;
  out.reserve(s.size() + s.size() / 8);
  for (const char ch : s) {
    const auto byte = static_cast<unsigned char>(ch);
    append_utf8(out, byte >= 0x80 && byte < 0xA0 ? kHigh[byte - 0x80] : char32_t{byte});
  }
  return out;
}

// Text with NUL bytes at every other position is UTF-16 that lost (or never
// had) its byte-order mark; other NUL bytes mean a binary file.
std::string nul_diagnosis(std::string_view bytes, std::size_t first_nul) {
  std::size_t even = 0, odd = 0;
  const std::size_t n = std::min<std::size_t>(bytes.size(), 4096);
  for (std::size_t k = 0; k < n; ++k)
    if (bytes[k] == '\0') ++(k % 2 == 0 ? even : odd);
  if (odd > n / 4 && even == 0)
    return "is UTF-16 (little-endian) text without a byte-order mark; save it as UTF-8, or as "
           "UTF-16 with a byte-order mark";
  if (even > n / 4 && odd == 0)
    return "is UTF-16 (big-endian) text without a byte-order mark; save it as UTF-8, or as "
           "UTF-16 with a byte-order mark";
  return fmt::format("is not a text file (a NUL byte at byte {})", first_nul + 1);
}

std::string byte_count(std::uintmax_t bytes) {
  if (bytes < (1u << 20)) return fmt::format("{} bytes", bytes);
  return fmt::format("{:.1f} MB", static_cast<double>(bytes) / (1u << 20));
}

void check_line_lengths(std::string_view text, std::size_t max_line, const std::string& where) {
  std::size_t number = 1, start = 0;
  for (std::size_t k = 0; k <= text.size(); ++k) {
    if (k < text.size() && text[k] != '\n') continue;
    if (k - start > max_line) {
      throw InputError(fmt::format(
          "{}: line {} is {} characters long, more than the {} a line may have here", where,
          number, k - start, max_line));
    }
    ++number;
    start = k + 1;
  }
}

}  // namespace

std::string binary_kind(std::string_view head) {
  struct Signature {
    std::string_view bytes, kind;
  };
  static constexpr Signature kSignatures[] = {
      {"\x89HDF\r\n\x1a\n", "an HDF5 file (a micro result?)"},
      {"PK\x03\x04", "a zip archive (an .xlsx or .ods workbook? export the sheet as CSV)"},
      {"\xD0\xCF\x11\xE0\xA1\xB1\x1A\xE1", "an old Office document (an .xls workbook? export the "
                                           "sheet as CSV)"},
      {"\x1f\x8b", "a gzip-compressed file (decompress it first)"},
      {"\x89PNG\r\n\x1a\n", "a PNG image"},
      {"%PDF", "a PDF document"},
      {"\x7f" "ELF", "a program (an ELF executable)"},
  };
  for (const Signature& s : kSignatures)
    if (head.starts_with(s.bytes)) return std::string(s.kind);
  return "";
}

std::string read_input_text(const std::filesystem::path& file, const std::string& kind,
                            const InputLimits& limits) {
  const std::string where = fmt::format("{} '{}'", kind, file.string());
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  if (!std::filesystem::exists(status)) throw InputError(where + " does not exist");
  if (std::filesystem::is_directory(status)) throw InputError(where + " is a directory, not a file");
  if (!std::filesystem::is_regular_file(status)) {
    throw InputError(where + " is not a regular file (a device, pipe or socket); name a file");
  }
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (!error && size > limits.max_bytes) {
    throw InputError(fmt::format("{} is {}, more than the {} a file of this kind may have", where,
                                 byte_count(size), byte_count(limits.max_bytes)));
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(where + " cannot be read (permissions?)");
  std::string bytes;
  bytes.resize(static_cast<std::size_t>(std::min(size, limits.max_bytes)) + 1);
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (in.bad()) throw InputError(where + " cannot be read");
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  if (bytes.size() > limits.max_bytes) throw InputError(where + " grew beyond its size cap while read");

  if (const std::string binary = binary_kind(bytes); !binary.empty())
    throw InputError(fmt::format("{} is {}, not a text file", where, binary));
  using namespace std::string_view_literals;
  const std::string_view view = bytes;
  std::string text;
  if (view.starts_with("\xFF\xFE\0\0"sv) || view.starts_with("\0\0\xFE\xFF"sv)) {
    throw InputError(where + " is UTF-32 text; save it as UTF-8 (or UTF-16)");
  } else if (view.starts_with("\xFF\xFE"sv) || view.starts_with("\xFE\xFF"sv)) {
    text = utf16_to_utf8(view.substr(2), view[0] == '\xFF', where);
  } else if (const std::size_t nul = view.find('\0'); nul != std::string_view::npos) {
    throw InputError(fmt::format("{} {}", where, nul_diagnosis(view, nul)));
  } else {
    const std::string_view body = view.starts_with("\xEF\xBB\xBF"sv) ? view.substr(3) : view;
    text = valid_utf8(body) ? std::string(body) : windows1252_to_utf8(body);
  }
  if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);  // a mark inside the UTF-16 too
  check_line_lengths(text, limits.max_line, where);
  return text;
}

}  // namespace softglass
