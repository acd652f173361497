// Decides one property and checks the answer before it is reported
// (docs/checker.md), in three steps that check_properties runs as three
// passes over all properties, so that what one property learns from the
// others (the runtime traces of the first pass) never depends on which worker
// finished first:
//   decide        the caller's directed runs (CheckOptions::directed_runs),
//                 then the engine portfolio on the property's cone of
//                 influence; a counterexample or witness replayed on the
//                 reference runtime and judged by the concrete evaluator (on
//                 failure the full, unsliced encoding is tried, then
//                 InternalError); the portfolio has re-checked the answer in
//                 a fresh context;
//   vacuity       (a proof) assumptions satisfiable, antecedent reachable:
//                 first asked of the first pass's runtime traces, then of
//                 seeded random runs of the cone on the runtime
//                 (checker/witness_pool.hpp), then of the engines;
//   support       (a proof) the matrix elements it needs.
// Every step works within budgets of work (CheckOptions::budgets); the
// wall clock (Limits::deadline, the cancel token) only interrupts: an
// interrupted decision is Unknown ("time limit"), an interrupted vacuity
// question or support search leaves the proof with a note saying so.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "checker/check.hpp"
#include "checker/cone_group.hpp"
#include "checker/group_support.hpp"
#include "checker/property_problem.hpp"
#include "checker/prover.hpp"
#include "checker/random_runs.hpp"
#include "checker/result.hpp"
#include "checker/shrink.hpp"
#include "checker/support.hpp"
#include "checker/witness_pool.hpp"
#include "properties/ast.hpp"

namespace cemv::checker {

class PropertyChecker {
 public:
  PropertyChecker(const model::Matrix& m, const properties::PropertyFile& file, const properties::Property& p,
                  const CheckOptions& options);
  // With what the property's cone group found (checker/cone_group.hpp): its
  // facts of the cone, and the group's answer, which decide() takes first.
  PropertyChecker(const model::Matrix& m, const properties::PropertyFile& file, const properties::Property& p,
                  const CheckOptions& options, EarlyAnswer early);

  // The verdict before vacuity: Proved and Unreachable are not final yet.
  PropertyResult decide(const Limits& limits);
  // For a Proved or Unreachable result of decide(): the question whether it
  // is vacuous, answered first from `known` (runtime traces of the run),
  // and the support of a proof.
  bool needs_vacuity(const PropertyResult& r) const;
  // `group`: the witnesses found for the other members of the property's
  // cone group, asked after `known` and given what this one finds.
  void settle_vacuity(PropertyResult& r, const WitnessPool& known, WitnessPool& group, const Limits& limits) const;
  bool needs_support(const PropertyResult& r) const;
  // --support core: the cells of the proof's unsat core, re-checked on the
  // matrix without the others; full: that core minimised by deletion
  // (docs/checker.md, "Support").
  // `core`: the proof's unsat core found on its cone group's encoding
  // (checker/group_support.hpp); nullopt: asked on the property's own.
  void find_support(PropertyResult& r, const Limits& limits,
                    const std::optional<SupportCore>& core = std::nullopt) const;
  // What the support is chosen from (candidate_deletions of the property's roots).
  std::vector<Deletion> support_candidates() const;
  // decide()'s proof, when it proved the property.
  const std::optional<ProverResult>& proof() const { return proof_; }
  // The runtime runs decide() made (its directed runs, the replayed
  // counterexample or witness), as property traces: witnesses of other
  // properties' antecedents.
  std::vector<properties::Trace> take_runs() { return std::move(runs_); }

 private:
  ProblemFactory factory(const model::Matrix& m, Goal goal, bool sliced) const;
  ProverResult ask(const model::Matrix& m, Goal goal, bool sliced, const Limits& limits) const;
  // Replays `r.cex`; fills the trace fields of `out`. False when the runtime
  // does not reproduce it.
  bool confirm_trace(const ProverResult& r, bool sliced, PropertyResult& out) const;
  // CheckOptions::directed_runs: the first that the runtime and the encoding
  // both show violating the property, reported; false when none does.
  bool directed_counterexample(PropertyResult& out) const;
  // A run that shows the property's answer (a violation, or a cover's
  // witness), replayed on the runtime and judged there, then replayed on the
  // property's own encoding, where the monitor must agree; false when it
  // does not show it. `agree_or_throw`: a disagreement of runtime and
  // encoding is an InternalError (else the run is left to the engines).
  bool answered_by_run(const std::vector<model::CycleInput>& inputs, Method method, bool agree_or_throw,
                       PropertyResult& out) const;
  // The candidates (candidate_deletions) the proof's unsat core needs, or
  // every candidate when no core is found; `reduced`: the matrix without the
  // others, on which the proof was re-checked.
  std::vector<SupportElement> core_support(const std::vector<Deletion>& candidates,
                                           const std::optional<SupportCore>& core, model::Matrix& reduced,
                                           const Limits& limits) const;
  // The unsat core of the proof's obligations on the property's own guarded
  // encoding; nullopt when there is none within the budget.
  std::optional<SupportCore> own_core(const std::vector<Deletion>& candidates, const Limits& limits) const;
  // Whether the property is proved on `trial` (a matrix with cells deleted),
  // `checked`: re-checked as every reported answer; nullopt when a tag the
  // property reads is gone.
  std::optional<ProverResult> prove_on(const model::Matrix& trial, bool checked, const Limits& limits) const;
  // The group's answer, when it has one.
  bool early_answer(PropertyResult& out);
  // A confirmed violation of the runtime, cut after its first violating
  // cycle, as `out`'s trace, timing table and scenario file.
  void report_trace(ConcreteTrace runtime_trace, int violation_cycle, PropertyResult& out) const;
  // Vacuous with the reason, or not vacuous; `undecided` when a limit left
  // the question open (the proof stands, with a note saying so).
  struct Vacuity {
    std::optional<std::string> vacuous;
    std::optional<std::string> undecided;
  };
  Vacuity vacuity(const WitnessPool& known, WitnessPool& group, const Limits& limits) const;

  const model::Matrix& m_;
  const properties::PropertyFile& file_;
  const properties::Property& p_;
  const CheckOptions& options_;
  std::vector<model::Node> roots_;
  bool has_antecedent_ = false;
  bool sliced_ = true;         // the answer came from the property's cone (else the whole matrix)
  PreferredValue preferred_;   // the plant at rest, for readable counterexamples
  RunSpace cone_space_;        // the inputs and commands of the cone, for random witnesses
  EarlyAnswer early_;
  std::optional<ProverResult> proof_;  // decide()'s proof, re-checked: what the support's core asks of
  mutable std::vector<properties::Trace> runs_;
};

// --standard: the candidate elements of the whole matrix that no proved
// property's support contains.
std::vector<SupportElement> unsupported_elements(const model::Matrix& m,
                                                 const std::vector<PropertyResult>& results);

}  // namespace cemv::checker
