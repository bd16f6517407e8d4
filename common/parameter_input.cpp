#include "common/parameter_input.h"

#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>

#include <sstream>

#include "common/deal_ii_message.h"
#include "common/errors.h"

namespace softglass {

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
  if (!std::filesystem::is_regular_file(file)) {
    throw InputError(fmt::format("{} '{}' does not exist", kind, file.string()));
  }
  try {
    // By file name, so that deal.II picks the format from the extension (.prm, .json, .xml).
    prm.parse_input(file.string(), "", false, false);
  } catch (const std::exception& error) {
    throw InputError(fmt::format("{} '{}': {}", kind, file.string(), deal_ii_message(error.what())));
  }
}

}  // namespace softglass
