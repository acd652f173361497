#include "response/search.hpp"

#include <algorithm>

#include "response/demand.hpp"
#include "response/probe.hpp"

namespace cemv::response {

namespace {

// The longest run tried before the engines: 100,000 cycles (a 30 min timer
// at 100 ms is 18,000).
constexpr long long kMaxDirectedRunCycles = 100000;

}  // namespace

std::string property_name(const Path& p, Mode mode) {
  return "response." + p.key() + (mode == Mode::Degraded ? ".degraded" : "");
}

long long search_cap(const Path& p) { return 2 * p.estimate + 64; }

// Probes in this order: the estimate E; then E - 1 (when E is proved) or
// E + 1 and the cap 2E + 64 (when E is falsified); then bisection between the
// largest falsified and the smallest proved bound. The largest falsified
// bound only grows, so the last scenario the checker writes for the
// property's name is that of T - 1.
Figure least_response(const model::Matrix& m, const Path& p, Mode mode, const SearchOptions& o) {
  Figure f;
  long long lo = -1;  // largest bound falsified (-1: none needed below 0)
  long long hi = -1;  // smallest bound proved or vacuous (-1: none yet)
  // Whether `hi` was vacuous: no demand can be held for hi + 1 cycles. Then
  // every larger bound is vacuous too, while a bound below may be proved.
  bool hi_vacuous = false;
  std::string vacuous_reason;
  std::string lo_scenario;
  std::vector<model::CycleInput> lo_run;  // the counterexample to `lo`
  const long long cap = search_cap(p);
  auto probe = [&](long long t, Expect e) -> bool {  // false: stop (unknown)
    Runs runs;
    // Every cycle of a run is held in memory (its inputs and, once run, every
    // observable): beyond kMaxDirectedRunCycles the engines decide alone.
    if (t < kMaxDirectedRunCycles) runs = demand_runs(m, p, mode, t);
    // A path held off beyond `lo` by what its counterexample did (a state
    // the demand alone does not reach) is often held off longer still: that
    // run with its last inputs held for the t - lo cycles more that a
    // violation of "within t" needs. Unbounded paths are then shown at the
    // cap by one run of the runtime.
    if (!lo_run.empty() && t > lo && t < kMaxDirectedRunCycles) {
      runs.push_back(lo_run);
      runs.back().resize(lo_run.size() + static_cast<std::size_t>(t - lo), lo_run.back());
    }
    Probe r = decide_probe(m, p, mode, t, o, e, runs);
    ++f.probes;
    switch (r.verdict) {
      case checker::PropertyVerdict::Proved:
        hi = t;
        hi_vacuous = false;
        f.method = r.method;
        return true;
      case checker::PropertyVerdict::Falsified:
        lo = t;
        lo_scenario = r.scenario;
        lo_run = std::move(r.run);
        return true;
      case checker::PropertyVerdict::Vacuous:
        hi = t;
        hi_vacuous = true;
        vacuous_reason = r.reason;
        return true;
      default:
        f.reason = r.reason.empty() ? "not decided" : r.reason;
        return false;
    }
  };
  const long long first = std::min(p.estimate, cap);
  if (!probe(first, Expect::Proof)) return f;
  if (hi == first) {
    if (first > 0 && !probe(first - 1, Expect::Counterexample)) return f;
  } else {
    if (!probe(first + 1, Expect::Either)) return f;
    if (hi < 0 && first + 1 < cap && !probe(cap, Expect::Either)) return f;
    if (hi < 0) {
      f.kind = Figure::Kind::Unbounded;
      f.cycles = lo;
      f.counterexample = lo_scenario;
      return f;
    }
  }
  while (hi - lo > 1) {
    long long mid = lo + (hi - lo) / 2;
    if (!probe(mid, Expect::Either)) return f;
  }
  if (hi_vacuous && lo < 0) {  // no demand at all (docs/response-time.md, "Vacuous paths")
    f.reason = "vacuous: " + vacuous_reason;
    return f;
  }
  if (hi_vacuous) {
    // A demand lasts at most lo + 1 cycles, and lo's counterexample shows
    // one that long without a response: the path never responds to a demand
    // that can be held.
    f.kind = Figure::Kind::Unbounded;
    f.cycles = lo;
    f.counterexample = lo_scenario;
    f.reason = "its demand cannot last longer than " + std::to_string(lo + 1) +
               " cycles: the logic then bypasses or inhibits an element of the path";
    return f;
  }
  f.kind = Figure::Kind::Exact;
  f.cycles = hi;
  f.counterexample = lo >= 0 ? lo_scenario : "";
  return f;
}

}  // namespace cemv::response
