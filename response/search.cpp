#include "response/search.hpp"

#include <chrono>
#include <filesystem>
#include <stdexcept>

#include "checker/check.hpp"
#include "checker/engines/portfolio.hpp"
#include "formats/diagnostics.hpp"
#include "properties/parser.hpp"
#include "response/demand.hpp"

namespace cemv::response {

namespace {

struct Probe {
  checker::PropertyVerdict verdict = checker::PropertyVerdict::Unknown;
  std::string reason;
  std::string method;
  std::string scenario;
  std::vector<model::CycleInput> run;  // Falsified: the counterexample's inputs, as replayed
};

// Runs the checker tries before its engines (checker::CheckOptions::
// directed_runs): the demand run, and the counterexample of a smaller bound
// continued with its last inputs held.
using Runs = std::vector<std::vector<model::CycleInput>>;

// The engines a probe asks, in order: `narrow` on a problem of at most 64
// state variables after the checker's reductions, `wide` on a wider one
// (checker::CheckOptions::engines_when_wide; empty: `narrow` raced there).
// Both empty: the whole portfolio, raced.
struct Engines {
  std::vector<std::string> narrow, wide;
};

Probe decide(const model::Matrix& m, const Path& p, Mode mode, long long cycles, const SearchOptions& o,
             const Engines& engines, const Runs& runs, bool localize) {
  const std::string name = property_name(p, mode);
  const std::string text = response_property_text(m, p, mode, cycles, name);
  properties::PropertyFile file;
  try {
    file = properties::parse_properties(text, m, "cemv-response:" + name);
  } catch (const formats::LoadError& e) {
    // cemv wrote this text: a parse error is cemv's fault, not the input's.
    std::string what;
    for (const auto& i : e.issues()) what += "\n" + i.str();
    throw std::logic_error("cemv response wrote a property the parser refuses:" + what + "\n" + text);
  }
  checker::CheckOptions options;
  options.property_timeout_s = o.timeout_s;
  options.jobs = 1;
  options.out_dir = o.out_dir;
  options.support = false;
  options.engines = engines.narrow;
  options.engines_when_wide = engines.wide;
  options.engines_in_order = !engines.narrow.empty();
  // The runs first: where one shows the bound too short, no engine is
  // needed; where none does, they still witness that the trigger can rise
  // (the proof's vacuity question).
  options.directed_runs = runs;
  // A cone is mostly other elements that can only make the effect respond
  // sooner (other causes, the effects their references read): a proof on
  // the path's own elements, the rest left free, is re-checked on the whole
  // cone (checker::CheckOptions::localize_to; tried on a wide cone, and on a
  // narrow one when that halves it).
  if (localize) options.localize_to = p.elements;
  // The accelerated unrolling's trace holds its inputs over at most 8 macro
  // steps: readable as it is, and the core-guided search over 33 to 64
  // cycles was most of the CPU of such a probe (compressor: 2 s of 2.2 s).
  if (engines.narrow == std::vector<std::string>{"accelerated-bmc"}) options.shrink_max_cycles = 0;
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

// What a probe expects, from the search's state: the estimate and the bounds
// above a falsified one are expected to be proved, the bound below a proved
// one to be falsified; a bisection step may go either way.
enum class Expect { Proof, Counterexample, Either };

// The engines that can give the expected answer, asked one after another in
// the probe's thread (checker::CheckOptions::engines_in_order): probes run in
// parallel over paths, so a probe needs no threads of its own, and one
// encoding serves all its engines. A proof of T: the quick k-induction (k <= 1,
// the portfolio's quick attempt), then invariants+induction, which proves a
// timer's bound in one strengthened step whatever its length, then
// k-induction to k = 10, then BMC (a guess too low that the demand run did
// not show). On a wide cone PDR alone: there the relational miner takes the
// whole time limit at k = 0, and PDR proves a short bound, or falsifies a
// guess too low, in seconds. A counterexample to T - 1 (when the demand run
// did not show one): BMC, whose trace is a shortest one, and the accelerated
// unrolling; above BMC's depth the accelerated unrolling alone (a violation
// of "within b cycles" takes at least b + 1 cycles); raced on a wide cone.
Engines engines_for(Expect e, long long bound) {
  switch (e) {
    case Expect::Proof: return {{"invariants+induction", "k-induction", "bmc"}, {"pdr"}};
    case Expect::Counterexample:
      if (bound > checker::PortfolioOptions{}.bmc_depth) return {{"accelerated-bmc"}, {}};
      return {{"bmc", "accelerated-bmc"}, {}};
    // Either answer: the whole portfolio, raced; on a wide cone PDR, which
    // gives either (the race would hold a PDR proof until invariants+
    // induction, earlier in its order, has used the whole time limit).
    case Expect::Either: return {{}, {"pdr"}};
  }
  return {};
}

// The longest run tried before the engines: 100,000 cycles (a 30 min timer
// at 100 ms is 18,000).
constexpr long long kMaxDirectedRunCycles = 100000;

// One probe: first with the engines for the expected answer; when they give
// none, the whole portfolio is asked, within what is left of the probe's
// time limit (--timeout is a hard limit per probe: none left, the probe is
// unknown).
Probe decide(const model::Matrix& m, const Path& p, Mode mode, long long cycles, const SearchOptions& o,
             Expect e, const Runs& runs) {
  const Engines engines = engines_for(e, cycles);
  const auto start = std::chrono::steady_clock::now();
  Probe r = decide(m, p, mode, cycles, o, engines, runs, e != Expect::Counterexample);
  if (r.verdict != checker::PropertyVerdict::Unknown || (engines.narrow.empty() && engines.wide.empty())) return r;
  SearchOptions rest = o;
  if (o.timeout_s > 0) {
    rest.timeout_s = o.timeout_s - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (rest.timeout_s < 0.001) return r;
  }
  return decide(m, p, mode, cycles, rest, Engines{}, runs, false);
}

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
  long long hi = -1;  // smallest bound proved (-1: none yet)
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
    Probe r = decide(m, p, mode, t, o, e, runs);
    ++f.probes;
    switch (r.verdict) {
      case checker::PropertyVerdict::Proved:
        hi = t;
        f.method = r.method;
        return true;
      case checker::PropertyVerdict::Falsified:
        lo = t;
        lo_scenario = r.scenario;
        lo_run = std::move(r.run);
        return true;
      case checker::PropertyVerdict::Vacuous:
        f.reason = "vacuous: " + r.reason;
        return false;
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
  f.kind = Figure::Kind::Exact;
  f.cycles = hi;
  f.counterexample = lo >= 0 ? lo_scenario : "";
  return f;
}

}  // namespace cemv::response
