// Houdini for a product of plc_check's (correspondence.hpp): the largest
// subset of the candidates that holds initially and is inductive under the
// constraints and the assumption, as checker::houdini finds it, with a solver
// made for the product's arithmetic. A reduced product of Bool and Int state
// (analog values as ordered integers) is linear integer arithmetic; Z3's
// QF_LIA solver answers each round in a quarter of the default solver's time
// (a random matrix's whole product: 77 rounds over 3,000 candidates, 12 s
// against 46 s). A product with Float32 terms left goes to checker::houdini.
#pragma once

#include <vector>

#include <z3++.h>

#include "checker/engines/solving.hpp"
#include "checker/prover.hpp"

namespace cemv::plc_check {

// Deterministic (candidates dropped in order, from a model of a fixed
// query); its checks are charged to `meter`; throws checker::Stopped when the
// meter or the limits end it.
std::vector<z3::expr> product_houdini(const checker::SafetyProblem& p, std::vector<z3::expr> candidates,
                                      const checker::Limits& limits, checker::WorkMeter& meter);

// The same one cone at a time (plc_check/cones.hpp: each cone's state
// variables are closed under their next-state functions): cone i's
// candidates, every one over cone i's variables alone, checked on cone i's
// own initial values and transitions, assuming what the cones before it kept
// (invariants of the product); a candidate an earlier cone kept or dropped is
// not asked again. Each kept set is inductive given the earlier ones, so
// their union is inductive on the product; each solver call is the size of
// one cone, not of their union. A candidate over variables of no single cone
// is left out. Returns the union, in the cones' order.
std::vector<z3::expr> product_houdini_by_cones(const checker::SafetyProblem& p,
                                               const std::vector<std::vector<z3::expr>>& candidates,
                                               const std::vector<std::vector<std::size_t>>& cones,
                                               const checker::Limits& limits, checker::WorkMeter& meter);

}  // namespace cemv::plc_check
