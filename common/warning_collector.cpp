#include "common/warning_collector.h"

#include <fmt/format.h>

#include <algorithm>

namespace softglass {

void WarningCollector::add(const std::string& kind, const std::string& where) {
  auto k = std::find_if(kinds_.begin(), kinds_.end(), [&](const Kind& x) { return x.text == kind; });
  if (k == kinds_.end()) k = kinds_.insert(kinds_.end(), Kind{kind, {}, 0});
  ++k->count;
  if (!where.empty()) k->places.push_back(where);
}

std::vector<std::string> WarningCollector::lines(std::size_t named) const {
  std::vector<std::string> out;
  for (const Kind& k : kinds_) {
    if (k.count == 1) {
      out.push_back(k.places.empty() ? k.text : k.places.front() + ": " + k.text);
      continue;
    }
    std::string places;
    for (std::size_t i = 0; i < std::min(named, k.places.size()); ++i)
      places += (i == 0 ? "" : "; ") + k.places[i];
    if (k.places.size() > named) places += fmt::format("; and {} more", k.places.size() - named);
    out.push_back(fmt::format("{} ({} times{}{})", k.text, k.count, places.empty() ? "" : ": ",
                              places));
  }
  return out;
}

}  // namespace softglass
