#include "checker/engines/portfolio.hpp"

#include <algorithm>
#include <stdexcept>

#include "checker/check/recheck.hpp"
#include "checker/context_pool.hpp"
#include "checker/engines/accelerated_bmc.hpp"
#include "checker/engines/bmc.hpp"
#include "checker/engines/invariants.hpp"
#include "checker/engines/kinduction.hpp"
#include "checker/engines/pdr.hpp"
#include "checker/engines/solving.hpp"
#include "checker/reduce.hpp"
#include "checker/shrink.hpp"
#include "checker/translate.hpp"

namespace cemv::checker {

std::unique_ptr<Prover> make_prover(Method engine, int max_k) {
  KInductionOptions o;
  o.max_k = max_k;
  switch (engine) {
    case Method::Bmc: return std::make_unique<Bmc>();
    case Method::KInduction: return std::make_unique<KInduction>(o);
    case Method::KInductionPlain:
      // Strengthened by the encoder's lemmas only: for a problem whose own
      // assumptions carry the invariants it needs (cemv response's member
      // lemmas), where the miner would spend the budget looking for them.
      o.mine_invariants = false;
      o.method = Method::KInductionPlain;
      return std::make_unique<KInduction>(o);
    case Method::InvariantsInduction: return make_invariant_prover();
    case Method::Pdr: return std::make_unique<Pdr>();
    case Method::AcceleratedBmc: return std::make_unique<AcceleratedBmc>();
    default: break;
  }
  throw std::invalid_argument(std::string("not an engine: ") + to_string(engine));
}

Portfolio::Portfolio(ProblemFactory make, PortfolioOptions options)
    : make_(std::move(make)), options_(std::move(options)) {}

namespace {

ProverResult interrupted_result(Clock::time_point start) {
  ProverResult r;
  r.method = Method::Portfolio;
  r.reason = UnknownReason::TimeLimit;
  r.seconds = seconds_since(start);
  return r;
}

}  // namespace

ProverResult Portfolio::run(const Limits& limits) {
  const auto start = Clock::now();
  try {
    return decide(limits, start);
  } catch (const Interrupted&) {
    return interrupted_result(start);
  }
}

ProverResult Portfolio::decide(const Limits& limits, Clock::time_point start) {
  const ProblemFactory make = options_.reduce ? reducing(make_) : make_;
  PooledContext ctx;
  OwnedProblem owned = make(ctx);
  std::optional<ProverResult> answer = quick_attempt(owned.problem, limits);
  const bool wide = owned.problem.ts->statevars().size() > options_.wide_states;
  if (!answer && options_.localize_keep) answer = localized_attempt(owned, wide, limits);
  if (!answer) {
    const auto& order = wide && !options_.wide_engines.empty() ? options_.wide_engines : options_.engines;
    ProverResult r = one_after_another(order, owned.problem, limits, options_.engine_work, options_.rounds);
    if (r.verdict == Verdict::Unknown) {
      r.seconds = seconds_since(start);
      if (limits.interrupted()) return interrupted_result(start);
      return r;
    }
    answer = std::move(r);
  }
  if (limits.interrupted()) return interrupted_result(start);
  ProverResult out = confirmed(owned, std::move(*answer), limits, start);
  if (limits.interrupted()) return interrupted_result(start);
  return out;
}

// k-induction as the quick attempt runs it: first with no strengthening at
// all, which settles what holds in every cycle by the cycle's own
// definitions (no Houdini run over the lemmas); then with the lemmas, to
// PortfolioOptions::quick_k. One budget for both.
ProverResult Portfolio::quick_k_induction(const SafetyProblem& problem, const Limits& limits) const {
  KInductionOptions o;
  o.mine_invariants = false;
  o.use_lemmas = false;
  o.max_k = 0;
  ProverResult r = KInduction(o).prove(problem, limits);
  if (r.verdict == Verdict::Unknown && options_.quick_k > 0 && r.reason == UnknownReason::BoundReached) {
    o.use_lemmas = true;
    o.max_k = options_.quick_k;
    const Work spent = r.work;
    r = KInduction(o).prove(problem, limits.with_work(limits.work > spent ? limits.work - spent : 1));
    r.work += spent;
  }
  return r;
}

// Most properties of a matrix are 0- or 1-inductive relative to the
// encoder's range lemmas, or fail within a cycle or two: k-induction with no
// mined invariants answers them at once, before any costlier engine.
std::optional<ProverResult> Portfolio::quick_attempt(const SafetyProblem& problem, const Limits& limits) const {
  const bool wanted = options_.quick_k >= 0 &&
                      std::count(options_.engines.begin(), options_.engines.end(), Method::KInduction) > 0;
  if (!wanted) return std::nullopt;
  const Limits quick = limits.with_work(options_.quick_work);
  ProverResult r = quick_k_induction(problem, quick);
  if (r.verdict == Verdict::Unknown && options_.quick_bmc_depth > options_.quick_k && !limits.interrupted()) {
    Limits bmc = limits.with_work(options_.quick_work).with_depth(std::min(limits.max_depth, options_.quick_bmc_depth));
    r = Bmc{}.prove(problem, bmc);
  }
  if (r.verdict == Verdict::Unknown) return std::nullopt;
  // Its base case is bounded model checking, depth by depth: a
  // counterexample found there is BMC's, a shortest one.
  if (r.verdict == Verdict::Falsified) r.method = Method::Bmc;
  return r;
}

std::optional<ProverResult> Portfolio::localized_attempt(const OwnedProblem& whole, bool wide,
                                                         const Limits& limits) const {
  std::optional<OwnedProblem> local = localize(whole, options_.localize_keep);
  if (!local) return std::nullopt;
  // A narrow problem is tried localized only when that at least halves it:
  // on a small cone of long timers (the compressor's 12 state variables, 9
  // localized) PDR is slower than the ordered engines on the whole.
  if (!wide && 2 * local->problem.ts->statevars().size() > whole.problem.ts->statevars().size()) return std::nullopt;
  ProverResult r = one_after_another(options_.localized_engines, local->problem, limits, options_.localized_work,
                                     options_.localized_rounds);
  if (r.verdict == Verdict::Proved && r.k <= 1 && !r.simple_path) {
    r.localized = true;
    return r;  // re-checked on the whole problem by confirmed()
  }
  if (r.verdict == Verdict::Falsified) {
    if (std::optional<Trace> t = concretize(whole.problem, r.cex)) {
      r.cex = std::move(*t);
      r.localized = true;
      return r;
    }
  }
  return std::nullopt;
}

Work Portfolio::work_of(Method engine, Work each) const {
  return engine == Method::Pdr || engine == Method::AcceleratedBmc ? 2 * each : each;
}

ProverResult Portfolio::one_after_another(const std::vector<Method>& order, const SafetyProblem& problem,
                                          const Limits& limits, Work each, const std::vector<double>& rounds) const {
  for (Method engine : order) make_prover(engine);  // a method that is no engine fails before any work
  ProverResult r;
  r.method = Method::Portfolio;
  std::vector<ProverResult> last(order.size());
  std::vector<bool> done(order.size(), false);  // ended at its bound: asking again gives the same answer
  for (std::size_t round = 0; round < rounds.size(); ++round) {
    const bool final_round = round + 1 == rounds.size();
    for (std::size_t i = 0; i < order.size(); ++i) {
      if (done[i] || limits.interrupted()) continue;
      const Method engine = order[i];
      const Work budget = work_of(engine, each);
      Limits mine = limits.with_work(budget == 0 ? 0 : std::max<Work>(1, static_cast<Work>(budget * rounds[round])));
      if (engine == Method::Bmc) mine.max_depth = std::min(mine.max_depth, options_.bmc_depth);
      ProverResult one = make_prover(engine, options_.max_k)->prove(problem, mine);
      r.work += one.work;
      if (one.verdict != Verdict::Unknown) {
        one.work = r.work;
        // The induction engines' base case is bounded model checking, depth
        // by depth: a counterexample found there is BMC's, a shortest one.
        if (one.verdict == Verdict::Falsified && engine != Method::AcceleratedBmc && engine != Method::Pdr)
          one.method = Method::Bmc;
        return one;
      }
      done[i] = final_round || budget == 0 || one.reason != UnknownReason::WorkLimit;
      last[i] = std::move(one);
    }
  }
  // Nobody decided: the most telling reason is a limit some engine hit;
  // "bound reached" only when every engine reached its bound.
  r.reason = UnknownReason::BoundReached;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const ProverResult& one = last[i];
    r.engines += (r.engines.empty() ? "" : "; ") + std::string(to_string(order[i])) + ": " + one.reason_text() +
                 " at k = " + std::to_string(one.k);
    if (one.reason != UnknownReason::BoundReached && r.reason == UnknownReason::BoundReached) {
      r.reason = one.reason;
      r.detail = one.detail;
    }
  }
  if (limits.interrupted()) r.reason = UnknownReason::TimeLimit;
  return r;
}

// The answer made readable, re-checked in a fresh context and, for a
// counterexample, lifted back to the caller's problem and replayed there.
ProverResult Portfolio::confirmed(OwnedProblem& reduced, ProverResult answer, const Limits& limits,
                                  Clock::time_point start) const {
  if (answer.verdict == Verdict::Falsified && options_.shrink_work > 0) {
    // Readable: every input the violation does not need kept at its
    // preferred value (checker/shrink.hpp), on the reduced problem, where
    // the solver works in integers.
    PreferredValue preferred = options_.preferred;
    if (!preferred) preferred = [](const std::string&) { return std::optional<Value>(Value{}); };
    answer.cex = shrink_trace(reduced.problem, answer.cex, preferred, limits.with_work(options_.shrink_work),
                              options_.shrink_max_cycles);
  }
  const ProblemFactory make = options_.reduce ? reducing(make_) : make_;
  if (answer.verdict == Verdict::Falsified && options_.reduce) {
    // Back to the problem as the caller stated it, and replayed there: a
    // trace that runs there is a counterexample, whatever the reduction did.
    // Only when it does not is the reduced problem's replay asked, to tell
    // an engine's error from the reduction's.
    PooledContext ctx;
    OwnedProblem original = make_(ctx);
    Trace lifted = lift_trace(original.problem, answer.cex);
    if (options_.recheck) {
      try {
        check::replay_counterexample(original.problem, lifted, &limits);
      } catch (const InternalError&) {
        check::recheck(make, answer, &limits);
        throw;
      }
    }
    answer.cex = std::move(lifted);
  } else if (options_.recheck && answer.verdict == Verdict::Proved) {
    // The engines' problem copied into a fresh context, where the proof's
    // obligations are stated afresh for a new solver (checker/translate.hpp).
    PooledContext ctx;
    const OwnedProblem copy = translate(reduced.problem, ctx);
    check::recheck_proof(copy.problem, answer, &limits);
  } else if (options_.recheck) {
    check::recheck(make, answer, &limits);
  }
  answer.seconds = seconds_since(start);
  return answer;
}

}  // namespace cemv::checker
