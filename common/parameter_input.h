// Reading parameter files with deal.II's ParameterHandler, the same way in
// every tool (micro's parameter and sweep files, bridge's law files, macro's
// scene and material files): whatever goes wrong becomes one InputError whose
// message is deal.II's on one line (common/deal_ii_message.h). Entries must be
// declared; an entry that is not is an error, never skipped.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace dealii {
class ParameterHandler;
}

namespace softglass {

/// Parses `text` into `prm`; `source` names it in deal.II's messages
/// ("Line <3> of file <source>").
void parse_parameter_text(dealii::ParameterHandler& prm, const std::string& text,
                          const std::string& source);

/// An entry a file sets: its subsections from the top, its name, its value
/// (trimmed, comment dropped), and where.
struct SetEntry {
  std::vector<std::string> subsections;
  std::string name;
  std::string value;
  std::string file;
  std::size_t line = 0;

  /// "subsection/…/name".
  std::string key() const;
};

/// Of `entries` (in the order they were set), the ones in effect: the last
/// `set` of each entry, in order.
std::vector<SetEntry> in_effect(std::vector<SetEntry> entries);

/// The entries `text` sets, in order (its `include` lines are not followed);
/// `file` names it in the entries.
std::vector<SetEntry> entries_set_in(const std::string& text, const std::string& file);

/// Parses the parameter file `file`. It must be a readable file (a directory
/// is named as one); a UTF-8 byte-order mark before its first line is skipped,
/// as editors on Windows write one; `include <file>` lines are replaced by that
/// file (relative to the including one), at most 8 deep, so that a file that
/// includes itself is an error rather than an endless recursion. An entry set
/// twice in one file is an error (deal.II would keep the last in silence); a
/// file may set again an entry of a file it includes, the later `set` winning.
/// Messages begin "<kind> '<file>'" (kind: "parameter file", "law file"...)
/// and name the file and line the user wrote, through includes. Returns the
/// entries the file sets, in order (for checks of what a command uses).
std::vector<SetEntry> parse_parameter_file(dealii::ParameterHandler& prm, const std::filesystem::path& file,
                          const std::string& kind);

}  // namespace softglass
