#include "common/parameter_input.h"

#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>

#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <utility>
#include <vector>

#include "common/deal_ii_message.h"
#include "common/errors.h"

namespace softglass {

namespace {

constexpr int kMaxIncludeDepth = 8;

// The text with its includes expanded, and where each of its lines came from
// (file and line), so that messages about the expanded text name the line the
// user wrote.
struct ExpandedText {
  std::string text;
  std::vector<std::pair<std::string, std::size_t>> origin;
};

// `file`'s text after the checks a user's message needs: it exists, it is not
// a directory, it can be read; without a leading UTF-8 byte-order mark.
std::string read_text(const std::filesystem::path& file, const std::string& kind) {
  if (std::filesystem::is_directory(file))
    throw InputError(fmt::format("{} '{}' is a directory, not a file", kind, file.string()));
  if (!std::filesystem::exists(file))
    throw InputError(fmt::format("{} '{}' does not exist", kind, file.string()));
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in.good() && !in.eof())
    throw InputError(fmt::format("{} '{}' cannot be read", kind, file.string()));
  std::string s = text.str();
  if (s.starts_with("\xEF\xBB\xBF")) s.erase(0, 3);
  return s;
}

// The statements of a parameter text, line by line: follows the subsections
// and continuation lines, and returns each `set` as an entry.
class Statements {
 public:
  std::optional<SetEntry> read(std::string line, const std::string& file, std::size_t number) {
    const auto last = line.find_last_not_of(" \t\r");
    const bool statement = !continued_;
    continued_ = last != std::string::npos && line[last] == '\\';
    if (!statement) return std::nullopt;
    line = line.substr(0, line.find('#'));
    static const std::regex subsection(R"(^\s*subsection\s+(.*\S)\s*$)");
    static const std::regex end(R"(^\s*end\s*$)");
    static const std::regex set(R"(^\s*set\s+([^=]*\S)\s*=\s*(.*?)\s*$)");
    std::smatch match;
    if (std::regex_match(line, match, subsection)) {
      path_.push_back(match[1].str());
    } else if (std::regex_match(line, end)) {
      if (!path_.empty()) path_.pop_back();
    } else if (std::regex_match(line, match, set)) {
      return SetEntry{path_, match[1].str(), match[2].str(), file, number};
    }
    return std::nullopt;
  }

 private:
  std::vector<std::string> path_;
  bool continued_ = false;
};

// The entries of the expanded text, checked as they come: an entry set twice
// in one file is refused (deal.II keeps the last value in silence, and a
// second `set` in one file is a slip, an edited copy, more often than an
// intention). A file may set again what a file it includes set: that is how
// a shared base file is specialised.
class SetEntries {
 public:
  void check(const std::string& line, const std::string& file, std::size_t number,
             const std::string& kind) {
    std::optional<SetEntry> entry = statements_.read(line, file, number);
    if (!entry) return;
    const auto [it, fresh] = where_.try_emplace(entry->key(), file, number);
    if (!fresh && it->second.first == file) {
      throw InputError(fmt::format(
          "{} '{}', line {}: '{}' is set a second time in this file (first on line {}); set "
          "each entry once",
          kind, file, number, entry->key(), it->second.second));
    }
    it->second = {file, number};
    set_.push_back(std::move(*entry));
  }

  std::vector<SetEntry> entries() && { return std::move(set_); }

 private:
  Statements statements_;
  std::vector<SetEntry> set_;
  std::map<std::string, std::pair<std::string, std::size_t>> where_;
};

void expand(const std::filesystem::path& file, const std::string& kind, int depth,
            ExpandedText& out, SetEntries& entries) {
  if (depth > kMaxIncludeDepth) {
    throw InputError(fmt::format("{}: includes nest deeper than {} at '{}' (does a file include "
                                 "itself?)",
                                 kind, kMaxIncludeDepth, file.string()));
  }
  static const std::regex include_line(R"(^\s*include\s+(\S+)\s*$)", std::regex::icase);
  std::istringstream in(read_text(file, depth == 0 ? kind : "included file"));
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    std::smatch match;
    if (std::regex_match(line, match, include_line)) {
      std::filesystem::path included = match[1].str();
      if (included.is_relative()) included = file.parent_path() / included;
      expand(included, kind, depth + 1, out, entries);
    } else {
      entries.check(line, file.string(), number, kind);
      out.text += line + "\n";
      out.origin.emplace_back(file.string(), number);
    }
  }
}

// deal.II's "Line <N> of file <F>" (N counted in the expanded text) → the
// file and line the user wrote. For an unknown subsection deal.II 9.4 leaves
// the '>' out ("Line <8> of file <a.prm: There is no such subsection").
std::string locate(const std::string& message, const ExpandedText& expanded) {
  static const std::regex place(R"(Line <(\d+)> of file <[^>:]*>?)");
  std::smatch match;
  if (!std::regex_search(message, match, place)) return message;
  const std::size_t line = std::stoul(match[1].str());
  if (line == 0 || line > expanded.origin.size()) return message;
  const auto& [file, number] = expanded.origin[line - 1];
  return match.prefix().str() + fmt::format("line {} of file '{}'", number, file) +
         match.suffix().str();
}

}  // namespace

std::string SetEntry::key() const {
  std::string key;
  for (const std::string& s : subsections) key += s + "/";
  return key + name;
}

std::vector<SetEntry> in_effect(std::vector<SetEntry> entries) {
  std::map<std::string, std::size_t> last;
  for (std::size_t k = 0; k < entries.size(); ++k) last[entries[k].key()] = k;
  std::vector<SetEntry> kept;
  for (std::size_t k = 0; k < entries.size(); ++k)
    if (last[entries[k].key()] == k) kept.push_back(std::move(entries[k]));
  return kept;
}

std::vector<SetEntry> entries_set_in(const std::string& text, const std::string& file) {
  Statements statements;
  std::vector<SetEntry> entries;
  std::istringstream in(text);
  std::size_t number = 0;
  for (std::string line; std::getline(in, line);)
    if (auto entry = statements.read(line, file, ++number)) entries.push_back(std::move(*entry));
  return entries;
}

void parse_parameter_text(dealii::ParameterHandler& prm, const std::string& text,
                          const std::string& source) {
  std::istringstream input(text);
  try {
    prm.parse_input(input, source, "", false);
  } catch (const std::exception& error) {
    throw InputError(deal_ii_message(error.what()));
  }
}

std::vector<SetEntry> parse_parameter_file(dealii::ParameterHandler& prm,
                                           const std::filesystem::path& file,
                                           const std::string& kind) {
  ExpandedText expanded;
  SetEntries entries;
  expand(file, kind, 0, expanded, entries);
  try {
    parse_parameter_text(prm, expanded.text, file.string());
  } catch (const InputError& error) {
    throw InputError(fmt::format("{} '{}': {}", kind, file.string(), locate(error.what(), expanded)));
  }
  return std::move(entries).entries();
}

}  // namespace softglass
