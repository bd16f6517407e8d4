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
  // Patterns in words a user reads.
  for (const auto& [jargon, plain] :
       {std::pair<std::string, std::string>{"[Double -MAX_DOUBLE...MAX_DOUBLE (inclusive)]",
                                            "a number (without units)"}}) {
    for (auto at = text.find(jargon); at != std::string::npos; at = text.find(jargon, at))
      text.replace(at, jargon.size(), plain);
  }
  return text;
}

}  // namespace softglass::macro::io
