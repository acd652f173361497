// What a property's AST says about its runs before any run: the expression
// whose reachability decides vacuity, and the fewest cycles a run needs
// before an expression can hold. For the checker's choice of engines: a
// question whose witness needs more cycles than BMC unrolls goes to the
// accelerated unrolling first.
#pragma once

#include "properties/ast.hpp"

namespace cemv::properties {

// The antecedent a vacuity check must reach (docs/properties.md "Vacuity"):
// the trigger of a Response, the left side of an Invariant `a implies b`, the
// first conjunct of a Never `a and b`, the body of a Reachable; else null.
const Expr* antecedent_of(const Property& p);

// A lower bound on the cycle (0-based) at which `e` can first hold in any
// run: `held(x, N cycles)` cannot hold before cycle N, `prev(x)` before
// cycle 1 plus x's bound; a conjunction takes the largest bound of its
// parts, a disjunction the smallest; anything else 0.
long long earliest_cycle(const Expr& e);

// Whether the property (or one of its own assumptions) counts cycles: a
// `held` or `within` over more than one cycle, a `since`, or a response's
// bound. Its monitor keeps a counter, which a proof must relate to the
// matrix's own timers: one induction step over the encoder's lemmas does
// not prove it.
bool counts_cycles(const Property& p);

}  // namespace cemv::properties
