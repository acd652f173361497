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

// The same one layer at a time (plc_check/cones.hpp, Layer): layer i's
// candidates checked on the transitions of the state variables they read,
// assuming the facts (constraints, assumption, what earlier layers kept:
// invariants of the product) over those and what their next-state functions
// read, less the clauses those facts' equalities repeat (premise.hpp); a
// candidate an earlier layer kept or dropped is not asked again.
// Each kept set is inductive given the earlier ones, so their union is
// inductive on the product; each solver call is the size of one layer and
// its frontier. Returns the union, in the layers' order.
std::vector<z3::expr> product_houdini_by_layers(const checker::SafetyProblem& p,
                                                const std::vector<std::vector<z3::expr>>& candidates,
                                                const checker::Limits& limits, checker::WorkMeter& meter);

}  // namespace cemv::plc_check
