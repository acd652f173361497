// The outputs of `cemv response` (docs/response-time.md, "Outputs"): a table
// per SIF as text, cemv-response/1 JSON, and JUnit / SARIF written by the
// printers of `cemv check` (reports/check_report.hpp), one test case or
// finding per path. Pure functions of the result: byte-identical between runs.
#pragma once

#include <string>

#include "response/analysis.hpp"

namespace cemv::response {

enum class Format { Text, Json, Junit, Sarif };

std::string response_report(const ResponseResult& r, const std::string& matrix_file, Format format,
                            const std::string& out_dir);

}  // namespace cemv::response
