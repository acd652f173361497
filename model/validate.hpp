// Plausibility checks of a loaded matrix: the validation report of 11.5.
#pragma once

#include <string>
#include <vector>

#include "model/matrix.hpp"

namespace cemv::model {

enum class Severity { Error, Warning };

struct Diagnostic {
  Severity severity = Severity::Error;
  std::string rule;      // stable rule id, e.g. "E-INTERSECTION-X"
  std::string element;   // e.g. "cause[3] LT100_HH", "effect[2]", "matrix"
  std::string section;   // manual section, e.g. "6.5.2"
  std::string message;
};

// Every finding, deterministically ordered (errors and warnings interleaved in
// rule-then-element order).
std::vector<Diagnostic> validate(const Matrix& m);
bool has_errors(const std::vector<Diagnostic>& ds);

// Every rule validate() applies, sorted by id: its severity, manual section and
// a one-line meaning (docs/validation.md lists the same table).
struct RuleInfo {
  const char* id;
  Severity severity;
  const char* section;
  const char* meaning;
};
const std::vector<RuleInfo>& validation_rules();
const char* to_string(Severity);  // "error" / "warning"

}  // namespace cemv::model
