#include "checker/engines/invariants.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "checker/engines/kinduction.hpp"
#include "checker/engines/solving.hpp"
#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"
#include "encoder/term_memo.hpp"
#include "encoder/unroller.hpp"

namespace cemv::checker {

namespace {

using Sample = std::vector<encoder::Evaluator::Value>;

// The numerals of the system's formulas: thresholds worth driving inputs to,
// and bounds worth proposing for counters.
struct Constants {
  std::set<std::int64_t> ints{0, 1};
  std::set<float> floats{0.0f};
};

void collect_constants(const z3::expr& e, Constants& out, std::unordered_set<unsigned>& seen) {
  if (!seen.insert(e.id()).second || !e.is_app()) return;
  if (e.num_args() == 0) {
    if (e.is_int() && e.is_numeral()) {
      std::int64_t v = 0;
      if (e.is_numeral_i64(v)) out.ints.insert(v);
    } else if (e.is_fpa() && e.decl().decl_kind() != Z3_OP_UNINTERPRETED) {
      z3::expr bits(e.ctx(), Z3_mk_fpa_to_ieee_bv(e.ctx(), e));
      z3::expr b = bits.simplify();
      if (b.is_numeral()) {
        float f = std::bit_cast<float>(static_cast<std::uint32_t>(b.get_numeral_uint64()));
        if (!std::isnan(f)) out.floats.insert(f);
      }
    }
    return;
  }
  for (unsigned i = 0; i < e.num_args(); ++i) collect_constants(e.arg(i), out, seen);
}

Constants constants_of(const SafetyProblem& p) {
  Constants c;
  std::unordered_set<unsigned> seen;
  for (const auto& s : p.ts->statevars()) collect_constants(s.next, c, seen);
  for (const auto& t : p.ts->named_terms()) collect_constants(t.term, c, seen);
  for (const auto& l : p.ts->lemmas()) collect_constants(l.term, c, seen);
  collect_constants(p.good, c, seen);
  collect_constants(p.assumption, c, seen);
  return c;
}

// Random runs with inputs held for stretches of varying length (timers run
// out only when a trip is held), commands issued at the start of a stretch
// with varying probability. Each state reached goes to `keep`, the initial
// state first.
void simulate(const SafetyProblem& p, const MiningOptions& opt, const std::function<void(const Sample&)>& keep) {
  const auto& ts = *p.ts;
  encoder::Encoding enc(ts.ctx());
  enc.ts = ts;
  encoder::Evaluator ev(enc);
  Constants k = constants_of(p);
  std::vector<float> fpool;
  for (float f : k.floats)
    for (float g : {f, std::nextafter(f, -INFINITY), std::nextafter(f, INFINITY), f - 1.0f, f + 1.0f})
      fpool.push_back(g);
  std::vector<std::int64_t> ipool(k.ints.begin(), k.ints.end());
  std::mt19937 rng(opt.seed);
  keep(ev.state());
  const double command_p[] = {0.3, 0.05, 0.01, 0.002};
  const int hold_max[] = {1, 8, 60, 600};
  for (int run = 0; run < opt.runs; ++run) {
    if (opt.limits && opt.limits->interrupted()) break;
    ev.reset();
    const double pc = command_p[run % 4];
    const int hm = hold_max[(run / 4 + run) % 4];
    int cycle = 0;
    while (cycle < opt.cycles_per_run) {
      std::vector<encoder::Evaluator::Value> in(ts.inputvars().size());
      for (std::size_t i = 0; i < in.size(); ++i) {
        const auto& v = ts.inputvars()[i];
        if (v.var.is_bool()) {
          bool command = v.name.rfind("cmd.", 0) == 0;
          in[i].i = std::bernoulli_distribution(command ? pc : 0.5)(rng) ? 1 : 0;
        } else if (v.var.is_int()) {
          in[i].i = ipool[std::uniform_int_distribution<std::size_t>(0, ipool.size() - 1)(rng)];
        } else {
          in[i].f = fpool[std::uniform_int_distribution<std::size_t>(0, fpool.size() - 1)(rng)];
        }
      }
      int hold = std::uniform_int_distribution<int>(1, hm)(rng);
      for (int h = 0; h < hold && cycle < opt.cycles_per_run; ++h, ++cycle) {
        ev.step_raw(in);
        keep(ev.state());
        if (h == 0)  // commands act once per stretch
          for (std::size_t i = 0; i < in.size(); ++i)
            if (ts.inputvars()[i].name.rfind("cmd.", 0) == 0 && ts.inputvars()[i].var.is_bool()) in[i].i = 0;
      }
    }
  }
}

// Candidates as (evaluable predicate, term builder) pairs are overkill; the
// templates are few, so each is tested on the samples where it is made.
class CandidateMiner {
 public:
  // Over the state variables `only` names (ascending indices), or all.
  // `projected`: each sample holds the values of `only`'s variables alone,
  // in its order; else every state variable's.
  CandidateMiner(const SafetyProblem& p, const std::vector<Sample>& samples, const MiningOptions& opt,
                 const Constants& k, const std::vector<std::size_t>* only = nullptr, bool projected = false)
      : ts_(*p.ts), samples_(samples), opt_(opt), k_(k) {
    col_.resize(ts_.statevars().size());
    for (std::size_t i = 0; i < col_.size(); ++i) col_[i] = i;
    if (only && projected)
      for (std::size_t j = 0; j < only->size(); ++j) col_[(*only)[j]] = j;
    auto take = [&](std::size_t i) {
      const auto& v = ts_.statevars()[i].var;
      if (v.is_int()) ints_.push_back(i);
      else if (v.is_bool()) bools_.push_back(i);
    };
    if (only)
      for (std::size_t i : *only) take(i);
    else
      for (std::size_t i = 0; i < ts_.statevars().size(); ++i) take(i);
  }

  std::vector<z3::expr> mine() {
    unary();
    pairs();
    guarded();
    if (opt_.bool_implications) bool_implications();
    monitor_bounds();  // last: the candidates of the other templates stay as they were
    return std::move(out_);
  }

 private:
  std::int64_t iv(const Sample& s, std::size_t v) const { return s[col_[v]].i; }
  z3::expr var(std::size_t v) const { return ts_.statevars()[v].var; }
  z3::expr num(std::int64_t c) const { return ts_.ctx().int_val(c); }
  void add(const z3::expr& e) {
    if (out_.size() < opt_.max_candidates) out_.push_back(e);
  }
  bool stop() const { return out_.size() >= opt_.max_candidates || (opt_.limits && opt_.limits->interrupted()); }

  void unary() {
    for (std::size_t x : ints_) {
      std::int64_t lo = std::numeric_limits<std::int64_t>::max(), hi = std::numeric_limits<std::int64_t>::min();
      for (const auto& s : samples_) {
        lo = std::min(lo, iv(s, x));
        hi = std::max(hi, iv(s, x));
      }
      if (lo == hi) {
        add(var(x) == num(lo));
        continue;
      }
      // The nearest numerals of the system beyond the observed range: a
      // saturating counter's bound is one of them.
      auto up = k_.ints.lower_bound(hi);
      if (up != k_.ints.end()) add(var(x) <= num(*up));
      if (up == k_.ints.end() || *up != hi) add(var(x) <= num(hi));
      auto down = k_.ints.upper_bound(lo);
      if (down != k_.ints.begin()) add(var(x) >= num(*std::prev(down)));
    }
    for (std::size_t b : bools_) {
      bool all_true = true, all_false = true;
      for (const auto& s : samples_) (iv(s, b) ? all_false : all_true) = false;
      if (all_true) add(var(b));
      if (all_false) add(!var(b));
    }
  }

  // Over the samples selected by `keep`: is x - y constant (and which)?
  template <class Keep>
  std::optional<std::int64_t> constant_difference(std::size_t x, std::size_t y, Keep keep) const {
    std::optional<std::int64_t> d;
    for (const auto& s : samples_) {
      if (!keep(s)) continue;
      std::int64_t v = iv(s, x) - (y == SIZE_MAX ? 0 : iv(s, y));
      if (d && *d != v) return std::nullopt;
      d = v;
    }
    return d;
  }

  bool related(std::size_t x, std::size_t y) const { return !opt_.related || opt_.related(x, y); }
  bool may_guard(std::size_t g, std::size_t x, std::size_t y) const { return !opt_.may_guard || opt_.may_guard(g, x, y); }

  void pairs() {
    for (std::size_t a = 0; a < ints_.size() && !stop(); ++a)
      for (std::size_t b = a + 1; b < ints_.size(); ++b) {
        std::size_t x = ints_[a], y = ints_[b];
        if (!related(x, y)) continue;
        if (auto d = constant_difference(x, y, [](const Sample&) { return true; })) {
          add(var(x) == var(y) + num(*d));
          continue;
        }
        std::int64_t lo = std::numeric_limits<std::int64_t>::max(), hi = std::numeric_limits<std::int64_t>::min();
        for (const auto& s : samples_) {
          lo = std::min(lo, iv(s, x) - iv(s, y));
          hi = std::max(hi, iv(s, x) - iv(s, y));
        }
        add(var(x) <= var(y) + num(hi));
        add(var(x) >= var(y) + num(lo));
      }
  }

  void guarded() {
    for (std::size_t g : bools_)
      for (int pol = 1; pol >= 0 && !stop(); --pol) {
        auto keep = [&](const Sample& s) { return iv(s, g) == pol; };
        if (std::none_of(samples_.begin(), samples_.end(), keep)) continue;
        z3::expr guard = pol ? var(g) : !var(g);
        for (std::size_t a = 0; a < ints_.size(); ++a) {
          std::size_t x = ints_[a];
          bool global = constant_difference(x, SIZE_MAX, [](const Sample&) { return true; }).has_value();
          if (!global && may_guard(g, x, SIZE_MAX))
            if (auto c = constant_difference(x, SIZE_MAX, keep)) add(z3::implies(guard, var(x) == num(*c)));
          for (std::size_t b = a + 1; b < ints_.size(); ++b) {
            std::size_t y = ints_[b];
            if (!related(x, y) || !may_guard(g, x, y)) continue;
            if (constant_difference(x, y, [](const Sample&) { return true; })) continue;
            if (auto d = constant_difference(x, y, keep)) add(z3::implies(guard, var(x) == var(y) + num(*d)));
          }
        }
      }
  }

  // A property monitor's counter against the matrix's timers, under a
  // monitor's Bool: `g -> (x >= y + c or x >= b)`, b the bound x saturates
  // at (the nearest numeral of the system at or above its sampled maximum).
  // A response monitor's `pending -> (elapsed >= age + c or elapsed >= D)`
  // is the shape that bounds a demand's wait by the timers along its path
  // (a timer that may have started before the demand, or that saturates
  // before the monitor does, breaks every equality template);
  // docs/response-time.md, "Method". c is the least x - y sampled under g
  // where x is below b, and, because random runs rarely hold one demand
  // with everything else quiet (the worst case), also the offsets the
  // timers before x on a path would give: 1 - r minus the bounds of up to
  // two other counters (r <= 2 cycles of references that read the previous
  // value), each below the sampled least. Guards and y are the few monitor
  // variables; Houdini keeps what is inductive.
  void monitor_bounds() {
    auto monitor = [&](std::size_t v) { return ts_.statevars()[v].name.rfind("monitor.", 0) == 0; };
    std::vector<std::int64_t> bound(ts_.statevars().size(), 0);
    std::vector<std::size_t> counters;  // the matrix's saturating counters
    for (std::size_t x : ints_) {
      std::int64_t lo = std::numeric_limits<std::int64_t>::max(), hi = std::numeric_limits<std::int64_t>::min();
      for (const auto& s : samples_) {
        lo = std::min(lo, iv(s, x));
        hi = std::max(hi, iv(s, x));
      }
      auto up = k_.ints.lower_bound(hi);
      bound[x] = up != k_.ints.end() ? *up : hi;
      if (!monitor(x) && lo >= 0 && bound[x] > 0) counters.push_back(x);
    }
    // Sums of the bounds of up to two counters other than x.
    const bool pairs_of_counters = counters.size() <= 12;
    auto offsets = [&](std::size_t x) {
      std::set<std::int64_t> sums{0};
      for (std::size_t a = 0; a < counters.size(); ++a) {
        if (counters[a] == x) continue;
        sums.insert(bound[counters[a]]);
        if (pairs_of_counters)
          for (std::size_t b = a + 1; b < counters.size(); ++b)
            if (counters[b] != x) sums.insert(bound[counters[a]] + bound[counters[b]]);
      }
      std::set<std::int64_t> out;
      for (std::int64_t sum : sums)
        for (std::int64_t r = 0; r <= 2; ++r) out.insert(1 - r - sum);
      return out;
    };
    // Each candidate costs Houdini; a big cone with many monitors stops here.
    const std::size_t budget = out_.size() + 4000;
    for (std::size_t g : bools_) {
      if (!monitor(g)) continue;
      for (int pol = 1; pol >= 0 && !stop() && out_.size() < budget; --pol) {
        z3::expr guard = pol ? var(g) : !var(g);
        bool seen = false;
        for (const auto& s : samples_) seen = seen || iv(s, g) == pol;
        if (!seen) continue;
        for (std::size_t y : ints_) {
          if (!monitor(y)) continue;
          for (std::size_t x : counters) {
            std::optional<std::int64_t> least;
            for (const auto& s : samples_)
              if (iv(s, g) == pol && iv(s, x) < bound[x])
                least = std::min(least.value_or(iv(s, x) - iv(s, y)), iv(s, x) - iv(s, y));
            std::set<std::int64_t> cs;
            if (least) cs.insert(*least);
            if (pol)
              for (std::int64_t c : offsets(x))
                if (!least || c < *least) cs.insert(c);
            for (std::int64_t c : cs) add(z3::implies(guard, var(x) >= var(y) + num(c) || var(x) >= num(bound[x])));
          }
        }
      }
    }
  }

  void bool_implications() {
    // Each flag's values over the samples as bits: a clause over two flags
    // is then a few words compared, not a pass over up to 4,096 samples per
    // pair and polarity (most of the mining of a 128 x 128 program's layers).
    const std::size_t words = (samples_.size() + 63) / 64;
    std::vector<std::uint64_t> set(bools_.size() * words, 0);
    for (std::size_t j = 0; j < bools_.size(); ++j)
      for (std::size_t k = 0; k < samples_.size(); ++k)
        if (iv(samples_[k], bools_[j]) != 0) set[j * words + k / 64] |= std::uint64_t{1} << (k % 64);
    auto every = [&](std::size_t w) {
      const std::size_t left = samples_.size() - 64 * w;
      return left >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << left) - 1;
    };
    // The clause (x == pa) or (y == pb) on every sample.
    auto holds = [&](std::size_t a, int pa, std::size_t b, int pb) {
      for (std::size_t w = 0; w < words; ++w) {
        const std::uint64_t x = set[a * words + w], y = set[b * words + w];
        const std::uint64_t either = (pa ? x : ~x) | (pb ? y : ~y);
        if ((~either & every(w)) != 0) return false;
      }
      return true;
    };
    for (std::size_t a = 0; a < bools_.size() && !stop(); ++a)
      for (std::size_t b = a + 1; b < bools_.size(); ++b)
        for (int pa = 0; pa < 2 && related(bools_[a], bools_[b]); ++pa)
          for (int pb = 0; pb < 2; ++pb) {
            if (!holds(a, pa, b, pb)) continue;
            z3::expr la = pa ? var(bools_[a]) : !var(bools_[a]);
            z3::expr lb = pb ? var(bools_[b]) : !var(bools_[b]);
            add(la || lb);
          }
  }

  const encoder::TransitionSystem& ts_;
  const std::vector<Sample>& samples_;
  std::vector<std::size_t> col_;  // a state variable's place in a sample
  const MiningOptions& opt_;
  const Constants& k_;
  std::vector<std::size_t> ints_, bools_;
  std::vector<z3::expr> out_;
};

// A candidate, its copy at the cycle whose value decides (0 for initiation,
// 1 for consecution; made once: renaming is the expensive part on big cones),
// and its activation literal in cycle 0 (consecution only).
struct Candidate {
  z3::expr term;
  z3::expr decided;
  std::optional<z3::expr> literal;
};

// Drops, in order, the candidates false in a model, until a check is unsat.
// Each round's "some candidate is false" sits behind a fresh literal instead
// of a push/pop, which keeps the solver's internalised terms.
void drop_until_unsat(z3::solver& s, std::vector<Candidate>& cands, const Limits& limits, WorkMeter& meter) {
  z3::context& ctx = s.ctx();
  for (int round = 0;; ++round) {
    if (limits.interrupted()) throw Stopped{UnknownReason::TimeLimit};
    if (cands.empty()) return;
    z3::expr_vector some_false(ctx);
    for (const auto& c : cands) some_false.push_back(!c.decided);
    z3::expr this_round = ctx.bool_const(("houdini.round." + std::to_string(round) + "." +
                                          std::to_string(cands.size())).c_str());
    s.add(z3::implies(this_round, z3::mk_or(some_false)));
    z3::expr_vector assume(ctx);
    assume.push_back(this_round);
    for (const auto& c : cands)
      if (c.literal) assume.push_back(*c.literal);
    z3::check_result r = check_within(s, meter, assume);
    if (r == z3::unsat) return;
    if (r == z3::unknown) throw Stopped{unknown_reason(s.reason_unknown(), limits, meter)};
    z3::model m = s.get_model();
    std::vector<Candidate> keep;
    for (auto& c : cands)
      if (m.eval(c.decided, true).is_true()) keep.push_back(std::move(c));
    s.add(!this_round);
    cands = std::move(keep);
  }
}

// Every Bool atom over Float32 terms (comparisons of analog inputs with
// limits, equalities of simulated values) replaced by a fresh Bool: an
// over-approximation of the transition relation, so whatever is inductive for
// it is inductive for the system. The candidates speak only of Int and Bool
// state, and without the floats each Houdini round is a small SAT/LIA query
// instead of a bit-blasted one (27 s -> well under a second on a 191-variable
// cone of a 128 x 128 matrix).
class FloatAbstraction {
 public:
  explicit FloatAbstraction(z3::context& ctx) : ctx_(ctx) {}

  z3::expr operator()(const z3::expr& e) {
    if (const z3::expr* known = memo_.find(e)) return *known;
    z3::expr out = e;
    if (e.is_app() && e.num_args() > 0) {
      bool float_atom = false;
      if (e.is_bool())
        for (unsigned i = 0; i < e.num_args(); ++i) float_atom = float_atom || e.arg(i).is_fpa();
      if (float_atom) {
        out = ctx_.bool_const(("houdini.float_atom." + std::to_string(memo_.size())).c_str());
      } else if (!e.is_fpa()) {
        z3::expr_vector args(ctx_);
        bool changed = false;
        for (unsigned i = 0; i < e.num_args(); ++i) {
          args.push_back((*this)(e.arg(i)));
          changed = changed || !z3::eq(args.back(), e.arg(i));
        }
        if (changed) out = e.decl()(args);
      }
    }
    return memo_.emplace(e, out);
  }

 private:
  z3::context& ctx_;
  encoder::TermMemo<z3::expr> memo_;
};

// Distinct states only: held inputs repeat a state for hundreds of cycles.
std::vector<Sample> distinct(std::vector<Sample> samples) {
  std::set<std::vector<std::int64_t>> seen;
  std::vector<Sample> out;
  for (auto& s : samples) {
    std::vector<std::int64_t> key;
    key.reserve(s.size() * 2);
    for (const auto& v : s) {
      key.push_back(v.i);
      key.push_back(std::bit_cast<std::uint32_t>(v.f));
    }
    if (seen.insert(std::move(key)).second) out.push_back(std::move(s));
  }
  return out;
}

}  // namespace

std::vector<z3::expr> mine_candidates(const SafetyProblem& problem, const MiningOptions& options) {
  std::vector<Sample> samples;
  try {
    simulate(problem, options, [&](const Sample& s) { samples.push_back(s); });
  } catch (const std::logic_error&) {
    return {};  // an operator the Evaluator does not interpret: no samples, no candidates
  }
  const std::vector<Sample> states = distinct(std::move(samples));
  const Constants k = constants_of(problem);
  return CandidateMiner(problem, states, options, k).mine();
}

std::vector<std::vector<z3::expr>> mine_candidates_from(const SafetyProblem& problem, const MiningOptions& options,
                                                        const std::vector<std::vector<std::size_t>>& subsets,
                                                        const std::vector<const std::vector<Sample>*>& states) {
  std::vector<std::vector<z3::expr>> out(subsets.size());
  const Constants k = constants_of(problem);
  for (std::size_t i = 0; i < subsets.size(); ++i)
    if (states[i] && !states[i]->empty())
      out[i] = CandidateMiner(problem, *states[i], options, k, &subsets[i], true).mine();
  return out;
}

std::vector<std::vector<z3::expr>> mine_candidates_within(const SafetyProblem& problem, const MiningOptions& options,
                                                          const std::vector<std::vector<std::size_t>>& subsets) {
  std::vector<std::vector<z3::expr>> out(subsets.size());
  // Each subset's distinct states of its own variables, the first
  // max_states_per_subset: the memory of a subset's, not of the product's
  // states (nearly every scan of a big product's runs is a distinct state).
  std::vector<std::vector<Sample>> states(subsets.size());
  // Seen by a 64-bit hash of the subset's values: a collision only leaves a
  // state out of the filter (a candidate more for Houdini to drop).
  std::vector<std::unordered_set<std::uint64_t>> seen(subsets.size());
  Sample projected;
  try {
    simulate(problem, options, [&](const Sample& s) {
      for (std::size_t i = 0; i < subsets.size(); ++i) {
        if (options.max_states_per_subset != 0 && states[i].size() >= options.max_states_per_subset) continue;
        projected.clear();
        std::uint64_t h = 0x9e3779b97f4a7c15ULL;
        for (std::size_t v : subsets[i]) {
          projected.push_back(s[v]);
          for (std::uint64_t x : {static_cast<std::uint64_t>(s[v].i), std::uint64_t{std::bit_cast<std::uint32_t>(s[v].f)}}) {
            x += h + 0x9e3779b97f4a7c15ULL;
            x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
            x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
            h = x ^ (x >> 31);
          }
        }
        if (seen[i].insert(h).second) states[i].push_back(projected);
      }
    });
  } catch (const std::logic_error&) {
    return out;
  }
  seen.clear();
  std::vector<const std::vector<Sample>*> each;
  for (const auto& s : states) each.push_back(&s);
  return mine_candidates_from(problem, options, subsets, each);
}

std::vector<z3::expr> houdini(const SafetyProblem& problem, std::vector<z3::expr> candidates,
                              const Limits& limits, WorkMeter& meter) {
  const auto& ts = *problem.ts;
  z3::context& ctx = ts.ctx();
  encoder::Unroller u(ts);
  Watchdog watchdog(ctx, limits);
  FloatAbstraction abstract(ctx);
  std::vector<Candidate> cands;
  for (const auto& c : candidates) cands.push_back(Candidate{c, u.at(c, 0), std::nullopt});
  // Initiation: drop what the initial state violates.
  {
    z3::solver s = make_solver(ctx, limits.solvers);
    s.add(abstract(u.at(ts.init_formula(), 0)));
    drop_until_unsat(s, cands, limits, meter);
  }
  // Consecution: candidates of cycle 0 (each behind an activation literal)
  // and one transition; drop what the post-state violates.
  z3::solver s = make_solver(ctx, limits.solvers);
  s.add(abstract(u.at(ts.constraint_formula() && problem.assumption && ts.trans_formula(), 0)));
  for (std::size_t i = 0; i < cands.size(); ++i) {
    z3::expr l = ctx.bool_const(("houdini.cand." + std::to_string(i)).c_str());
    s.add(z3::implies(l, cands[i].decided));
    cands[i].literal = l;
    cands[i].decided = u.at(cands[i].term, 1);
  }
  drop_until_unsat(s, cands, limits, meter);
  std::vector<z3::expr> kept;
  for (const auto& c : cands) kept.push_back(c.term);
  return kept;
}

namespace {

// Three rounds, cheapest first: the encoder's lemmas alone (many properties of
// a matrix need nothing more, and mining costs seconds on a big cone), then
// the counter relations, and only if induction still fails, the Bool clauses.
class InvariantProver : public Prover {
 public:
  Method method() const override { return Method::InvariantsInduction; }
  // The three rounds share one budget of work.
  ProverResult prove(const SafetyProblem& problem, const Limits& limits) override {
    KInductionOptions o;
    o.simple_path = false;
    o.max_k = 1;
    o.method = method();
    double seconds = 0.0;
    Work work = 0;
    ProverResult r;
    for (int round = 0; round < 3; ++round) {
      o.mine_invariants = round > 0;
      o.bool_implications = round > 1;
      const Work left = limits.work == 0 ? 0 : limits.work > work ? limits.work - work : 0;
      if (limits.work != 0 && left == 0) {
        r.reason = UnknownReason::WorkLimit;
        break;
      }
      r = KInduction(o).prove(problem, limits.with_work(left));
      seconds += r.seconds;
      work += r.work;
      r.seconds = seconds;
      r.work = work;
      if (r.verdict != Verdict::Unknown || r.reason != UnknownReason::BoundReached) return r;
    }
    return r;
  }
};

}  // namespace

std::unique_ptr<Prover> make_invariant_prover() { return std::make_unique<InvariantProver>(); }

}  // namespace cemv::checker
