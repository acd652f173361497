// `cemv diff` output: text, Markdown, HTML (one self-contained page), the
// versioned JSON schema cemv-diff/1 (docs/change-acceptance.md, "JSON") and
// SARIF.
#pragma once

#include <string>
#include <vector>

#include "diff/semantic.hpp"
#include "diff/structural.hpp"
#include "model/matrix.hpp"

namespace cemv::diff {

inline constexpr const char* kDiffFormat = "cemv-diff/1";

struct DiffReport {
  const model::Matrix* old_m = nullptr;
  const model::Matrix* new_m = nullptr;
  std::string old_file, new_file;
  std::string old_signature, new_signature;
  // The files' texts, for the lines of the changed elements (SARIF); empty
  // when not known (the changes are then placed at the file).
  std::string old_text, new_text;
  StructuralDiff structure;
  SemanticDiff behaviour;
  // Scenario files written for distinguishing runs, by group name ("effect[2]").
  std::vector<std::pair<std::string, std::string>> scenarios;
  // Why the behaviour was not compared: one line per validation error of a
  // side ("OLD: E-OVERRIDE-TIME-MISSING effect[1] ..."); empty when it was.
  // A matrix with validation errors cannot be executed, so only the
  // structural comparison is given (docs/change-acceptance.md).
  std::vector<std::string> not_compared;
  int exit_code() const;  // 0 no behaviour changed, 1 changed, 2 not compared (invalid), 3 undecided
  std::string verdict() const;  // one line: what the exit code says
};

std::string to_text(const DiffReport& r);
std::string to_markdown(const DiffReport& r);
std::string to_html(const DiffReport& r);
std::string to_json(const DiffReport& r);
// SARIF 2.1.0 for code review (docs/change-acceptance.md, "SARIF"): a result
// at the line of every changed element in NEW (in OLD for a removed one),
// and one at the line of every effect whose behaviour changed or was not
// decided.
std::string to_sarif(const DiffReport& r, const std::string& tool_version);

// The opening of a change checklist (`cemv testgen NEW --changed-from OLD`):
// the list of changes, the effects whose behaviour changed, and whether a
// partial retest is justified (retest_scope). Markdown and HTML sections, and
// one line per item for the CSV's comment rows.
std::string change_preface_markdown(const DiffReport& r);
std::string change_preface_html(const DiffReport& r);
std::vector<std::string> change_preface_lines(const DiffReport& r);

}  // namespace cemv::diff
