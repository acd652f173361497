// The correspondence between the program's state and the matrix's (docs/plc.md
// "How an equality is proved"): in a product that computes the same outputs,
// each state of the one is a function of the other's, and that relation is
// what makes the output's equality inductive. A TON's elapsed time (ms) is the
// matrix's delay counter (cycles) times the scan time while it runs, an SR's
// Q1 is the effect's latch, an R_TRIG's memory the reset's previous value.
//
// Candidates are stated from templates over the product's state variables
// (guarded linear relations between a program integer and a matrix integer,
// guarded constants, clauses over one block instance's flags) together with
// the checker's own mined candidates, kept only where seeded runs of the
// product never break them, and proved jointly inductive by Houdini
// (checker/engines/invariants.hpp); the output's relation must then follow
// from them in one scan (k = 0) or after one (k = 1). The caller re-checks a
// proof in a fresh context like any engine's.
#pragma once

#include <vector>

#include <z3++.h>

#include "checker/prover.hpp"
#include "plc_check/sampling.hpp"

namespace cemv::plc_check {

// Candidates over the state variables of `cone` (ascending indices into the
// state variables of `p`, a product of plc_check's, best reduced:
// checker/reduce.hpp), each true in every sampled state. `with_clauses`:
// the checker's clauses over pairs of Booleans are asked beside them (they
// state a flag's constant under a guard, which the templates then leave
// out of their equalities).
class Supports;
std::vector<z3::expr> correspondence_candidates(const checker::SafetyProblem& p, const Samples& samples,
                                                const std::vector<std::size_t>& cone,
                                                const Supports* supports = nullptr, bool with_clauses = false);
std::vector<std::size_t> every_state_variable(const checker::SafetyProblem& p);

struct Correspondence {
  // Proved with the invariant and k (0 or 1), or Unknown: BoundReached when
  // `good` does not follow from the invariant, the limits' reason otherwise.
  // Method InvariantsInduction.
  checker::ProverResult result;
  // What Houdini kept, in p's context: true in every reachable state of the
  // product, also when `good` does not follow from it (a bounded search may
  // then assume it in every scan: it removes no run). Empty when the limits
  // ended Houdini.
  std::vector<z3::expr> invariant;
};

// Houdini over the candidates (those above and the checker's mined ones, with
// the runs `o` describes), then `good` from what is kept; in two rounds, the
// second with the checker's clauses over pairs of Booleans, only when `good`
// does not follow from the first's. With `cones` (a group's, plc_check/cones.hpp),
// in one round by the cones' layers (layers_of): each layer sampled again on
// its own variables, its templates and mined pairs of related inputs
// (Supports) that read its top, Houdini one layer at a time
// (product_houdini_by_layers), Unknown (BoundReached, nothing kept) when
// those runs break `good`; with cones, `samples` need only say which
// variables change. Without cones, the candidates of every state variable.
Correspondence prove_by_correspondence(const checker::SafetyProblem& p, const Samples& samples,
                                       const checker::Limits& limits, const SamplingOptions& o = {},
                                       std::vector<std::vector<std::size_t>> cones = {});

}  // namespace cemv::plc_check
