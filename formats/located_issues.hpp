#pragma once
// The end of a JSON reader whose own checks found issues: each placed at its
// FILE:LINE:COL in the text and reported in the order of the text.

#include <algorithm>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "formats/diagnostics.hpp"

namespace cemv::formats {

[[noreturn]] inline void throw_in_text_order(std::string_view text, const std::string& file,
                                             std::vector<LoadIssue> issues) {
  locate_issues(text, file, issues);
  std::stable_sort(issues.begin(), issues.end(), [](const LoadIssue& a, const LoadIssue& b) {
    return std::pair(a.line, a.column) < std::pair(b.line, b.column);
  });
  throw LoadError(std::move(issues));
}

}  // namespace cemv::formats
