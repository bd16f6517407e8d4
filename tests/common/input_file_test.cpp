// The input gate: every kind of file a user might name is recognised and
// refused, or converted, before a parser sees it — devices, folders, binary
// files named by their signature, sizes and line lengths beyond the caps, and
// the encodings instrument software writes.
#include <gtest/gtest.h>

#include <string>

#include "common/errors.h"
#include "common/input_file.h"
#include "tests/common/test_files.h"
#include "tests/common/text_checks.h"

namespace softglass {
namespace {

using testing::expect_contains;

std::string refusal(const std::filesystem::path& file, const InputLimits& limits = {}) {
  try {
    read_input_text(file, "table", limits);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << file << " was accepted";
  return "";
}

TEST(InputFile, RefusesWhatIsNotARegularFile) {
  testing::TemporaryDirectory dir;
  expect_contains(refusal(dir / "absent.csv"), {"table '" + (dir / "absent.csv").string() + "' does not exist"});
  expect_contains(refusal(dir.path()), {"is a directory, not a file"});
  // /dev/zero is endless: it must be refused by kind, not read until memory runs out.
  expect_contains(refusal("/dev/zero"), {"is not a regular file (a device, pipe or socket)"});
}

TEST(InputFile, NamesBinaryFilesBySignature) {
  testing::TemporaryDirectory dir;
  const std::pair<std::string, std::string> kinds[] = {
      {std::string("\x89HDF\r\n\x1a\n\0\0", 10), "an HDF5 file"},
      {std::string("PK\x03\x04\x14\0", 6), "a zip archive (an .xlsx or .ods workbook?"},
      {"\x1f\x8b\x08", "gzip"},
      {"%PDF-1.7\n", "a PDF document"},
  };
  for (const auto& [bytes, kind] : kinds) {
    testing::write_text(dir / "f.csv", bytes);
    expect_contains(refusal(dir / "f.csv"), {kind});
  }
  testing::write_text(dir / "f.csv", std::string("a,b\n1,\0\n", 8));
  expect_contains(refusal(dir / "f.csv"), {"is not a text file (a NUL byte at byte 7)"});
}

TEST(InputFile, CapsTheSizeAndTheLineLength) {
  testing::TemporaryDirectory dir;
  testing::write_text(dir / "big.csv", std::string(2000, 'x'));
  expect_contains(refusal(dir / "big.csv", {1000, 100}), {"is 2000 bytes, more than the 1000 bytes"});
  testing::write_text(dir / "long.csv", "a\n" + std::string(101, 'x') + "\nb\n");
  expect_contains(refusal(dir / "long.csv", {1000, 100}),
                  {"line 2 is 101 characters long, more than the 100"});
  testing::write_text(dir / "fits.csv", "a\n" + std::string(100, 'x') + "\n");
  EXPECT_EQ(read_input_text(dir / "fits.csv", "table", {1000, 100}).size(), 103u);
}

TEST(InputFile, ConvertsUtf16AndWindows1252ToUtf8) {
  testing::TemporaryDirectory dir;
  // "T [°C];µ" in UTF-16 little- and big-endian with their byte-order marks.
  const std::u16string text = u"T [\u00B0C];\u00B5\r\n";
  std::string le = "\xFF\xFE", be = "\xFE\xFF";
  for (const char16_t c : text) {
    le += static_cast<char>(c & 0xFF), le += static_cast<char>(c >> 8);
    be += static_cast<char>(c >> 8), be += static_cast<char>(c & 0xFF);
  }
  const std::string utf8 = "T [\xC2\xB0" "C];\xC2\xB5\r\n";
  testing::write_text(dir / "le.csv", le);
  testing::write_text(dir / "be.csv", be);
  EXPECT_EQ(read_input_text(dir / "le.csv", "table"), utf8);
  EXPECT_EQ(read_input_text(dir / "be.csv", "table"), utf8);
  // The same in Windows-1252 (one byte each for ° and µ), and in UTF-8 with its mark.
  testing::write_text(dir / "cp.csv", "T [\xB0" "C];\xB5\r\n");
  EXPECT_EQ(read_input_text(dir / "cp.csv", "table"), utf8);
  testing::write_text(dir / "bom.csv", "\xEF\xBB\xBF" + utf8);
  EXPECT_EQ(read_input_text(dir / "bom.csv", "table"), utf8);
  // UTF-16 whose mark was lost is named as such rather than called binary.
  testing::write_text(dir / "nomark.csv", le.substr(2));
  expect_contains(refusal(dir / "nomark.csv"), {"UTF-16 (little-endian) text without a byte-order mark"});
  testing::write_text(dir / "u32.csv", std::string("\xFF\xFE\0\0a\0\0\0", 8));
  expect_contains(refusal(dir / "u32.csv"), {"is UTF-32 text"});
}

}  // namespace
}  // namespace softglass
