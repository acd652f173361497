// Engines in parallel threads, each with its own z3::context and its own copy
// of the problem (Z3 is not thread-safe within one context), built by the
// caller's factory. The first definitive answer ends the race, yet the result
// is deterministic:
// - Falsified: the counterexample of BMC, which is a shortest one; when another
//   engine finds one first, BMC is allowed to finish (it must succeed at that
//   depth or less). A counterexample deeper than BMC's bound (the accelerated
//   unrolling's) is reported as that engine found it.
// - Proved: the first engine in the preference order
//   invariants+induction, k-induction, pdr that proves it; engines earlier in
//   the order are waited for (each stops at its own bound), later ones stopped.
// A counterexample's inputs that the violation does not need are set to zero
// (trace_shrink.hpp). The answer is re-checked in a fresh context before it
// is returned.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "checker/prover.hpp"

namespace cemv::checker {

struct PortfolioOptions {
  // Engine names: "bmc", "k-induction", "invariants+induction", "pdr", "accelerated-bmc".
  std::vector<std::string> engines{"invariants+induction", "k-induction", "pdr", "bmc", "accelerated-bmc"};
  int max_k = 10;        // k-induction's bound inside the portfolio
  bool recheck = true;   // checker/check/ on the answer
};

// A prover by name, for the portfolio and the command line; throws
// std::invalid_argument for an unknown name.
std::unique_ptr<Prover> make_prover(const std::string& name, int max_k = -1);

class Portfolio {
 public:
  explicit Portfolio(ProblemFactory make, PortfolioOptions options = {});
  // Throws InternalError when the answer fails its re-check or an engine
  // failed other than by running out of time.
  ProverResult run(const Limits& limits);

 private:
  ProblemFactory make_;
  PortfolioOptions options_;
};

}  // namespace cemv::checker
