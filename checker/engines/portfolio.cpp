#include "checker/engines/portfolio.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

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

namespace cemv::checker {

std::unique_ptr<Prover> make_prover(const std::string& name, int max_k) {
  if (name == "bmc") return std::make_unique<Bmc>();
  if (name == "k-induction") {
    KInductionOptions o;
    o.max_k = max_k;
    return std::make_unique<KInduction>(o);
  }
  if (name == "k-induction-plain") {
    // Strengthened by the encoder's lemmas only: for a problem whose own
    // assumptions carry the invariants it needs (cemv response's member
    // lemmas), where the miner would spend the time limit looking for them.
    KInductionOptions o;
    o.max_k = max_k;
    o.mine_invariants = false;
    return std::make_unique<KInduction>(o);
  }
  if (name == "invariants+induction") return make_invariant_prover();
  if (name == "pdr") return std::make_unique<Pdr>();
  if (name == "accelerated-bmc") return std::make_unique<AcceleratedBmc>();
  throw std::invalid_argument("unknown engine " + name);
}

namespace {

const std::vector<std::string> kProofOrder{"k-induction", "invariants+induction", "pdr"};

int proof_rank(const std::string& engine) {
  auto it = std::find(kProofOrder.begin(), kProofOrder.end(), engine);
  return it == kProofOrder.end() ? -1 : static_cast<int>(it - kProofOrder.begin());
}

// One engine's thread and what it reported.
struct Lane {
  std::string engine;
  std::atomic<bool> cancel{false};
  std::optional<ProverResult> result;
  std::exception_ptr error;
  int tier = 0;  // starts once the provers of earlier tiers are done (PortfolioOptions::tiers)
  bool started = false;
  std::thread thread;
};

}  // namespace

// k-induction as the quick attempt runs it: first with no strengthening at
// all, which settles what holds in every cycle by the cycle's own
// definitions (no Houdini run over the lemmas); then with the lemmas, to
// PortfolioOptions::quick_k. The race's k-induction starts the same way, so
// that a quick attempt cut short by its wall-clock budget on a loaded machine
// does not change the answer (method, k, invariant) the race then gives.
ProverResult Portfolio::quick_k_induction(const SafetyProblem& problem, const Limits& limits) const {
  KInductionOptions o;
  o.mine_invariants = false;
  o.use_lemmas = false;
  o.max_k = 0;
  ProverResult r = KInduction(o).prove(problem, limits);
  if (r.verdict == Verdict::Unknown && options_.quick_k > 0 && !limits.over()) {
    o.use_lemmas = true;
    o.max_k = options_.quick_k;
    r = KInduction(o).prove(problem, limits);
  }
  return r;
}

Portfolio::Portfolio(ProblemFactory make, PortfolioOptions options)
    : make_(std::move(make)), options_(std::move(options)) {}

ProverResult Portfolio::run(const Limits& limits) {
  const auto start = std::chrono::steady_clock::now();
  const ProblemFactory make = options_.reduce ? reducing(make_) : make_;
  std::optional<ProverResult> answer;
  if (wants_quick_attempt() || options_.in_order || !options_.wide_engines.empty() || options_.localize_keep) {
    PooledContext ctx;
    OwnedProblem owned = make(ctx);
    answer = quick_attempt(owned.problem, limits);
    const bool wide = owned.problem.ts->statevars().size() > options_.in_order_max_states;
    const std::vector<std::string>* order = nullptr;
    if (wide && !options_.wide_engines.empty()) order = &options_.wide_engines;
    else if (!wide && options_.in_order) order = &options_.engines;
    if (!answer && options_.localize_keep) answer = localized_attempt(owned, wide, limits);
    if (!answer && order) {
      ProverResult r = wide && options_.race_wide && order == &options_.wide_engines
                           ? race(make, *order, limits)
                           : one_after_another(*order, owned.problem, limits);
      if (r.verdict == Verdict::Unknown) {
        r.seconds = seconds_since(start);
        return r;
      }
      answer = std::move(r);
    }
  }
  if (!answer) {
    ProverResult raced = race(make, options_.engines, limits);
    if (raced.verdict == Verdict::Unknown) {
      raced.seconds = seconds_since(start);
      return raced;
    }
    answer = std::move(raced);
  }
  return confirmed(make, std::move(*answer), limits, start);
}

// Most properties of a matrix are 0- or 1-inductive relative to the
// encoder's range lemmas, or fail within a cycle or two: k-induction with no
// mined invariants answers them in one thread and one build, before any
// engine races (PortfolioOptions::quick_k). Its answer is what the race would
// give: the same k-induction proof, or the shortest counterexample, since its
// base case tries every depth in order.
bool Portfolio::wants_quick_attempt() const {
  return options_.quick_k >= 0 &&
         std::find(options_.engines.begin(), options_.engines.end(), "k-induction") != options_.engines.end();
}

std::optional<ProverResult> Portfolio::quick_attempt(const SafetyProblem& problem, const Limits& limits) const {
  if (!wants_quick_attempt()) return std::nullopt;
  Limits quick = limits;
  quick.deadline = std::min(limits.deadline, std::chrono::steady_clock::now() + options_.quick_budget);
  ProverResult r = quick_k_induction(problem, quick);
  if (r.verdict == Verdict::Unknown && options_.quick_bmc_depth > options_.quick_k && !quick.over()) {
    Limits bmc = quick;
    bmc.max_depth = std::min(limits.max_depth, options_.quick_bmc_depth);
    r = Bmc{}.prove(problem, bmc);
  }
  if (r.verdict == Verdict::Unknown) return std::nullopt;
  // Its base case is bounded model checking, depth by depth: a
  // counterexample found there is BMC's, a shortest one.
  if (r.verdict == Verdict::Falsified) r.method = "bmc";
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
  Limits mine = limits;
  const auto now = std::chrono::steady_clock::now();
  if (limits.deadline != std::chrono::steady_clock::time_point::max()) mine.deadline = now + (limits.deadline - now) / 2;
  ProverResult r = one_after_another(options_.localized_engines, local->problem, mine);
  if (r.verdict == Verdict::Proved && r.k <= 1 && !r.simple_path) {
    r.method += ", localized";
    return r;  // re-checked on the whole problem by confirmed()
  }
  if (r.verdict == Verdict::Falsified) {
    if (std::optional<Trace> t = concretize(whole.problem, r.cex)) {
      r.cex = std::move(*t);
      r.method += ", localized";
      return r;
    }
  }
  return std::nullopt;
}

ProverResult Portfolio::one_after_another(const std::vector<std::string>& order, const SafetyProblem& problem,
                                          const Limits& limits) const {
  ProverResult last;
  std::string engines;
  for (const auto& name : order) {
    if (limits.over()) break;
    Limits mine = limits;
    if (name == "bmc") mine.max_depth = std::min(mine.max_depth, options_.bmc_depth);
    last = make_prover(name, options_.max_k)->prove(problem, mine);
    if (last.verdict != Verdict::Unknown) return last;
    engines += (engines.empty() ? "" : "; ") + name + ": " + last.reason + " at k = " + std::to_string(last.k);
  }
  ProverResult r;
  r.method = "portfolio";
  r.reason = limits.over() ? "time limit" : last.reason.empty() ? "bound reached" : last.reason;
  r.engines = engines;
  return r;
}

ProverResult Portfolio::race(const ProblemFactory& make, const std::vector<std::string>& engines,
                             const Limits& limits) const {
  const auto start = std::chrono::steady_clock::now();
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<std::unique_ptr<Lane>> lanes;
  for (const auto& name : engines) {
    make_prover(name);  // unknown names fail here, before any thread starts
    auto lane = std::make_unique<Lane>();
    lane->engine = name;
    lanes.push_back(std::move(lane));
  }
  auto start_lane = [&](Lane* lane) {
    lane->started = true;
    lane->thread = std::thread([&, lane] {
      std::optional<ProverResult> r;
      std::exception_ptr error;
      try {
        PooledContext ctx;
        OwnedProblem owned = make(ctx);
        Limits mine = limits;
        mine.cancel = &lane->cancel;
        if (lane->engine == "bmc") mine.max_depth = std::min(mine.max_depth, options_.bmc_depth);
        if (lane->engine == "k-induction" && options_.quick_k >= 0) {
          r = quick_k_induction(owned.problem, mine);
          if (r->verdict == Verdict::Unknown && !mine.over())
            r = make_prover(lane->engine, options_.max_k)->prove(owned.problem, mine);
        } else {
          r = make_prover(lane->engine, options_.max_k)->prove(owned.problem, mine);
        }
      } catch (...) {
        error = std::current_exception();
      }
      std::lock_guard<std::mutex> lock(mutex);
      lane->result = std::move(r);
      lane->error = error;
      changed.notify_all();
    });
  };
  for (auto& lane : lanes) {
    for (std::size_t t = 0; t < options_.tiers.size(); ++t)
      if (std::count(options_.tiers[t].begin(), options_.tiers[t].end(), lane->engine)) lane->tier = static_cast<int>(t);
    if (lane->tier == 0) start_lane(lane.get());
  }
  auto finished = [](const Lane& l) { return !l.started || l.result.has_value() || l.error; };
  auto find = [&](const std::string& name) -> Lane* {
    for (auto& l : lanes)
      if (l->engine == name) return l.get();
    return nullptr;
  };

  std::optional<ProverResult> answer;
  {
    std::unique_lock<std::mutex> lock(mutex);
    std::vector<std::string> stopped;  // engines cancelled because their answer no longer matters
    for (;;) {
      // A falsification decides; prefer BMC's shortest counterexample.
      Lane* falsifier = nullptr;
      for (auto& l : lanes)
        if (l->result && l->result->verdict == Verdict::Falsified) {
          falsifier = l.get();
          break;
        }
      if (falsifier) {
        Lane* bmc = find("bmc");
        for (auto& l : lanes)
          if (l.get() != bmc) l->cancel = true;
        if (falsifier == bmc || !bmc) {
          answer = falsifier->result;
          break;
        }
        if (bmc->result && bmc->result->verdict == Verdict::Falsified) {
          answer = bmc->result;
          break;
        }
        const bool bmc_can_reach = static_cast<int>(falsifier->result->cex.length()) - 1 <=
                                   std::min(limits.max_depth, options_.bmc_depth);
        if (!bmc_can_reach || finished(*bmc)) {
          bmc->cancel = true;
          answer = falsifier->result;
          break;
        }
        changed.wait(lock);
        continue;
      }
      // A proof decides once every engine preferred to it has finished.
      std::optional<int> best;
      for (auto& l : lanes) {
        int rank = proof_rank(l->engine);
        if (l->result && l->result->verdict == Verdict::Proved && rank >= 0 && (!best || rank < *best)) best = rank;
      }
      if (best) {
        bool waiting = false;
        for (auto& l : lanes) {
          int rank = proof_rank(l->engine);
          if (rank >= 0 && rank < *best && !finished(*l)) waiting = true;
          else if (rank < 0 || rank > *best) l->cancel = true;
        }
        if (!waiting) {
          answer = find(kProofOrder[*best])->result;
          break;
        }
      }
      bool errors = false;
      // The slower engines join when the quick ones are done without an
      // answer, or after a grace period: an easy property is decided on two
      // cores without five threads competing for them.
      // Tier t starts when every prover of the earlier tiers has finished
      // (BMC runs on: it is the falsifier), or t grace periods after the start.
      int open_tier = 0;
      const auto now = std::chrono::steady_clock::now();
      for (int t = 1; t < static_cast<int>(options_.tiers.size()); ++t) {
        bool earlier_done = true;
        for (auto& l : lanes)
          if (l->tier < t && l->engine != "bmc" && !finished(*l)) earlier_done = false;
        if (earlier_done || now - start >= t * options_.grace) open_tier = t;
        else break;
      }
      for (auto& l : lanes)
        if (l->tier <= open_tier && !l->started && !l->cancel) start_lane(l.get());
      const bool grace_over = open_tier + 1 >= static_cast<int>(options_.tiers.size());
      if (std::all_of(lanes.begin(), lanes.end(), [&](const auto& l) { return l->started && finished(*l); }))
        break;
      for (auto& l : lanes) errors = errors || l->error;
      if (errors) break;
      changed.wait_until(lock, grace_over ? limits.deadline : start + (open_tier + 1) * options_.grace);
    }
    for (auto& l : lanes) l->cancel = true;
  }
  for (auto& l : lanes)
    if (l->started) l->thread.join();
  for (auto& l : lanes)
    if (l->error) {
      try {
        std::rethrow_exception(l->error);
      } catch (const std::exception& e) {
        throw InternalError("engine " + l->engine + " failed: " + e.what());
      }
    }
  // Two engines contradicting each other means one of them (or Z3) is wrong.
  for (auto& l : lanes)
    if (answer && l->result && l->result->verdict != Verdict::Unknown && l->result->verdict != answer->verdict)
      throw InternalError("engines disagree: " + answer->method + " says " + to_string(answer->verdict) + ", " +
                          l->engine + " says " + to_string(l->result->verdict));
  if (!answer) {
    // Nobody decided: say why, the most telling reason first.
    ProverResult r;
    r.method = "portfolio";
    bool memory = false, all_bounds = true;
    for (auto& l : lanes) {
      if (!l->result) continue;
      memory = memory || l->result->reason == "memory limit";
      all_bounds = all_bounds && l->result->reason == "bound reached";
    }
    r.reason = limits.over() ? "time limit" : memory ? "memory limit" : all_bounds ? "bound reached" : "time limit";
    for (auto& l : lanes) {
      if (!r.engines.empty()) r.engines += "; ";
      r.engines += l->engine + ": ";
      if (!l->started) r.engines += "not started";
      else if (l->result) r.engines += l->result->reason + " at k = " + std::to_string(l->result->k);
      else r.engines += "no answer";
    }
    r.seconds = seconds_since(start);
    return r;
  }
  return *answer;
}

// The answer made readable, re-checked in a fresh context and, for a
// counterexample, lifted back to the caller's problem and replayed there.
ProverResult Portfolio::confirmed(const ProblemFactory& make, ProverResult answer, const Limits& limits,
                                  std::chrono::steady_clock::time_point start) const {
  if (answer.verdict == Verdict::Falsified && options_.shrink_budget.count() > 0) {
    // Readable: every input the violation does not need kept at its
    // preferred value (checker/shrink.hpp), on the reduced problem, where
    // the solver works in integers.
    PooledContext ctx;
    OwnedProblem owned = make(ctx);
    Limits shrink_limits = limits;
    shrink_limits.deadline = std::min(limits.deadline, std::chrono::steady_clock::now() + options_.shrink_budget);
    shrink_limits.cancel = nullptr;
    PreferredValue preferred = options_.preferred;
    if (!preferred) preferred = [](const std::string&) { return std::optional<Value>(Value{}); };
    answer.cex = shrink_trace(owned.problem, answer.cex, preferred, shrink_limits, options_.shrink_max_cycles);
  }
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
        check::replay_counterexample(original.problem, lifted);
      } catch (const InternalError&) {
        check::recheck(make, answer);
        throw;
      }
    }
    answer.cex = std::move(lifted);
  } else if (options_.recheck) {
    check::recheck(make, answer);
  }
  answer.seconds = seconds_since(start);
  return answer;
}

}  // namespace cemv::checker
