// The model's systematic error per prediction mode (bridge/material/prediction.h):
// predicted/measured − 1 pooled over the public flow curves the scoreboard
// scores (bench/validate_measured.sh writes it beside the law file, as
// LAW_model_error.csv), per mode, law form and branch — the yield plateau
// (stress below 1.5× the yield stress) and the flowing branch above it.
// `bridge predict` states it beside its band, with the data sets it comes from:
// the band says how well the particles are known, this how well the model
// has matched real emulsions in the same mode.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <tuple>

namespace softglass::bridge {

struct ModelErrorEntry {
  double median_abs_error = 0.0, bias = 0.0;  // [1]
  int points = 0;
  std::string data_sets;
};

/// Keyed by (mode letter a–d, law form "tabulated" | "herschel-bulkley",
/// branch "all" | "plateau" | "flowing").
using ModelError = std::map<std::tuple<char, std::string, std::string>, ModelErrorEntry>;

/// LAW_model_error.csv beside `law_file`, or nothing when it is absent;
/// InputError when it is there but malformed.
std::optional<ModelError> read_model_error(const std::filesystem::path& law_file);

}  // namespace softglass::bridge
