#include "macro/io/deal_ii_errors.h"

#include <deal.II/base/exceptions.h>

#include <sstream>

namespace softglass::macro::io {

std::string one_line(const dealii::ExceptionBase& error) {
  std::ostringstream info;
  error.print_info(info);
  std::string text;
  for (std::istringstream words(info.str()); words;) {
    std::string word;
    if (words >> word) text += (text.empty() ? "" : " ") + word;
  }
  // The pattern of every number entry, in words a user reads.
  const std::string jargon = "[Double -MAX_DOUBLE...MAX_DOUBLE (inclusive)]";
  if (const auto at = text.find(jargon); at != std::string::npos)
    text.replace(at, jargon.size(), "a number (without units)");
  return text;
}

}  // namespace softglass::macro::io
