// Checks of message texts, shared by the test suites of every module.
#pragma once

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "common/csv_table.h"
#include "common/errors.h"

namespace softglass::testing {

/// Expects `text` to contain every one of `parts`.
inline void expect_contains(const std::string& text, std::initializer_list<std::string> parts) {
  for (const std::string& part : parts)
    EXPECT_NE(text.find(part), std::string::npos) << part << " in: " << text;
}

/// The message of the `Error` (an InputError unless said) `read` throws; a
/// failure when it throws none.
template <class Error = InputError, class Read>
std::string refusal_of(Read read) {
  try {
    read();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted";
  return "";
}

/// The header of a result table (common/csv_writer.h: names, then a units
/// line) as "name [unit],...", the form the checks of its columns name.
inline std::string table_header(const std::string& csv_text) {
  const CsvTable table = CsvTable::parse(csv_text, "table");
  std::string header;
  for (const std::string& column : table.header())
    header += (header.empty() ? "" : ",") + column;
  return header;
}

}  // namespace softglass::testing
