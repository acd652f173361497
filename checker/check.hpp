// The checker's public API: one function, check_properties. Given a validated matrix and its
// properties, decide every property and check every answer before reporting
// it (docs/checker.md):
//   1. encode the property's cone of influence and compile its monitor;
//   2. decide vacuity (assumptions satisfiable, antecedent reachable);
//   3. run the engine portfolio (k-induction, relational invariants, BMC, PDR,
//      the accelerated unrolling), one engine after another, each within a
//      budget of work, so that the answer is the same on every machine;
//   4. re-check the answer: a counterexample is replayed on the reference
//      runtime and judged by the concrete property evaluator; an invariant or
//      induction step is re-proved by a fresh solver;
//   5. for a proof, find its support (the matrix elements it needs).
// A check that fails throws checker::InternalError (checker/prover.hpp, exit 4),
// never a silent pass.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "checker/limits.hpp"
#include "checker/names.hpp"
#include "checker/result.hpp"
#include "encoder/encode.hpp"
#include "model/matrix.hpp"
#include "model/node.hpp"
#include "properties/ast.hpp"

namespace cemv::checker {

// Budgets of work (checker/limits.hpp): what each step of a property may
// spend. The same budgets give the same answers on every machine.
struct CheckBudgets {
  Work engine = 20 * kMega;   // each engine of a decision (PDR and the accelerated unrolling twice)
  Work quick = 2 * kMega;     // the quick k-induction before the engines
  Work shrink = kMega;        // the solver's pass of making a counterexample readable (checker/shrink.hpp)
  Work vacuity = 4 * kMega;   // each engine of a vacuity question
  Work support = 2 * kMega;   // the core's obligations of a proof; each engine of a --support full trial
};

struct CheckOptions {
  double property_timeout_s = 0.0;  // --timeout: wall clock per property; 0 = none
  double total_timeout_s = 0.0;     // --total-timeout: the whole run (when `cancel` is not given); 0 = none
  // The run's cancel token (checker/work_queue.hpp), for a caller whose run
  // is more than this check; its deadline bounds the whole run.
  CancelToken* cancel = nullptr;
  int jobs = 1;                     // workers over the properties
  int shard_index = 1;              // --shard i/n: 1-based i
  int shard_count = 1;
  std::string out_dir;              // counterexample scenarios go here ("" = nowhere)
  bool support = true;              // compute the support of proofs (false: as SupportMode::Off)
  SupportMode support_mode = SupportMode::Core;  // --support: how (checker/result.hpp)
  bool standard = false;            // the properties are the standard set
  CheckBudgets budgets;
  // How every engine, re-check and support query of the run makes its Z3
  // solvers and reads its work (checker/limits.hpp, docs/performance.md
  // "Solver set-up"). SmtKernel by default: the same verdicts as
  // DefaultSolver on the examples, at half the CPU of a standard set.
  SolverSetup solvers = SolverSetup::SmtKernel;
  // The engines that decide each property, in order (empty = the
  // portfolio's default order). A caller that knows which answer to expect
  // (cemv response: a proof of T, a counterexample to T - 1) leaves out the
  // engines that cannot give it; an Unknown then means "not with these
  // engines", and the caller asks again with the default order. Vacuity and
  // support questions always use the default order.
  std::vector<Method> engines;
  // The engines asked instead on a problem wider than 64 state variables
  // after the reduction (empty: `engines` apply there too;
  // PortfolioOptions::wide_engines).
  std::vector<Method> engines_when_wide;
  // Matrix elements whose state a localization keeps on a wide problem
  // before its engines: the state of every other element is made free
  // (PortfolioOptions::localize_keep, checker/localize.hpp). Empty: none.
  // cemv response passes the elements of the path it measures.
  std::vector<model::Node> localize_to;
  // Counterexamples longer than this are reported as the engine found them,
  // not made readable (PortfolioOptions::shrink_max_cycles; -1 = the
  // portfolio's default). cemv response passes 0 for its T - 1 question when
  // only the accelerated unrolling can answer it: that trace holds its inputs
  // over at most 8 macro steps already.
  int shrink_max_cycles = -1;
  // Runs to try before any engine, each as cycle inputs of the whole matrix
  // with no operator command (cemv response's demand runs: the plant quiet,
  // then the trigger's inputs beyond their limits and held). A run is
  // executed by the reference runtime and judged by the concrete evaluator;
  // one that violates the property is then replayed on the property's
  // encoding, where the monitor must be violated in the same cycle
  // (check::replay_counterexample), and is the counterexample, with method
  // "directed run". Every run is also kept as a witness for the vacuity
  // question. Not tried for reachability (cover) properties.
  std::vector<std::vector<model::CycleInput>> directed_runs;
  // Only the directed runs: when none violates, the property is Unknown
  // ("no directed run violates it") and no engine is asked. A caller tries
  // its cheap candidates this way before a costlier question of its own.
  bool directed_runs_only = false;
  // k-induction's bound for the property (PortfolioOptions::max_k; -1: the
  // portfolio's default).
  int max_k = -1;
  // false: a proof is reported without the vacuity question (can the
  // assumptions and the antecedent hold?). For a caller that uses the proof
  // only as a lemma of another property under the same assumptions, where
  // a vacuous lemma constrains nothing that property judges.
  bool vacuity = true;
  // Called once per finished property (any thread, serialised by the checker).
  std::function<void(const PropertyResult&)> on_result;
  // Called when a property's decision starts, with its name (any thread,
  // serialised): the command line's progress line shows what is running.
  std::function<void(const std::string&)> on_start;
  // A modifier of every encoding the checker builds, applied before the
  // property's monitor is compiled into it (Pono's modifiers/). Tests use it
  // to plant a wrong rule and see the runtime replay catch it.
  std::function<void(encoder::Encoding&)> modify_encoding;
};

CheckResult check_properties(const model::Matrix& m, const std::vector<properties::PropertyFile>& files,
                             const CheckOptions& options);

// The properties of `files` that shard i of n checks: a deterministic split by
// position in the concatenated list (property k goes to shard k mod n + 1).
inline bool in_shard(std::size_t index, int shard_index, int shard_count) {
  return shard_count <= 1 || static_cast<int>(index % static_cast<std::size_t>(shard_count)) + 1 == shard_index;
}

}  // namespace cemv::checker
