// The plausibility rules of the timing fields that `cemv response` reads
// (process safety times, watchdog, sensor and actuator times;
// docs/response-time.md), kept apart from validate.cpp's element rules.
// Internal to model/: validate() merges these findings into its report.
#pragma once

#include <string>
#include <vector>

#include "model/matrix.hpp"

namespace cemv::model::detail {

struct TimingFinding {
  std::string rule;     // a rule id of validation_rules()
  int rank = 0;         // 0 matrix, 1 cause, 2 effect (validate's element order)
  int id = 0;
  std::string element;  // "matrix", "cause[3] NAME", ...
  std::string message;
};

std::vector<TimingFinding> timing_findings(const Matrix& m);

}  // namespace cemv::model::detail
