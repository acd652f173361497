// Reductions of a safety problem before the engines see it (Pono's
// modifiers/), all exact (docs/checker.md, "Reductions"):
//
// 0. Constant propagation. Boolean inputs the assumption fixes in every cycle
//    (`assume not issued(simulate_tag)`) become constants, and so does every
//    state variable that can then never leave its initial value (the
//    simulation and soft-bypass states such an assumption freezes).
// 1. Cone of influence over variables. The encoder slices by matrix element
//    (a cause, an effect); inside a cause it still encodes every status
//    field, e.g. the deviation alarm of an analog cause, whose |a - b| is a
//    Float32 subtraction that bit-blasts to thousands of clauses per cycle.
//    Only the variables that `good`, the assumptions and the constraints on
//    them reach through next-state functions are kept.
// 2. Analog values as ordered integers. When what remains reads Float32
//    values only through comparisons (no arithmetic), each value is replaced
//    by its position in the order of finite single-precision numbers, an
//    integer: comparisons keep their meaning exactly, and the engines solve
//    linear integer arithmetic instead of bit-blasted floating point. -0.0
//    and +0.0 become one value, as they are for every comparison.
//
// A reduced problem's counterexample is lifted back to the original problem
// (inputs outside the cone at rest, integers back to floats, states
// re-simulated); its proofs are proofs of the original, because both
// reductions preserve the set of runs as seen by `good`.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "checker/prover.hpp"

namespace cemv::checker {

// The order-preserving integer of a finite float (-0.0 gives 0) and back.
std::int64_t float_key(float f);
float key_float(std::int64_t key);

struct Reduction {
  std::size_t state_vars_before = 0, state_vars_after = 0;
  std::size_t inputs_before = 0, inputs_after = 0;
  bool floats_as_integers = false;  // reduction 2 applied
};

// The Boolean inputs that the assumption fixes in every cycle, with their
// value (reduction 0 makes them constants).
std::vector<std::pair<std::string, bool>> forced_inputs(const SafetyProblem& p);

// The reduced problem; its owner keeps the original's owner alive.
OwnedProblem reduce(const OwnedProblem& original, Reduction* what = nullptr);
// The same, with `terms` over the original's variables (the goods and
// antecedents of a cone group's members, under the problem's assumption)
// kept in the cone and replaced by their reduced forms.
OwnedProblem reduce_with(const OwnedProblem& original, std::vector<z3::expr>& terms, Reduction* what = nullptr);

// A factory of reduced problems.
ProblemFactory reducing(ProblemFactory make);

// A counterexample of the reduced problem as one of the original: the same
// cycles, every original input given (an input the reduction dropped keeps 0,
// FALSE or 0.0), floats restored, states re-simulated.
Trace lift_trace(const SafetyProblem& original, const Trace& reduced);

}  // namespace cemv::checker
