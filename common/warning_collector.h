// Warnings of one kind folded into one line with a count.
//
// A tool that checks every volume fraction and quantity would otherwise print
// the same warning once per case ("phi = 0.7, N1: poorly determined", "phi =
// 0.75, N1: poorly determined", ...). Collected here by kind, each kind is one
// line: "poorly determined (4 times: phi 0.7 N1, phi 0.75 N1, ...)", or the
// plain "phi 0.7 N1: poorly determined" when it occurred once.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace softglass {

class WarningCollector {
 public:
  /// One warning of `kind` (the message without its place) at `where` (e.g.
  /// "phi 0.7, N1"; empty when it has no place).
  void add(const std::string& kind, const std::string& where = "");
  /// One line per kind, in the order the kinds first occurred; at most
  /// `named` places are listed, the rest counted ("and 3 more").
  std::vector<std::string> lines(std::size_t named = 6) const;
  bool empty() const { return kinds_.empty(); }

 private:
  struct Kind {
    std::string text;
    std::vector<std::string> places;
    std::size_t count = 0;
  };
  std::vector<Kind> kinds_;
};

}  // namespace softglass
