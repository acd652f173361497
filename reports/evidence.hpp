// The evidence report of `cemv evidence` (docs/reports.md, "Evidence report"):
// one self-contained, printable HTML file for an assessor. It holds the matrix
// as a cause & effect grid, the validation result (11.5), every property with
// its verdict, method and (for counterexamples and witnesses) its timing
// diagram, the test-generation figures when given, and on every page (the
// print header and footer) the matrix signature, the tool version and the date.
// Inline CSS and images only: no scripts, no external resources. The same
// inputs (and date) give the same bytes.
#pragma once

#include <string>
#include <vector>

#include "checker/result.hpp"
#include "model/matrix.hpp"
#include "model/validate.hpp"

namespace cemv::reports {

struct EvidenceInputs {
  std::string matrix_file;                    // as given on the command line
  std::vector<model::Diagnostic> validation;  // model::validate(m)
  checker::CheckResult check;                 // no properties: "no properties given"
  std::string date;                           // "2024-05-01 12:00 UTC"
  // Test generation results (cemv-coverage JSON text) when given; empty: the
  // report says that none were given.
  std::string coverage_file;
  std::string coverage_json;
};

std::string evidence_html(const model::Matrix& m, const EvidenceInputs& in);

// "YYYY-MM-DD HH:MM UTC" of a Unix time.
std::string utc_date(long long epoch_seconds);

}  // namespace cemv::reports
