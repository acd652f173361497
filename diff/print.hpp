// `cemv diff` output: text, Markdown, HTML (one self-contained page) and the
// versioned JSON schema cemv-diff/1 (docs/change-acceptance.md, "JSON").
#pragma once

#include <string>

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
  StructuralDiff structure;
  SemanticDiff behaviour;
  // Scenario files written for distinguishing runs, by group name ("effect[2]").
  std::vector<std::pair<std::string, std::string>> scenarios;
  int exit_code() const;  // 0 no behaviour changed, 1 changed, 3 undecided
  std::string verdict() const;  // one line: what the exit code says
};

std::string to_text(const DiffReport& r);
std::string to_markdown(const DiffReport& r);
std::string to_html(const DiffReport& r);
std::string to_json(const DiffReport& r);

}  // namespace cemv::diff
