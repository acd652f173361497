#include "response/probe.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>
#include <set>
#include <stdexcept>

#include "checker/check.hpp"
#include "checker/engines/portfolio.hpp"

namespace cemv::response {

namespace {

using checker::Clock;
using checker::Method;

// The engines a probe asks, in order: `narrow` on a problem of at most 64
// state variables after the checker's reductions, `wide` on a wider one
// (checker::CheckOptions::engines_when_wide; empty: `narrow` there too).
// Both empty: the portfolio's default order.
struct Engines {
  std::vector<Method> narrow, wide;
};

// The probe's wall clock (--timeout), shared by its checks: it only
// interrupts, and a probe it interrupted anywhere is unknown, so that no
// figure depends on the machine.
struct ProbeClock {
  double limit_s = 0.0;
  Clock::time_point start = Clock::now();
  // Seconds left for the next check (0: no limit); nullopt when none are.
  std::optional<double> left() const {
    if (limit_s <= 0) return 0.0;
    const double l = limit_s - std::chrono::duration<double>(Clock::now() - start).count();
    if (l < 0.001) return std::nullopt;
    return l;
  }
  bool over() const { return limit_s > 0 && !left(); }
};

Probe time_limit() {
  Probe none;
  none.reason = checker::to_string(checker::UnknownReason::TimeLimit);
  return none;
}

// The answer for the file's one property.
Probe check_one(const model::Matrix& m, const properties::PropertyFile& file, const checker::CheckOptions& options) {
  checker::CheckResult r = checker::check_properties(m, {file}, options);
  Probe out;
  const checker::PropertyResult& pr = r.properties.at(0);
  out.verdict = pr.verdict;
  out.reason = pr.reason;
  out.method = pr.method;
  if (!pr.scenario_file.empty()) out.scenario = std::filesystem::path(pr.scenario_file).filename().string();
  if (pr.verdict == checker::PropertyVerdict::Falsified && pr.trace) out.run = pr.trace->inputs;
  return out;
}

checker::CheckOptions probe_options(const SearchOptions& o, const Engines& engines, const Runs& runs,
                                    checker::Work work, double seconds) {
  checker::CheckOptions options;
  options.property_timeout_s = seconds;
  options.cancel = o.cancel;
  options.jobs = 1;
  options.out_dir = o.out_dir;
  options.support = false;
  options.budgets.engine = work;
  options.engines = engines.narrow;
  options.engines_when_wide = engines.wide;
  // The runs first: where one shows the bound too short, no engine is
  // needed; where none does, they still witness that the trigger can rise
  // (the proof's vacuity question).
  options.directed_runs = runs;
  return options;
}

Probe decide(const model::Matrix& m, const Path& p, Mode mode, long long cycles, const SearchOptions& o,
             const Engines& engines, const Runs& runs, bool localize, double seconds) {
  const std::string name = property_name(p, mode);
  checker::CheckOptions options = probe_options(o, engines, runs, o.work, seconds);
  // A cone is mostly other elements that can only make the effect respond
  // sooner (other causes, the effects their references read): a proof on
  // the path's own elements, the rest left free, is re-checked on the whole
  // cone (checker::CheckOptions::localize_to; tried on a wide cone, and on a
  // narrow one when that halves it).
  if (localize) options.localize_to = p.elements;
  // The accelerated unrolling's trace holds its inputs over at most 8 macro
  // steps: readable as it is, and the core-guided search over 33 to 64
  // cycles was most of the CPU of such a probe (compressor: 2 s of 2.2 s).
  if (engines.narrow == std::vector<Method>{Method::AcceleratedBmc}) options.shrink_max_cycles = 0;
  return check_one(m, response_property(m, p, mode, cycles, name), options);
}

// The deepest induction over an XooN bound's member lemmas: an effect's
// output delay of up to about a second at 100 ms cycles.
constexpr long long kMaxMemberLemmaK = 12;

// An XooN bound from its member lemmas (response/property.hpp, member_lemmas;
// docs/response-time.md, "Compositional proof"), the lemmas each within a
// quarter of a probe's budget, the bound within half of it: the lemmas first, then the bound assuming those proved, by
// k-induction with the encoder's lemmas only. The member lemmas are what the
// miner would otherwise have to find: an induction over eleven `held`
// counters and their causes' timers (big_matrix's 4oo11 into effect 17: no
// engine within 60 s) becomes one over the effect's own delays (1.7 s). A
// counterexample of the bound assuming them is one of the bound: the lemmas
// hold in every run the bound judges. Nullopt when it decides nothing: no
// lemma proved, or the bound neither proved nor refuted.
std::optional<Probe> decide_from_member_lemmas(const model::Matrix& m, const Path& p, Mode mode, long long cycles,
                                               const SearchOptions& o, const ProbeClock& clock, const Runs& runs) {
  const std::string name = property_name(p, mode);
  const std::optional<MemberLemmas> lemmas = member_lemmas(m, p, mode, cycles, name + ".members");
  if (!lemmas) return std::nullopt;
  std::optional<double> left = clock.left();
  if (!left) return std::nullopt;
  // Each lemma is a small cone (a cause's inputs, timers and `held`
  // counter): a quarter of the budget each is plenty (PDR proves
  // big_matrix's slowest, cause 107 with its bypass through effect 18, in
  // about a second).
  checker::CheckOptions options =
      probe_options(o, {{Method::InvariantsInduction, Method::Pdr, Method::KInduction}, {}}, {}, o.work / 4, *left);
  options.out_dir.clear();  // a lemma's counterexample is no figure's
  // A vacuous lemma (its assumptions unsatisfiable) constrains no run the
  // bound judges: the bound states those assumptions too.
  options.vacuity = false;
  checker::CheckResult proved = checker::check_properties(m, {lemmas->file}, options);
  std::vector<properties::Expr> assumed;
  std::set<std::string> methods;
  long long slowest = 0;  // the longest on-delay among the members proved
  for (std::size_t i = 0; i < lemmas->names.size(); ++i) {
    const checker::PropertyResult& r = proved.properties.at(i);
    if (r.verdict != checker::PropertyVerdict::Proved) continue;
    assumed.push_back(lemmas->terms[i]);
    methods.insert(r.method);
    slowest = std::max(slowest, lemmas->delays[i]);
  }
  if (assumed.empty()) return std::nullopt;
  left = clock.left();
  if (!left) return std::nullopt;
  // In a violation, every member of the set has been active for at least
  // the last `cycles` - `slowest` cycles: the induction needs to reach back
  // over those and the cycle before (and no further when the bound is
  // tight, since then they are the effect's own delays).
  const std::vector<Method> plain{Method::KInductionPlain};
  // The demand runs again: none violates the bound (decide() tried them),
  // but they witness that its demand can be held (the vacuity question).
  checker::CheckOptions bound_options = probe_options(o, {plain, plain}, runs, o.work / 2, *left);
  bound_options.max_k = static_cast<int>(std::min<long long>(kMaxMemberLemmaK, cycles - slowest + 2));
  Probe bound = check_one(m, response_property(m, p, mode, cycles, name, assumed), bound_options);
  if (bound.verdict == checker::PropertyVerdict::Proved) {
    std::string how;
    for (const auto& x : methods) how += (how.empty() ? "" : ", ") + x;
    bound.method += ", from member lemmas (" + how + ")";
    return bound;
  }
  // Falsified, or vacuous (no demand can be held that long): the lemmas hold
  // in every run the bound judges, so assuming them changes neither.
  if (bound.verdict == checker::PropertyVerdict::Falsified || bound.verdict == checker::PropertyVerdict::Vacuous)
    return bound;
  return std::nullopt;
}

// The engines that can give the expected answer, asked one after another in
// the probe's thread: probes run in parallel over paths, so a probe needs no
// threads of its own, and one encoding serves all its engines. A proof of T:
// the quick k-induction (k <= 1, the portfolio's quick attempt), then
// invariants+induction, which proves a timer's bound in one strengthened step
// whatever its length, then k-induction to k = 10, then BMC (a guess too low
// that the demand run did not show). On a wide cone PDR, then BMC: there the
// relational miner spends its whole budget at k = 0, and PDR proves a short
// bound at once, while a guess too low that needs a preamble (an effect
// latched at start-up released first) is BMC's (big_matrix's cause 9 ->
// effect 61 at depth 18; effect 127 at T = 0). A counterexample to T - 1
// (when the demand run did not show one): BMC, whose trace is a shortest one,
// and the accelerated unrolling; above BMC's depth the accelerated unrolling
// alone (a violation of "within b cycles" takes at least b + 1 cycles).
Engines engines_for(Expect e, long long bound) {
  switch (e) {
    case Expect::Proof:
      return {{Method::InvariantsInduction, Method::KInduction, Method::Bmc}, {Method::Pdr, Method::Bmc}};
    case Expect::Counterexample:
      if (bound > checker::PortfolioOptions{}.bmc_depth) return {{Method::AcceleratedBmc}, {}};
      return {{Method::Bmc, Method::AcceleratedBmc}, {}};
    // Either answer: the portfolio's order; on a wide cone PDR, then BMC.
    case Expect::Either: return {{}, {Method::Pdr, Method::Bmc}};
  }
  return {};
}

Probe decide_probe_within(const model::Matrix& m, const Path& p, Mode mode, long long cycles, const SearchOptions& o,
                          Expect e, const Runs& runs, const ProbeClock& clock) {
  const Engines engines = engines_for(e, cycles);
  // An XooN bound that may hold: first the demand runs alone (they show a
  // bound too short in milliseconds), then from its member lemmas.
  if (e != Expect::Counterexample && p.causes.size() > 1) {
    if (!runs.empty()) {
      const std::optional<double> left = clock.left();
      if (!left) return time_limit();
      checker::CheckOptions only = probe_options(o, engines, runs, o.work, *left);
      only.directed_runs_only = true;
      const std::string name = property_name(p, mode);
      Probe r = check_one(m, response_property(m, p, mode, cycles, name), only);
      if (r.verdict == checker::PropertyVerdict::Falsified) return r;
    }
    if (auto r = decide_from_member_lemmas(m, p, mode, cycles, o, clock, runs)) return *r;
  }
  std::optional<double> left = clock.left();
  if (!left) return time_limit();
  Probe r = decide(m, p, mode, cycles, o, engines, runs, e != Expect::Counterexample, *left);
  if (r.verdict != checker::PropertyVerdict::Unknown || (engines.narrow.empty() && engines.wide.empty())) return r;
  left = clock.left();
  if (!left) return r;
  return decide(m, p, mode, cycles, o, Engines{}, runs, false, *left);
}

}  // namespace

Probe decide_probe(const model::Matrix& m, const Path& p, Mode mode, long long cycles, const SearchOptions& o,
                   Expect e, const Runs& runs) {
  const ProbeClock clock{o.timeout_s};
  Probe r = decide_probe_within(m, p, mode, cycles, o, e, runs, clock);
  // Interrupted anywhere: the figure would depend on the machine.
  return clock.over() ? time_limit() : r;
}

}  // namespace cemv::response
