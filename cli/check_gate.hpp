// `cemv check --expect` and `--baseline FILE` (docs/checker.md, "Gating"):
// what each property is expected to get, so that a pipeline fails on what
// changed, not on the findings it already knows. The expected verdict of a
// property is the baseline's (a previous cemv-result/1) when the baseline has
// the property and decided it, else with --expect its `# expect:` comment,
// else a passing one (proved, reachable).
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "checker/result.hpp"
#include "properties/ast.hpp"

namespace cemv::cli {

class CheckGate {
 public:
  // Reads and checks the baseline; throws formats::LoadError (exit 2) when it
  // is not a cemv-result/1 file. `files` are the property files as parsed,
  // named as messages name them.
  CheckGate(bool expect, const std::string& baseline_file, const std::vector<properties::PropertyFile>& files);

  bool active() const { return expect_ || !baseline_file_.empty(); }

  // Sets PropertyResult::expected and expected_from on every property.
  void annotate(checker::CheckResult& r) const;

  // The exit status of an annotated result: without a gate the verdicts'
  // (checker::exit_code); with one, 0 every verdict as expected, 1 some
  // decided verdict not, 3 only undecided ones not (unknown is no verdict).
  int exit_code(const checker::CheckResult& r) const;

  // One line for the log: "cemv check --expect: 8 of 8 properties as expected
  // (1 falsified)" or "... 1 of 8 not as expected: NAME (proved, expected
  // falsified)"; "" without a gate.
  std::string summary(const checker::CheckResult& r) const;

 private:
  using Key = std::pair<std::string, std::string>;  // (property file or "" for the standard set, name)
  struct Expectation {
    std::string verdict;
    std::string from;
  };
  bool expect_;
  std::string baseline_file_;
  std::map<Key, Expectation> expected_;
};

}  // namespace cemv::cli
