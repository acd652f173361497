#include "response/probe.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>
#include <set>
#include <stdexcept>

#include "checker/check.hpp"
#include "checker/engines/portfolio.hpp"
#include "formats/diagnostics.hpp"
#include "properties/parser.hpp"

namespace cemv::response {

namespace {

// The engines a probe asks, in order: `narrow` on a problem of at most 64
// state variables after the checker's reductions, `wide` on a wider one
// (checker::CheckOptions::engines_when_wide; empty: `narrow` raced there).
// Both empty: the whole portfolio, raced.
struct Engines {
  std::vector<std::string> narrow, wide;
  bool race_wide = false;  // `wide` raced (checker::CheckOptions::race_when_wide), not in order
};

// What is left of a time limit of `limit` seconds that started at `start`:
// 0 for no limit; nullopt when (next to) nothing is left, since --timeout is
// a hard limit per probe.
std::optional<double> time_left(double limit, std::chrono::steady_clock::time_point start) {
  if (limit <= 0) return 0.0;
  const double left = limit - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (left < 0.001) return std::nullopt;
  return left;
}

// A property file's text decided by the checker with `options`.
checker::CheckResult check_text(const model::Matrix& m, const std::string& name, const std::string& text,
                                const checker::CheckOptions& options) {
  properties::PropertyFile file;
  try {
    file = properties::parse_properties(text, m, "cemv-response:" + name);
  } catch (const formats::LoadError& e) {
    // cemv wrote this text: a parse error is cemv's fault, not the input's.
    std::string what;
    for (const auto& i : e.issues()) what += "\n" + i.str();
    throw std::logic_error("cemv response wrote a property the parser refuses:" + what + "\n" + text);
  }
  return checker::check_properties(m, {file}, options);
}

// The answer for the text's one property.
Probe check_one(const model::Matrix& m, const std::string& name, const std::string& text,
                const checker::CheckOptions& options) {
  checker::CheckResult r = check_text(m, name, text, options);
  Probe out;
  const checker::PropertyResult& pr = r.properties.at(0);
  out.verdict = pr.verdict;
  out.reason = pr.reason;
  out.method = pr.method;
  if (!pr.scenario_file.empty()) out.scenario = std::filesystem::path(pr.scenario_file).filename().string();
  if (pr.verdict == checker::PropertyVerdict::Falsified && pr.trace) out.run = pr.trace->inputs;
  return out;
}

checker::CheckOptions probe_options(const SearchOptions& o, const Engines& engines, const Runs& runs) {
  checker::CheckOptions options;
  options.property_timeout_s = o.timeout_s;
  options.jobs = 1;
  options.out_dir = o.out_dir;
  options.support = false;
  options.engines = engines.narrow;
  options.engines_when_wide = engines.wide;
  options.engines_in_order = !engines.narrow.empty();
  options.race_when_wide = engines.race_wide;
  // The runs first: where one shows the bound too short, no engine is
  // needed; where none does, they still witness that the trigger can rise
  // (the proof's vacuity question).
  options.directed_runs = runs;
  return options;
}

Probe decide(const model::Matrix& m, const Path& p, Mode mode, long long cycles, const SearchOptions& o,
             const Engines& engines, const Runs& runs, bool localize) {
  const std::string name = property_name(p, mode);
  checker::CheckOptions options = probe_options(o, engines, runs);
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
  return check_one(m, name, response_property_text(m, p, mode, cycles, name), options);
}

// The deepest induction over an XooN bound's member lemmas: an effect's
// output delay of up to about a second at 100 ms cycles.
constexpr long long kMaxMemberLemmaK = 12;

// An XooN bound from its member lemmas (response/property.hpp, member_lemmas;
// docs/response-time.md, "Compositional proof"), within `seconds` (0: no
// limit): the lemmas first, then the bound assuming those proved, by
// k-induction with the encoder's lemmas only. The member lemmas are what the
// miner would otherwise have to find: an induction over eleven `held`
// counters and their causes' timers (big_matrix's 4oo11 into effect 17: no
// engine within 60 s) becomes one over the effect's own delays (1.7 s). A
// counterexample of the bound assuming them is one of the bound: the lemmas
// hold in every run the bound judges. Nullopt when it decides nothing: no
// lemma proved, or the bound neither proved nor refuted.
std::optional<Probe> decide_from_member_lemmas(const model::Matrix& m, const Path& p, Mode mode, long long cycles,
                                               const SearchOptions& o, double seconds, const Runs& runs) {
  const std::string name = property_name(p, mode);
  const std::optional<MemberLemmas> lemmas = member_lemmas(m, p, mode, cycles, name + ".members");
  if (!lemmas) return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  SearchOptions mine = o;
  // Each lemma is a small cone (a cause's inputs, timers and `held`
  // counter): a quarter of the time each is plenty (PDR proves big_matrix's
  // slowest, cause 107 with its bypass through effect 18, in about a second).
  mine.timeout_s = seconds / 4;
  checker::CheckOptions options = probe_options(mine, {{"invariants+induction", "pdr", "k-induction"}, {}}, {});
  options.out_dir.clear();  // a lemma's counterexample is no figure's
  // A vacuous lemma (its assumptions unsatisfiable) constrains no run the
  // bound judges: the bound states those assumptions too.
  options.vacuity = false;
  checker::CheckResult proved = check_text(m, name + ".members", lemmas->property_text, options);
  std::vector<std::string> assumed;
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
  const std::optional<double> left = time_left(seconds, start);
  if (!left) return std::nullopt;
  mine.timeout_s = *left;
  // In a violation, every member of the set has been active for at least
  // the last `cycles` - `slowest` cycles: the induction needs to reach back
  // over those and the cycle before (and no further when the bound is
  // tight, since then they are the effect's own delays).
  const std::vector<std::string> plain{"k-induction-plain"};
  // The demand runs again: none violates the bound (decide() tried them),
  // but they witness that its demand can be held (the vacuity question).
  checker::CheckOptions bound_options = probe_options(mine, {plain, plain}, runs);
  bound_options.max_k = static_cast<int>(std::min<long long>(kMaxMemberLemmaK, cycles - slowest + 2));
  Probe bound = check_one(m, name, response_property_text(m, p, mode, cycles, name, assumed), bound_options);
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
// the probe's thread (checker::CheckOptions::engines_in_order): probes run in
// parallel over paths, so a probe needs no threads of its own, and one
// encoding serves all its engines. A proof of T: the quick k-induction (k <= 1,
// the portfolio's quick attempt), then invariants+induction, which proves a
// timer's bound in one strengthened step whatever its length, then
// k-induction to k = 10, then BMC (a guess too low that the demand run did
// not show). On a wide cone PDR raced against BMC: there the relational
// miner takes the whole time limit at k = 0, and PDR proves a short bound in
// seconds, while a guess too low that needs a preamble (an effect latched at
// start-up released first) takes PDR minutes and BMC seconds (big_matrix's
// cause 9 -> effect 61: PDR 80 s, BMC 10 s at depth 18; effect 127 at
// T = 0: 7.8 s and 0.6 s). A counterexample to T - 1 (when the demand run
// did not show one): BMC, whose trace is a shortest one, and the accelerated
// unrolling; above BMC's depth the accelerated unrolling alone (a violation
// of "within b cycles" takes at least b + 1 cycles); raced on a wide cone.
Engines engines_for(Expect e, long long bound) {
  switch (e) {
    case Expect::Proof: return {{"invariants+induction", "k-induction", "bmc"}, {"pdr", "bmc"}, true};
    case Expect::Counterexample:
      if (bound > checker::PortfolioOptions{}.bmc_depth) return {{"accelerated-bmc"}, {}};
      return {{"bmc", "accelerated-bmc"}, {}};
    // Either answer: the whole portfolio, raced; on a wide cone PDR against
    // BMC (the whole race would hold a PDR proof until invariants+induction,
    // earlier in its order, has used the whole time limit).
    case Expect::Either: return {{}, {"pdr", "bmc"}, true};
  }
  return {};
}

}  // namespace

Probe decide_probe(const model::Matrix& m, const Path& p, Mode mode, long long cycles, const SearchOptions& o,
                   Expect e, const Runs& runs) {
  const Engines engines = engines_for(e, cycles);
  const auto start = std::chrono::steady_clock::now();
  // An XooN bound that may hold: first the demand runs alone (they show a
  // bound too short in milliseconds), then from its member lemmas, within
  // half of the probe's time.
  if (e != Expect::Counterexample && p.causes.size() > 1) {
    if (!runs.empty()) {
      checker::CheckOptions only = probe_options(o, engines, runs);
      only.directed_runs_only = true;
      const std::string name = property_name(p, mode);
      Probe r = check_one(m, name, response_property_text(m, p, mode, cycles, name), only);
      if (r.verdict == checker::PropertyVerdict::Falsified) return r;
    }
    if (auto r = decide_from_member_lemmas(m, p, mode, cycles, o, o.timeout_s / 2, runs)) return *r;
  }
  SearchOptions rest = o;
  std::optional<double> left = time_left(o.timeout_s, start);
  if (!left) {
    Probe none;
    none.reason = "time limit";
    return none;
  }
  rest.timeout_s = *left;
  Probe r = decide(m, p, mode, cycles, rest, engines, runs, e != Expect::Counterexample);
  if (r.verdict != checker::PropertyVerdict::Unknown || (engines.narrow.empty() && engines.wide.empty())) return r;
  left = time_left(o.timeout_s, start);
  if (!left) return r;
  rest.timeout_s = *left;
  return decide(m, p, mode, cycles, rest, Engines{}, runs, false);
}

}  // namespace cemv::response
