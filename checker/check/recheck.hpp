// Independent re-checks of an engine's answer before it is reported
// (Bitwuzla's check/): a proof's invariant and induction step with a fresh
// solver, a counterexample by re-simulation on the encoder's Evaluator. A
// failed re-check throws InternalError: it is never turned into a verdict.
//
// The overloads taking a ProblemFactory build the problem in a fresh
// z3::context, so nothing the engine's context cached (simplifications,
// learned clauses, a wrong rewrite) takes part in the check.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "checker/prover.hpp"

namespace cemv::checker::check {

// Proved: the invariant holds initially and is inductive, and `good` is
// k-inductive relative to it (ProverResult's comment); each a fresh solver
// call that must answer unsat.
// With `limits`: a check the wall clock or the cancel token interrupts throws
// Interrupted, never InternalError.
void recheck_proof(const SafetyProblem& problem, const ProverResult& result, const Limits* limits = nullptr);
void recheck_proof(const ProblemFactory& make, const ProverResult& result, const Limits* limits = nullptr);

// Falsified: from the initial state, the trace's inputs drive the system so
// that `assumption` holds in every cycle and `good` is false in the last one.
void replay_counterexample(const SafetyProblem& problem, const Trace& cex, const Limits* limits = nullptr);
void replay_counterexample(const ProblemFactory& make, const Trace& cex, const Limits* limits = nullptr);

// The activation literals a proof needs (docs/checker.md, "Support"): the
// proof obligations of `result` (as recheck_proof states them) on a problem
// whose cells are guarded by `literals` (encoder::EncodeOptions::guard_cells;
// `fixed`: guards held TRUE, not asked about), each checked with every
// literal assumed TRUE, the union of their unsat cores. nullopt when an
// obligation is not unsat under them within `work` (the proof does not carry
// over to this problem, or the budget ran out) or the invariant does not
// parse here; Interrupted when `limits` end it.
std::optional<std::vector<z3::expr>> proof_core(const SafetyProblem& problem, const ProverResult& result,
                                                const std::vector<z3::expr>& literals,
                                                const std::vector<z3::expr>& fixed, Work work, const Limits& limits);

// Either of the two above, by verdict; Unknown needs no check.
void recheck(const ProblemFactory& make, const ProverResult& result, const Limits* limits = nullptr);

// The proof obligations of a Proved result as SMT-LIB 2 scripts, each of
// which a solver must answer unsat: invariant initiation and consecution,
// base case and inductive step.
struct ProofObligation {
  std::string name;    // "invariant-init", "invariant-step", "base", "step"
  std::string script;  // (set-logic ALL) ... (check-sat)
};
std::vector<ProofObligation> proof_obligations_smtlib(const SafetyProblem& problem, const ProverResult& result);

}  // namespace cemv::checker::check
