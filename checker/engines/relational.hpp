// "relational-induction": the engine for equivalence problems on a product of
// two transition systems (encoder/product.hpp). Candidates are the system's
// lemmas, above all the product's relational ones (a.x = b.x for every state
// variable both copies have); Houdini keeps the largest inductive subset;
// `good` must then follow from it in the same cycle (k = 0).
//
// Every Float32 operation is replaced by an uninterpreted function of the same
// arguments (Ackermann's abstraction). Unlike the engines/invariants.hpp
// abstraction, which gives each float atom a fresh Bool and so loses the
// link between the two copies' atoms, a function keeps congruence: equal
// arguments give equal results, which is exactly what a.x = b.x needs, and
// no solver call bit-blasts a float circuit. An over-approximation: what it
// proves holds for the real floats. The answer is re-checked with the real
// semantics (checker/check/) before anyone sees it.
#pragma once

#include <memory>

#include "checker/prover.hpp"

namespace cemv::checker {

std::unique_ptr<Prover> make_relational_prover();

}  // namespace cemv::checker
