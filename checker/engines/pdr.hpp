// IC3/PDR through Z3's Spacer on a CHC encoding of the system: one predicate
// Inv over the state variables with the rules
//   init(s)                                  -> Inv(s)
//   Inv(s) and C(s,i) and A(s,i) and T(s,i,s') -> Inv(s')
//   Inv(s) and C(s,i) and A(s,i) and not good(s,i) -> Bad
// and the query Bad. Unsat: Spacer's solution for Inv is an inductive
// invariant implying good (a k = 0 proof). Sat: a shortest counterexample is
// then found by BMC, which the answer bounds.
#pragma once

#include "checker/prover.hpp"

namespace cemv::checker {

class Pdr : public Prover {
 public:
  Method method() const override { return Method::Pdr; }
  ProverResult prove(const SafetyProblem& problem, const Limits& limits) override;
};

}  // namespace cemv::checker
