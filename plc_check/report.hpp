// The outputs of `cemv plc-check` (docs/plc.md "Outputs"): text for people,
// `cemv-plc-result/1` JSON, and JUnit and SARIF through the printers of
// `cemv check` (each output tag a property located at the program's line that
// set the output in the first differing scan). Deterministic: no times in
// JSON, JUnit or SARIF.
#pragma once

#include <string>
#include <vector>

#include "checker/result.hpp"
#include "model/matrix.hpp"
#include "plc_check/check.hpp"

namespace cemv::plc_check {

struct PlcCheckReport {
  std::string matrix_file;
  std::string matrix_signature;
  std::string program_file;
  std::string program_sha256;
  std::string pou;
  Relation relation = Relation::Equal;
  ResolvedMap map;
  std::string map_source;  // the map file, or "found by name"
  std::vector<OutputResult> outputs;
  // Per output (same order): the files written under --out, "" when none.
  std::vector<std::string> scenario_files, diagram_files;
  bool interrupted = false;  // --total-timeout ended the run
  std::string tool_version;
};

// 0 every output related, 1 a difference, 3 unknown and no difference.
int exit_code(const PlcCheckReport& r);

std::string to_text(const PlcCheckReport& r, const model::Matrix& m);
std::string to_json(const PlcCheckReport& r);  // cemv-plc-result/1

// The results as `cemv check` results, for its JUnit and SARIF printers.
checker::CheckResult as_check_result(const PlcCheckReport& r);

// The run of a difference as a table of both sides, one column per scan
// (folded where nothing changes), the first differing scan marked.
std::string timing_table(const OutputResult& o, const model::Matrix& m);

}  // namespace cemv::plc_check
