#include "common/deal_ii_message.h"

namespace softglass {

namespace {

// The closing rule deal.II prints under every exception (with or without a
// stack trace before it).
constexpr std::string_view kRule = "--------------------------------------------------------";

bool blank(char c) {
  return c == ' ' || c == '\n' || c == '\t';
}

}  // namespace

std::string deal_ii_message(std::string_view what) {
  constexpr std::string_view info = "Additional information:";
  if (const auto at = what.find(info); at != std::string_view::npos) {
    what.remove_prefix(at + info.size());
    what = what.substr(0, what.find(kRule));
  }
  what = what.substr(0, what.find("Stacktrace:"));
  std::string text;
  bool space = false;
  for (const char c : what) {
    if (blank(c)) {
      space = !text.empty();
      continue;
    }
    if (space) text += ' ';
    text += c;
    space = false;
  }
  // Patterns::Double() without bounds describes itself by its limits.
  constexpr std::string_view jargon = "[Double -MAX_DOUBLE...MAX_DOUBLE (inclusive)]";
  if (const auto at = text.find(jargon); at != std::string::npos)
    text.replace(at, jargon.size(), "a number (without units)");
  return text;
}

}  // namespace softglass
