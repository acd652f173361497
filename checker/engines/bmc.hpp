// Bounded model checking, incremental: one solver holds the path; the
// violation of each depth is asked under an assumption literal, and after an
// unsat answer `good` of that cycle is added, so the first sat answer is a
// shortest counterexample.
#pragma once

#include "checker/prover.hpp"

namespace cemv::checker {

class Bmc : public Prover {
 public:
  Method method() const override { return Method::Bmc; }
  // Falsified with a shortest counterexample of at most limits.max_depth + 1
  // cycles; Unknown "bound reached" when there is none that short.
  ProverResult prove(const SafetyProblem& problem, const Limits& limits) override;
};

}  // namespace cemv::checker
