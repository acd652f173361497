// A built problem carried into another Z3 context term for term (Z3's AST
// translation), instead of encoding and reducing it again there. The
// re-checks use it: the obligations are then stated afresh over the copy,
// in a context that holds no term, solver or model of the engine that
// answered, and checked by a new solver (checker/check/recheck.hpp). What the
// copy shares with the engines is the problem's description alone, which
// encoding it again would give term for term as well (the encoder and the
// reductions are deterministic).
#pragma once

#include <vector>

#include <z3++.h>

#include "checker/prover.hpp"

namespace cemv::checker {

// `p` in context `to`: the same state and input variables (by name), initial
// values, next-state functions, constraints, named terms and lemmas, its
// `good` and `assumption`; `terms` (over `p`'s variables) are replaced by
// their copies. For solver queries: the copy does not know which of its
// terms are float constants (TransitionSystem::float_value), so the
// encoder's Evaluator cannot run it. `p`'s context must not be in use by
// another thread meanwhile.
OwnedProblem translate(const SafetyProblem& p, z3::context& to, std::vector<z3::expr>* terms = nullptr);

}  // namespace cemv::checker
