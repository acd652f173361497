// Relational template invariants, Houdini-style (Kind 2's and JKind's
// invariant generation): candidates relating pairs of Int state variables
// (x - y = c, x <= y + c, x <= c, x >= c), the same guarded by a Bool state
// variable (b -> x = y + c, !b -> x = c), a monitor's counter y against a
// saturating counter x under a monitor Bool (g -> x >= y + c or x >= bound),
// and implications between Bool state
// variables are mined from the initial state and short simulated runs of the
// encoder's Evaluator; a fresh solver then keeps the largest inductive subset.
// A monitor counter and the matrix's own timer counter are related this way
// (`override -> m = elapsed`), which is what proves an 18,000-cycle timer
// bound in one induction step where unrolling cannot.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include <z3++.h>

#include "checker/prover.hpp"
#include "encoder/evaluate.hpp"

namespace cemv::checker {

struct MiningOptions {
  // Simulated runs. Each false candidate that sampling misses costs Houdini a
  // solver round; on a 191-variable cone of a 128 x 128 matrix, 32 x 800
  // cycles (1 s) halve the total against 12 x 400.
  int runs = 32;
  int cycles_per_run = 800;
  unsigned seed = 1;        // fixed: the same problem gives the same candidates
  std::size_t max_candidates = 20000;
  // Clauses between pairs of Bool state variables: many candidates, each
  // Houdini round costs a solver call, so engines that need speed over
  // strength leave them out.
  bool bool_implications = true;
  // Mining stops early when the question is interrupted (the answer is
  // then abandoned anyway); its runs are a fixed number, not a time.
  const Limits* limits = nullptr;
  // Which pairs of state variables (indices into statevars()) are worth a
  // relation, and which Bool `g` worth stating one under (y = SIZE_MAX for a
  // constant of x alone); unset: every pair and guard.
  std::function<bool(std::size_t x, std::size_t y)> related;
  std::function<bool(std::size_t g, std::size_t x, std::size_t y)> may_guard;
  // mine_candidates_within: the distinct states of a subset's variables kept
  // (the first reached; 0: all). Below it the candidates are those of every
  // sampled state; above, a candidate false only in a later state is left to
  // Houdini.
  std::size_t max_states_per_subset = 4096;
};

// Candidate invariants over the state variables, true in every sampled state.
std::vector<z3::expr> mine_candidates(const SafetyProblem& problem, const MiningOptions& options = {});
// The same for each subset of the state variables (ascending indices into
// statevars()), from one simulation: each subset's candidates speak of its
// variables alone (a cone's, so that many cones cost their sizes, not the
// size of their union).
std::vector<std::vector<z3::expr>> mine_candidates_within(const SafetyProblem& problem, const MiningOptions& options,
                                                          const std::vector<std::vector<std::size_t>>& subsets);

// The same from states sampled elsewhere: `states[i]` holds distinct states
// of subsets[i]'s variables, each in the subset's order (an empty list
// gives no candidates for that subset).
std::vector<std::vector<z3::expr>> mine_candidates_from(
    const SafetyProblem& problem, const MiningOptions& options, const std::vector<std::vector<std::size_t>>& subsets,
    const std::vector<const std::vector<std::vector<encoder::Evaluator::Value>>*>& states);

// The largest subset of `candidates` that holds initially and is inductive
// (under the constraints and the assumption of the cycle). Candidates are
// dropped in a fixed order, so the answer is deterministic. Its checks are
// charged to `meter`; throws Stopped when the meter or the limits end it.
class WorkMeter;
std::vector<z3::expr> houdini(const SafetyProblem& problem, std::vector<z3::expr> candidates,
                              const Limits& limits, WorkMeter& meter);

// "invariants+induction": the encoder's lemmas and the mined candidates,
// filtered by Houdini, then `good` by induction relative to them (k <= 1).
std::unique_ptr<Prover> make_invariant_prover();

}  // namespace cemv::checker
