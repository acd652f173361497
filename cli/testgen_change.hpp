// `cemv testgen NEW --changed-from OLD` (docs/change-acceptance.md, "Testing
// the change"): the change comparison of `cemv diff` turned into test
// generation options. When the structural and the semantic comparison agree
// (diff::retest_scope), only the objectives about the impacted effects and
// their cones are generated; otherwise all of them. Every distinguishing run
// becomes a given test expecting NEW's behaviour. The checklist opens with
// the list of changes and the retest scope.
#pragma once

#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "testgen/testgen.hpp"

namespace cemv::cli {

struct ChangeScope {
  bool partial = false;
  std::string summary;  // what stdout prints: retest scope, changed effects
  std::string preface_markdown, preface_html;
  std::vector<std::string> preface_csv;
};

// Compares OLD with NEW (per effect at most `timeout_s`) and sets
// `options.elements` and `options.given`. Throws checker::InternalError like
// `cemv diff` (a distinguishing run that does not replay).
ChangeScope apply_change(const std::string& old_file, const std::string& new_file, const model::Matrix& new_m,
                         double timeout_s, testgen::TestgenOptions& options);

}  // namespace cemv::cli
