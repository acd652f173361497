// The engines of one question, asked one after another on one problem (one
// context, one encoding, one reduction), each within its own budget of work;
// the first definitive answer is the answer. Nothing depends on which thread
// is faster or how loaded the machine is: the same problem gives the same
// method, proof and trace everywhere (docs/checker.md, "Budgets").
//
// The order (PortfolioOptions::engines) puts the cheap and common answers
// first:
// - a quick k-induction: no strengthening at k = 0, then the encoder's lemmas
//   to PortfolioOptions::quick_k; its base case is BMC, so a counterexample
//   found there is a shortest one and is reported as BMC's;
// - for questions that expect a witness (covers, antecedents), BMC to
//   quick_bmc_depth;
// - then the engines in order: by default invariants+induction, k-induction
//   with mined invariants, BMC to bmc_depth, PDR, the accelerated unrolling.
// The engines work on the reduced problem (checker/reduce.hpp); a
// counterexample is lifted back to the caller's problem and replayed there.
// A counterexample's inputs that the violation does not need keep their
// preferred value (checker/shrink.hpp), within a budget of work. The answer is
// re-checked in a fresh context before it is returned.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "checker/localize.hpp"
#include "checker/prover.hpp"
#include "checker/shrink.hpp"

namespace cemv::checker {

struct PortfolioOptions {
  // The engines after the quick attempt, in order.
  std::vector<Method> engines{Method::InvariantsInduction, Method::KInduction, Method::Bmc, Method::Pdr,
                              Method::AcceleratedBmc};
  // Each engine's budget of work. PDR and the accelerated unrolling get
  // twice as much: they answer what the others cannot.
  Work engine_work = 20 * kMega;
  // The engines are asked in rounds, each with this fraction of its budget:
  // a cheap answer of a later engine (PDR's proof of an output delay, the
  // accelerated unrolling's long witness) comes before an earlier engine has
  // spent its whole budget. An engine that ended at its depth bound, not at
  // its budget, is not asked again. Fractions ascending, the last 1.
  std::vector<double> rounds{0.125, 1.0};
  int max_k = 10;        // k-induction's bound
  // BMC's depth. A counterexample that short is BMC's, a shortest one; a
  // longer one is the accelerated unrolling's (complete for every length, as
  // a macro step may be one cycle).
  int bmc_depth = 32;
  bool recheck = true;   // checker/check/ on the answer
  bool reduce = true;    // the engines work on the reduced problem (checker/reduce.hpp)
  // What a counterexample's inputs should read where the violation does not
  // need otherwise (by input name); empty = 0, FALSE, 0.0 for every input.
  PreferredValue preferred;
  // The work the solver's pass of the readable counterexample may take
  // (0: no readable form, the engine's trace as it is). The concrete pass
  // before it does most of the work at little cost (checker/shrink.hpp).
  Work shrink_work = kMega;
  // Longer counterexamples are not made readable: they come from the
  // accelerated unrolling, whose inputs are already held over macro steps,
  // and the core-guided search over a hundred cycles costs more than the
  // decision. Where the search was cut short on the 102-cycle pipeline
  // defect, the trace it left was worse to read than the engine's, every
  // analog input toggling.
  std::size_t shrink_max_cycles = 64;
  // The quick attempt: k-induction up to this k with the encoder's lemmas
  // only, within `quick_work` (-1: none).
  int quick_k = 1;
  // Then, for questions that are expected to have a witness (can the
  // antecedent hold?), BMC to this depth (0: none).
  int quick_bmc_depth = 0;
  Work quick_work = 2 * kMega;
  // On a problem of more than this many state variables after the
  // reduction, `wide_engines` are asked instead of `engines` (when given). On
  // a wide cone the relational miner of invariants+induction can spend its
  // whole budget at k = 0 where PDR proves a short bound at once (big_matrix's
  // reference chains: 122-138 state variables). A count, so the choice
  // never depends on the machine.
  std::size_t wide_states = 64;
  std::vector<Method> wide_engines;
  // Localization (checker/localize.hpp): before the engines (after the quick
  // attempt), `localized_engines` in order on the problem with only the
  // state that `localize_keep` keeps, each within `localized_work`; on a
  // problem of at most `wide_states` only when that keeps at most half of its
  // state variables. A proof counts when its evidence re-checks on the whole
  // (reduced) problem in a fresh context, as every proof does; only an
  // invariant with k <= 1 and no simple-path condition is taken, because its
  // re-check on the whole problem is one step, and a simple path of the kept
  // variables is not one of the whole state. A counterexample counts when its
  // inputs violate the whole problem. Anything else: the engines go on as
  // without. Empty: no localization.
  KeepState localize_keep;
  std::vector<Method> localized_engines{Method::Pdr, Method::InvariantsInduction};
  Work localized_work = 10 * kMega;
  // The localized problem is small: its first engine (PDR) mostly answers
  // within a quarter of its budget.
  std::vector<double> localized_rounds{0.25, 1.0};
};

// A prover by its method; throws std::invalid_argument for a method that is
// not an engine.
std::unique_ptr<Prover> make_prover(Method engine, int max_k = -1);

class Portfolio {
 public:
  explicit Portfolio(ProblemFactory make, PortfolioOptions options = {});
  // Throws InternalError when the answer fails its re-check. An interrupted
  // question (Limits::interrupted) is Unknown with reason TimeLimit, whatever
  // an engine had found.
  ProverResult run(const Limits& limits);

 private:
  ProverResult decide(const Limits& limits, Clock::time_point start);
  std::optional<ProverResult> quick_attempt(const SafetyProblem& problem, const Limits& limits) const;
  ProverResult quick_k_induction(const SafetyProblem& problem, const Limits& limits) const;
  std::optional<ProverResult> localized_attempt(const OwnedProblem& whole, bool wide, const Limits& limits) const;
  ProverResult one_after_another(const std::vector<Method>& engines, const SafetyProblem& problem,
                                 const Limits& limits, Work each, const std::vector<double>& rounds) const;
  Work work_of(Method engine, Work each) const;
  ProverResult confirmed(OwnedProblem& reduced, ProverResult answer, const Limits& limits, Clock::time_point start) const;
  ProblemFactory make_;
  PortfolioOptions options_;
};

}  // namespace cemv::checker
