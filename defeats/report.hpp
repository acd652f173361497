// The outputs of `cemv defeats` (docs/defeats.md, "Outputs"): a table per
// SIF as text, cemv-defeats/1 JSON, and JUnit / SARIF written by the printers
// of `cemv check` (reports/check_report.hpp), one test case or finding per
// path. Pure functions of the result: byte-identical between runs.
#pragma once

#include <string>

#include "defeats/analysis.hpp"

namespace cemv::defeats {

enum class Format { Text, Json, Junit, Sarif };

// `require_distance`: the gate (0 = none), which JUnit and SARIF report as
// the failure of a path and text and JSON state.
std::string defeats_report(const model::Matrix& m, const DefeatsResult& r, const std::string& matrix_file,
                           Format format, const std::string& out_dir, int require_distance);

// "{soft bypass of cause 1 LT_HH, bad quality of input tag LT_100A}".
std::string set_text(const model::Matrix& m, const PathDefeats& p, const DefeatSet& s);

}  // namespace cemv::defeats
