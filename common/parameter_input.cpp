#include "common/parameter_input.h"

#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>

#include <fstream>
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

void expand(const std::filesystem::path& file, const std::string& kind, int depth,
            ExpandedText& out) {
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
      expand(included, kind, depth + 1, out);
    } else {
      out.text += line + "\n";
      out.origin.emplace_back(file.string(), number);
    }
  }
}

// deal.II's "Line <N> of file <F>" (N counted in the expanded text) → the
// file and line the user wrote.
std::string locate(const std::string& message, const ExpandedText& expanded) {
  static const std::regex place(R"(Line <(\d+)> of file <[^>]*>)");
  std::smatch match;
  if (!std::regex_search(message, match, place)) return message;
  const std::size_t line = std::stoul(match[1].str());
  if (line == 0 || line > expanded.origin.size()) return message;
  const auto& [file, number] = expanded.origin[line - 1];
  return match.prefix().str() + fmt::format("line {} of file '{}'", number, file) +
         match.suffix().str();
}

}  // namespace

void parse_parameter_text(dealii::ParameterHandler& prm, const std::string& text,
                          const std::string& source) {
  std::istringstream input(text);
  try {
    prm.parse_input(input, source, "", false);
  } catch (const std::exception& error) {
    throw InputError(deal_ii_message(error.what()));
  }
}

void parse_parameter_file(dealii::ParameterHandler& prm, const std::filesystem::path& file,
                          const std::string& kind) {
  ExpandedText expanded;
  expand(file, kind, 0, expanded);
  try {
    parse_parameter_text(prm, expanded.text, file.string());
  } catch (const InputError& error) {
    throw InputError(fmt::format("{} '{}': {}", kind, file.string(), locate(error.what(), expanded)));
  }
}

}  // namespace softglass
