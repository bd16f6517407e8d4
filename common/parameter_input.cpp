#include "common/parameter_input.h"

#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>

#include <cctype>
#include <map>
#include <optional>
#include <string_view>
#include <sstream>
#include <utility>
#include <vector>

#include "common/deal_ii_message.h"
#include "common/errors.h"
#include "common/input_file.h"

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

constexpr std::string_view kBlank = " \t\r\f\v";

std::string_view trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(kBlank);
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(kBlank) - first + 1);
}

// `line` (trimmed) is `keyword` followed by blanks and a rest: the rest,
// trimmed; otherwise nothing. ASCII case is ignored when `any_case`.
std::optional<std::string_view> after_keyword(std::string_view line, std::string_view keyword,
                                              bool any_case = false) {
  if (line.size() <= keyword.size()) return std::nullopt;
  for (std::size_t k = 0; k < keyword.size(); ++k) {
    const char c = any_case ? static_cast<char>(std::tolower(static_cast<unsigned char>(line[k])))
                            : line[k];
    if (c != keyword[k]) return std::nullopt;
  }
  if (kBlank.find(line[keyword.size()]) == std::string_view::npos) return std::nullopt;
  return trimmed(line.substr(keyword.size()));
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
    const std::string_view text = trimmed(std::string_view(line).substr(0, line.find('#')));
    if (const auto subsection = after_keyword(text, "subsection")) {
      path_.emplace_back(*subsection);
    } else if (text == "end") {
      if (!path_.empty()) path_.pop_back();
    } else if (const auto assignment = after_keyword(text, "set")) {
      const auto equals = assignment->find('=');
      const std::string_view name = trimmed(assignment->substr(0, equals));
      if (equals != std::string_view::npos && !name.empty())
        return SetEntry{path_, std::string(name), std::string(trimmed(assignment->substr(equals + 1))),
                        file, number};
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
  std::istringstream in(
      read_input_text(file, depth == 0 ? kind : "included file", kParameterFileLimits));
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    const auto target = after_keyword(trimmed(line), "include", /*any_case=*/true);
    if (target && target->find_first_of(kBlank) == std::string_view::npos) {
      std::filesystem::path included{std::string(*target)};
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
  constexpr std::string_view kOpen = "Line <", kMiddle = "> of file <";
  const std::size_t start = message.find(kOpen);
  if (start == std::string::npos) return message;
  std::size_t k = start + kOpen.size();
  std::size_t line = 0;
  const std::size_t digits = k;
  for (; k < message.size() && std::isdigit(static_cast<unsigned char>(message[k])) && k - digits < 12;
       ++k)
    line = 10 * line + static_cast<std::size_t>(message[k] - '0');
  if (k == digits || message.compare(k, kMiddle.size(), kMiddle) != 0) return message;
  k = message.find_first_of(">:", k + kMiddle.size());
  if (k == std::string::npos) k = message.size();
  else if (message[k] == '>') ++k;
  if (line == 0 || line > expanded.origin.size()) return message;
  const auto& [file, number] = expanded.origin[line - 1];
  return message.substr(0, start) + fmt::format("line {} of file '{}'", number, file) +
         message.substr(k);
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
