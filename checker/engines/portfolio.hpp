// Engines in parallel threads, each with its own z3::context and its own copy
// of the problem (Z3 is not thread-safe within one context), built by the
// caller's factory. The first definitive answer ends the race, yet the result
// is deterministic:
// - Falsified: the counterexample of BMC, which is a shortest one, when there
//   is one within BMC's bound (PortfolioOptions::bmc_depth); when another
//   engine finds one first, BMC is allowed to finish (it must succeed at that
//   depth or less). A counterexample deeper than BMC's bound (the accelerated
//   unrolling's) is reported as that engine found it.
// - Proved: the first engine in the preference order
//   k-induction, invariants+induction, pdr that proves it; engines earlier in
//   the order are waited for (each stops at its own bound), later ones stopped.
// The engines work on the reduced problem (checker/reduce.hpp); a
// counterexample is lifted back to the caller's problem and replayed there.
// Engines start in tiers (PortfolioOptions::tiers), so that easy properties
// do not share two cores among five threads.
// A counterexample's inputs that the violation does not need keep their
// preferred value (checker/shrink.hpp; zero when none is given). The answer is re-checked in a fresh context before it
// is returned.
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "checker/localize.hpp"
#include "checker/prover.hpp"
#include "checker/shrink.hpp"

namespace cemv::checker {

struct PortfolioOptions {
  // Engine names: "bmc", "k-induction", "invariants+induction", "pdr", "accelerated-bmc";
  // and "k-induction-plain" (k-induction with the encoder's lemmas only, no
  // mined invariants), which only a caller names.
  std::vector<std::string> engines{"k-induction", "invariants+induction", "bmc", "pdr", "accelerated-bmc"};
  // When each engine starts: tier t once every prover of the earlier tiers has
  // finished without an answer, or t * `grace` after the start. Two threads
  // first, for two cores: most properties are decided there.
  std::vector<std::vector<std::string>> tiers{{"k-induction", "bmc"}, {"invariants+induction"},
                                              {"pdr", "accelerated-bmc"}};
  std::chrono::milliseconds grace{1500};
  int max_k = 10;        // k-induction's bound inside the portfolio
  // BMC's depth inside the portfolio. A counterexample that short is BMC's,
  // a shortest one; a longer one is the accelerated unrolling's (complete
  // for every length, as a macro step may be one cycle). The bound keeps the
  // wait for BMC's answer finite, so the choice never depends on timing.
  int bmc_depth = 32;
  bool recheck = true;   // checker/check/ on the answer
  bool reduce = true;    // the engines work on the reduced problem (checker/reduce.hpp)
  // What a counterexample's inputs should read where the violation does not
  // need otherwise (by input name); empty = 0, FALSE, 0.0 for every input.
  PreferredValue preferred;
  std::chrono::milliseconds shrink_budget{10000};
  // Longer counterexamples are not made readable: they come from the
  // accelerated unrolling, whose inputs are already held over macro steps,
  // and the core-guided search over a hundred cycles costs more than the
  // decision and could run into shrink_budget, so that the trace shown would
  // depend on the machine's load (cemv response's T - 1 runs: compressor
  // 69 s -> 37 s of CPU, the same report). Where the search ran out of its
  // budget on the 102-cycle pipeline defect, the trace it left was worse to
  // read than the engine's, every analog input toggling.
  std::size_t shrink_max_cycles = 64;
  // Before the race: k-induction up to this k with the encoder's lemmas
  // only, in the calling thread, within `quick_budget` (-1: no quick attempt).
  int quick_k = 1;
  // Then, for questions that are expected to have a witness (can the
  // antecedent hold?), BMC to this depth (0: none).
  int quick_bmc_depth = 0;
  std::chrono::milliseconds quick_budget{2000};
  // Instead of the race: after the quick attempt, `engines` one after
  // another in the order given, in the calling thread, on the quick attempt's
  // problem (one encoding and one reduction for all of them); the first
  // definitive answer is the answer. For a caller that decides many
  // properties in parallel and knows which engine is likely to answer
  // (cemv response: docs/response-time.md, "Method"): no thread, context or
  // reduction per engine, and no engine running beside the one that answers.
  bool in_order = false;
  // ... but only for a problem of at most this many state variables after
  // the reduction. A wider one is asked `wide_engines` in order instead
  // (whether or not `in_order` is set), or, when that is empty, races
  // `engines`. On a wide cone the relational miner
  // of invariants+induction can use the whole time limit at k = 0 where PDR
  // proves a short bound in a second (big_matrix's reference chains: 122-138
  // state variables). A count, so the choice never depends on the machine.
  std::size_t in_order_max_states = 64;
  std::vector<std::string> wide_engines;
  // Race `wide_engines` (threads, under the race's preference rules) instead
  // of asking them in order: for a question whose answer may be either, on
  // a wide problem where one engine is quick at one answer and slow at the
  // other (PDR proves a short bound in seconds and may take minutes to
  // find the counterexample BMC finds in one).
  bool race_wide = false;
  // Localization (checker/localize.hpp): before the engines (after the quick
  // attempt), `localized_engines` in order on the problem with only the
  // state that `localize_keep` keeps, within half of the time left; on a
  // problem of at most `in_order_max_states` only when that keeps at most
  // half of its state variables (a count: the choice never depends on time). A proof counts
  // when its evidence re-checks on the whole (reduced) problem in a fresh
  // context, as every proof does (it holds there when the localization is an
  // over-approximation, which that check does not take on trust); only an
  // invariant with k <= 1 and no simple-path condition is taken, because its
  // re-check on the whole problem is one step, and a simple path of the
  // kept variables is not one of the whole state. A counterexample counts
  // when its inputs violate the whole problem. Anything else: the engines
  // go on as without. Empty: no localization.
  KeepState localize_keep;
  std::vector<std::string> localized_engines{"pdr", "invariants+induction"};
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
  bool wants_quick_attempt() const;  // quick_k set and k-induction among the engines
  std::optional<ProverResult> quick_attempt(const SafetyProblem& problem, const Limits& limits) const;
  std::optional<ProverResult> localized_attempt(const OwnedProblem& whole, bool wide, const Limits& limits) const;
  ProverResult quick_k_induction(const SafetyProblem& problem, const Limits& limits) const;
  ProverResult race(const ProblemFactory& make, const std::vector<std::string>& engines, const Limits& limits) const;
  ProverResult one_after_another(const std::vector<std::string>& engines, const SafetyProblem& problem,
                                 const Limits& limits) const;
  ProverResult confirmed(const ProblemFactory& make, ProverResult answer, const Limits& limits,
                         std::chrono::steady_clock::time_point start) const;
  ProblemFactory make_;
  PortfolioOptions options_;
};

}  // namespace cemv::checker
