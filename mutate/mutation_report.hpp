// Mutation adequacy of a generated test suite (docs/mutation.md): for every
// single-point mutant of the matrix, whether it is equivalent to the original
// (proved on the product of the two transition systems, or a distinguishing
// run replayed on both runtimes: checker/equivalence.hpp), and whether the
// suite detects it (some replayed expectation of the suite fails on the
// mutant, or a test no longer loads against it). A non-equivalent mutant that
// the suite does not detect survives: a gap in the test generator.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "checker/equivalence.hpp"
#include "model/matrix.hpp"
#include "mutate/mutants.hpp"
#include "testgen/testgen.hpp"

namespace cemv::mutate {

enum class MutantStatus { Equivalent, Detected, Survived, Undecided };
const char* to_string(MutantStatus);  // "equivalent", "detected", "survived", "undecided"

struct MutantOutcome {
  std::string id, op, element, description;
  MutantStatus status = MutantStatus::Undecided;
  checker::GroupEquivalence equivalence;
  std::vector<std::string> failing_tests;  // tests whose replay fails on the mutant (Detected)
};

struct MutationReport {
  std::string matrix_name, signature;
  std::vector<MutantOutcome> mutants;
  std::size_t refused = 0;  // single-point edits that do not validate
  std::size_t equivalent = 0, detected = 0, survived = 0, undecided = 0;
  // Of the equivalent: those equal on every common observable whose
  // interface differs (method "interface-only", docs/mutation.md).
  std::size_t interface_only = 0;
  // 1 some mutant survived, 3 some equivalence undecided (and none survived), 0 otherwise.
  int exit_code() const;
};

struct MutationOptions {
  checker::Work work = 20 * checker::kMega;  // each engine's budget of work per mutant
  double timeout_s = 0.0;                    // --timeout: the user's wall clock per mutant (0 = none)
  int jobs = 1;                              // mutants decided in parallel (the run's one work queue)
  // The run's cancel token (--total-timeout): the mutants it leaves are
  // undecided ("time limit").
  checker::CancelToken* cancel = nullptr;
};

// Replays the suite on every mutant; decides equivalence of the mutants the
// suite does not detect (a detected mutant is non-equivalent by its failing
// test, and the detecting run is real: it replayed on the runtime).
MutationReport mutation_report(const model::Matrix& m, const testgen::TestSuite& suite,
                               const MutationOptions& options = {});

std::string report_json(const MutationReport& r);      // cemv-mutation-report/1
std::string report_markdown(const MutationReport& r);

}  // namespace cemv::mutate
