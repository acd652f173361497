// The four printers of `cemv check` results (docs/checker.md, "Outputs"), and
// what they share. Every printer is a pure function of the CheckResult: only
// the text printer shows times, so JSON, JUnit and SARIF are byte-identical
// between runs on the same inputs.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "checker/result.hpp"

namespace cemv::reports {

enum class CheckFormat { Text, Json, Junit, Sarif };
std::optional<CheckFormat> check_format_from_string(std::string_view name);

// The inputs a printer needs beyond the result itself.
struct CheckReportInputs {
  std::string matrix_file;  // as given on the command line
  // The matrix file's text, to place findings at the lines of the matrix
  // elements they concern (SARIF related locations, standard properties);
  // empty: no such lines (standard input).
  std::string matrix_text = {};
};

// Renders `r` in `format` (one of the printers below).
std::string check_report(const checker::CheckResult& r, const CheckReportInputs& in,
                         CheckFormat format);

// The verdict as every output spells it: "proved", "falsified", "reachable",
// "unreachable", "vacuous", "unknown" (the cemv-result/1 vocabulary).
const char* verdict_name(checker::PropertyVerdict v);

// A verdict that fails the check (exit 1): falsified, unreachable, vacuous.
bool is_failure(checker::PropertyVerdict v);

// A property of the standard set (--standard), which is derived from the
// matrix: the checker names its file "<standard>" (or none), reports place
// it in the matrix file.
bool is_standard(const checker::PropertyResult& p);

// Whether a verdict is what the run expects of it (cemv check --expect,
// --baseline): the expected verdict when one is given, else a passing one
// (proved, reachable). Without a gate this is "the property passed".
bool as_expected(const checker::PropertyResult& p);

// The diagnostic line of a property that did not pass or did not get its
// expected verdict, as compilers write them: `FILE:LINE:COL: error: property
// 'NAME' falsified at cycle 3 (found by bmc)` (`warning` for unknown, `note`
// and "(as expected)" for a negative verdict the gate expects, ", expected
// proved (# expect:)" for one it does not); "" for a property that passed as
// expected. A standard property is placed at its element's line in the matrix.
std::string finding_line(const checker::PropertyResult& p, const CheckReportInputs& in);

// finding_line of every property that has one, a line each: what
// `cemv check --quiet` still prints.
std::string check_findings(const checker::CheckResult& r, const CheckReportInputs& in);

// How many properties ended in each verdict, indexed by the PropertyVerdict enumerator.
std::array<int, 6> verdict_counts(const checker::CheckResult& r);

// The matrix elements a property is about, derived from the observables it
// reads ("effect[1].tag[2]" -> "effect[1]"), in first-use order; used to name
// the element in SARIF messages and logical locations.
std::vector<std::string> property_elements(const checker::PropertyResult& p);

// "Why, per step" as lines: "cycle 3: effect[1].latched 1 -> 0: R latch
// cleared without a reset: ... (E.5)" (an input tag: "cycle 2: TAG 0 -> 1: an
// input of the run ..."), one per entry of p.explanation.
std::vector<std::string> explanation_lines(const checker::PropertyResult& p);

// One line describing the outcome, without times: "proved by k-induction (k = 3)",
// "falsified at cycle 4 (trace of 5 cycles)", "unknown: time limit", ...
std::string outcome_text(const checker::PropertyResult& p);

}  // namespace cemv::reports
