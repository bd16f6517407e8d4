// Helpers shared by the bridge tests: a per-test temporary directory, text
// files, and the shared rheometry folder (absent on some machines).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/common/test_files.h"
#include "tests/common/text_checks.h"

namespace softglass::bridge::testing {

using softglass::testing::expect_contains;
using softglass::testing::read_text;
using softglass::testing::TemporaryDirectory;
using softglass::testing::write_text;

/// ../shared/data/rheometry, where the real rheometer files live when present.
inline std::filesystem::path rheometry_dir() {
  return std::filesystem::path(SOFTGLASS_SHARED_DIR) / "data" / "rheometry";
}

}  // namespace softglass::bridge::testing
