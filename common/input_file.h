// The one gate every text file a softglass tool reads passes through before it
// is parsed: parameter and scene files and what they include, law files,
// tables, measured curves, contact-law tables, meshes.
//
// A user can name anything as an input — a device (/dev/zero), a folder, a
// workbook, a result file of another tool, a file from an instrument PC in
// another encoding. Each is recognised here and refused, or converted, with a
// message that says what the file is, before a byte of it reaches a parser:
//   - only regular files are read (a device or pipe could be endless);
//   - a size cap per kind of file, and a cap on the length of one line, so that
//     no parser is handed more than it was written for;
//   - binary files are named by their signature (HDF5, zip/xlsx, gzip, PNG,
//     PDF) or by the NUL byte that shows them binary;
//   - encodings are detected and named: UTF-8 (a byte-order mark is dropped),
//     UTF-16 with a byte-order mark (as Windows instrument software exports) is
//     converted to UTF-8, and text that is not valid UTF-8 is read as
//     Windows-1252 (the 8-bit code page of European instrument PCs, a superset
//     of Latin-1 in print) and converted — its units (°C, µm) keep their meaning.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace softglass {

struct InputLimits {
  std::uintmax_t max_bytes = 64u << 20;  // tables of a large sweep stay far below
  std::size_t max_line = 1u << 16;       // characters of one line
};

/// Limits for hand-written parameter, scene, material and law files.
inline constexpr InputLimits kParameterFileLimits{4u << 20, 1u << 16};

/// The text of `file` as UTF-8, after the checks above; InputError beginning
/// "<kind> '<file>'" and naming what the file is otherwise.
std::string read_input_text(const std::filesystem::path& file, const std::string& kind,
                            const InputLimits& limits = {});

/// What the first bytes of `head` show a file to be ("an HDF5 file", "a zip
/// archive (an .xlsx workbook?)", ...), or "" for none of the binary kinds.
std::string binary_kind(std::string_view head);

}  // namespace softglass
