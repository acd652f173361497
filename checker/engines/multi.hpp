// Many questions about one transition system at once (a cone group,
// checker/cone_group.hpp): one encoding, one reduction, one invariant search
// and one unrolling serve every member, and each member's question is an
// incremental solver call under an assumption literal. Hardware model
// checkers decide the properties of one design this way (ABC's multi-output
// pdr and bmc3).
#pragma once

#include <vector>

#include <z3++.h>

#include "checker/prover.hpp"

namespace cemv::checker {

// `goods[i]` must hold in every cycle of every run in which `assumption`
// held in every cycle so far (checker/prover.hpp's SafetyProblem, one system
// and one assumption for all).
struct MultiProblem {
  const encoder::TransitionSystem* ts = nullptr;
  std::vector<z3::expr> goods;
  z3::expr assumption;
  SafetyProblem member(std::size_t i) const { return SafetyProblem{ts, goods.at(i), assumption}; }
};

// k-induction with k <= 1 for every member whose `open` flag is set: first
// with no strengthening, then strengthened by the encoder's lemmas that one
// Houdini run keeps (the same for every member: it depends on the system and
// the assumption only). Each result is Proved (method k-induction, its k and
// invariant, as KInduction would state them) or Unknown; no counterexample is
// reported here (a member that fails goes to its own portfolio, which finds
// a shortest one). Within `limits.work` for the whole group.
// `strengthen[i]`: the member is worth the strengthened steps (a member whose
// monitor counts cycles needs invariants the lemmas do not give).
std::vector<ProverResult> prove_each(const MultiProblem& p, const std::vector<bool>& open,
                                     const std::vector<bool>& strengthen, const Limits& limits);

// Bounded model checking for the members whose `open` flag is set, to
// `limits.max_depth`: one unrolling, each depth asked whether any open
// member's target holds there (again, without those found, while one does),
// so that a member's first witness is a shortest one.
// `targets[i]` is what the member's witness must reach (the negation of a
// cover's `good`, an antecedent). Each result is Falsified with the witness
// (cycles 0..k, `targets[i]` true in the last) or Unknown. Within
// `limits.work` for the whole group.
std::vector<ProverResult> reach_each(const encoder::TransitionSystem& ts, const std::vector<z3::expr>& targets,
                                     const z3::expr& assumption, const std::vector<bool>& open,
                                     const Limits& limits);

}  // namespace cemv::checker
