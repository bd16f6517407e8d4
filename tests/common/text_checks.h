// Checks of message texts, shared by the test suites of every module.
#pragma once

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

namespace softglass::testing {

/// Expects `text` to contain every one of `parts`.
inline void expect_contains(const std::string& text, std::initializer_list<std::string> parts) {
  for (const std::string& part : parts)
    EXPECT_NE(text.find(part), std::string::npos) << part << " in: " << text;
}

}  // namespace softglass::testing
