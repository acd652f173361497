// The acceptance checklist (docs/testgen.md, "Checklist") in three forms,
// Markdown, one self-contained printable HTML page, and CSV, and the
// coverage file `coverage.json` (cemv-coverage/1). Each carries the matrix
// name and signature; the checklist also the date (SOURCE_DATE_EPOCH when
// set, so outputs are reproducible) and the tool version.
#pragma once

#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "testgen/testgen.hpp"

namespace cemv::testgen {

struct ChecklistHeader {
  std::string matrix_name;
  std::string matrix_title;
  std::string signature;
  std::string date;          // YYYY-MM-DD (UTC)
  std::string tool_version;  // "cemv 0.1.0"
  // Printed after the header, before the tests: a change checklist's list of
  // changes and retest scope (`--changed-from`, docs/change-acceptance.md).
  std::string preface_markdown, preface_html;
  std::vector<std::string> preface_csv;  // one `# change,...` comment row each
};
ChecklistHeader checklist_header(const model::Matrix& m, const TestSuite& s, const std::string& tool_version);
// The date of SOURCE_DATE_EPOCH when set and valid, else today (UTC).
std::string report_date();

std::string checklist_markdown(const model::Matrix& m, const TestSuite& s, const ChecklistHeader& h);
std::string checklist_html(const model::Matrix& m, const TestSuite& s, const ChecklistHeader& h);
std::string checklist_csv(const model::Matrix& m, const TestSuite& s, const ChecklistHeader& h);
// Deterministic (no date): the same matrix and options give the same bytes.
std::string coverage_json(const TestSuite& s, const std::string& tool_version);

}  // namespace cemv::testgen
