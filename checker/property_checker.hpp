// Decides one property and checks the answer before it is reported
// (docs/checker.md). The steps, in the order run() takes them:
//   directed runs the caller's candidate runs (CheckOptions::directed_runs),
//                 on the runtime and then on the encoding;
//   decide        the engine portfolio on the property's cone of influence;
//   confirm_trace a counterexample or witness replayed on the reference
//                 runtime and judged by the concrete evaluator (on failure the
//                 full, unsliced encoding is tried, then InternalError);
//   (re-check)    done by the portfolio: the proof's invariant and induction
//                 step re-proved, a trace re-simulated, in a fresh context;
//   vacuity       assumptions satisfiable, antecedent reachable: first
//                 asked of the runtime traces the run has produced, then of
//                 seeded random runs of the cone on the runtime
//                 (checker/witness_pool.hpp), then of the engines;
//   support       the matrix elements the proof needs.
#pragma once

#include <chrono>
#include <optional>
#include <vector>

#include "checker/check.hpp"
#include "checker/property_problem.hpp"
#include "checker/prover.hpp"
#include "checker/shrink.hpp"
#include "checker/result.hpp"
#include "checker/witness_pool.hpp"
#include "model/graph.hpp"
#include "properties/ast.hpp"

namespace cemv::checker {

class PropertyChecker {
 public:
  using Clock = std::chrono::steady_clock;
  PropertyChecker(const model::Matrix& m, const properties::PropertyFile& file,
                  const properties::Property& p, const CheckOptions& options, Clock::time_point deadline,
                  WitnessPool* witnesses = nullptr);

  PropertyResult run();

 private:
  ProblemFactory factory(const model::Matrix& m, Goal goal, bool sliced) const;
  ProverResult decide(const model::Matrix& m, Goal goal, bool sliced, Clock::time_point deadline) const;
  // Replays `r.cex`; fills the trace fields of `out`. False when the runtime
  // does not reproduce it.
  bool confirm_trace(const ProverResult& r, bool sliced, PropertyResult& out) const;
  // CheckOptions::directed_runs: the first that the runtime and the encoding
  // both show violating the property, reported; false when none does.
  bool directed_counterexample(PropertyResult& out) const;
  // A confirmed violation of the runtime, cut after its first violating
  // cycle, as `out`'s trace, timing table and scenario file.
  void report_trace(ConcreteTrace runtime_trace, int violation_cycle, PropertyResult& out) const;
  // Vacuous with the reason, or not vacuous; `undecided` when a limit left
  // the question open (the proof stands, with a note saying so).
  struct Vacuity {
    std::optional<std::string> vacuous;
    std::optional<std::string> undecided;
  };
  Vacuity vacuity() const;
  // An engine's witness that the antecedent can hold, run on the runtime and
  // kept for the properties after this one.
  void keep_witness(const ProverResult& r) const;
  void find_support(PropertyResult& out) const;

  const model::Matrix& m_;
  const properties::PropertyFile& file_;
  const properties::Property& p_;
  const CheckOptions& options_;
  Clock::time_point deadline_;
  std::vector<model::Node> roots_;
  bool has_antecedent_ = false;
  PreferredValue preferred_;  // the plant at rest, for readable counterexamples
  RunSpace cone_space_;        // the inputs and commands of the cone, for random witnesses
  WitnessPool* witnesses_;     // runtime traces of this check run (may be null)
};

// --standard: the candidate elements of the whole matrix that no proved
// property's support contains.
std::vector<SupportElement> unsupported_elements(const model::Matrix& m,
                                                 const std::vector<PropertyResult>& results);

}  // namespace cemv::checker
