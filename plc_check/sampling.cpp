// Seeded runs of a product (sampling.hpp).
#include "plc_check/sampling.hpp"

#include <algorithm>
#include <bit>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "checker/reduce.hpp"
#include "encoder/encode.hpp"
#include "plc_check/product.hpp"

namespace cemv::plc_check {

namespace {

using Inputs = std::vector<encoder::Evaluator::Value>;

void int_numerals(const z3::expr& e, std::set<std::int64_t>& out, std::unordered_set<unsigned>& seen) {
  if (!seen.insert(e.id()).second || !e.is_app()) return;
  std::int64_t v = 0;
  if (e.num_args() == 0 && e.is_int() && e.is_numeral() && e.is_numeral_i64(v)) out.insert(v);
  for (unsigned i = 0; i < e.num_args(); ++i) int_numerals(e.arg(i), out, seen);
}

// For each integer input, the numerals it is compared with (`input <= c`,
// an analog limit as an ordered integer once reduced): drawn from these and
// one either side, an input is as often on either side of its own limits,
// where a draw among every numeral of the product (most of them other tags'
// limits, far away) leaves a low limit tripped in nearly every scan and its
// off-delay never run.
std::vector<std::set<std::int64_t>> compared_numerals(const encoder::TransitionSystem& ts,
                                                      const std::vector<z3::expr>& roots) {
  std::unordered_map<unsigned, std::size_t> index;
  for (std::size_t i = 0; i < ts.inputvars().size(); ++i)
    if (ts.inputvars()[i].var.is_int()) index.emplace(ts.inputvars()[i].var.id(), i);
  std::vector<std::set<std::int64_t>> out(ts.inputvars().size());
  std::unordered_set<unsigned> seen;
  std::vector<z3::expr> todo = roots;
  while (!todo.empty()) {
    const z3::expr e = todo.back();
    todo.pop_back();
    if (!e.is_app() || !seen.insert(e.id()).second) continue;
    const Z3_decl_kind k = e.decl().decl_kind();
    if (e.num_args() == 2 && (k == Z3_OP_LE || k == Z3_OP_GE || k == Z3_OP_LT || k == Z3_OP_GT || k == Z3_OP_EQ))
      for (int side = 0; side < 2; ++side) {
        const z3::expr v = e.arg(side), c = e.arg(1 - side);
        std::int64_t n = 0;
        if (const auto it = index.find(v.id()); it != index.end() && c.is_numeral() && c.is_numeral_i64(n))
          out[it->second].insert(n);
      }
    for (unsigned i = 0; i < e.num_args(); ++i) todo.push_back(e.arg(i));
  }
  return out;
}

const std::string kAllowed = std::string(kProgramPrefix) + "sample.allowed";
const std::string kGood = std::string(kProgramPrefix) + "sample.good";

class Runner {
 public:
  explicit Runner(const checker::SafetyProblem& p) : p_(p), enc_(p.ts->ctx()), ev_(init(p)) {}

  const std::vector<encoder::Evaluator::Value>& state() const { return ev_.state(); }
  // Back to the initial state.
  void reset() {
    ev_.reset();
    repeats_ = false;
    repeated_ = false;
  }
  // One scan: false when it breaks the constraints or the assumption. A scan
  // is a function of the state and the inputs: after one that left the state
  // as it was, the same inputs give the same scan again, and it is not
  // evaluated (a run holds its inputs for up to hundreds of scans, most of
  // them with nothing running).
  bool step(const Inputs& in) {
    repeated_ = repeats_ && same(in, last_inputs_);
    if (repeated_) return allowed_;
    before_ = ev_.state();
    ev_.step_raw(in);
    allowed_ = ev_.value(kAllowed) != 0;
    repeats_ = same(ev_.state(), before_);
    last_inputs_ = in;
    return allowed_;
  }
  bool good() const { return ev_.value(kGood) != 0; }
  // The last scan was the one before again: the same state, already seen.
  bool repeated() const { return repeated_; }

  // The scan (0-based) in which `run` first breaks `good`; nullopt when it
  // does not, or breaks the assumption before.
  std::optional<std::size_t> first_violation(const std::vector<Inputs>& run) {
    reset();
    for (std::size_t c = 0; c < run.size(); ++c) {
      if (!step(run[c])) return std::nullopt;
      if (!good()) return c;
    }
    return std::nullopt;
  }

  // Deletes stretches of scans, halves first, while the run still breaks
  // `good`; cut after the scan that does.
  std::vector<Inputs> shorten(std::vector<Inputs> run) {
    run.resize(*first_violation(run) + 1);
    for (std::size_t chunk = run.size() / 2; chunk >= 1; chunk /= 2)
      for (std::size_t start = 0; start + chunk < run.size();) {
        std::vector<Inputs> shorter(run.begin(), run.begin() + static_cast<std::ptrdiff_t>(start));
        shorter.insert(shorter.end(), run.begin() + static_cast<std::ptrdiff_t>(start + chunk), run.end());
        if (const auto v = first_violation(shorter)) {
          shorter.resize(*v + 1);
          run = std::move(shorter);
        } else {
          start += chunk;
        }
      }
    return run;
  }

  checker::Trace trace(const std::vector<Inputs>& run) {
    const auto& ts = *p_.ts;
    checker::Trace t;
    for (const auto& v : ts.inputvars()) t.input_names.push_back(v.name);
    for (const auto& v : ts.statevars()) t.state_names.push_back(v.name);
    auto value = [](const z3::expr& var, const encoder::Evaluator::Value& x) {
      checker::Value v;
      v.is_float = var.is_fpa();
      v.i = x.i;
      v.f = x.f;
      return v;
    };
    reset();
    for (const auto& in : run) {
      checker::Trace::Cycle c;
      for (std::size_t i = 0; i < in.size(); ++i) c.inputs.push_back(value(ts.inputvars()[i].var, in[i]));
      for (std::size_t i = 0; i < ev_.state().size(); ++i) c.state.push_back(value(ts.statevars()[i].var, ev_.state()[i]));
      t.cycles.push_back(std::move(c));
      step(in);
    }
    return t;
  }

 private:
  const encoder::Encoding& init(const checker::SafetyProblem& p) {
    enc_.ts = *p.ts;
    enc_.ts.name_term(kAllowed, p.ts->constraint_formula() && p.assumption);
    enc_.ts.name_term(kGood, p.good);
    return enc_;
  }

  // Equal values: integers, and floats bit for bit.
  static bool same(const std::vector<encoder::Evaluator::Value>& a, const std::vector<encoder::Evaluator::Value>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const auto& x, const auto& y) {
      return x.i == y.i && std::bit_cast<std::uint32_t>(x.f) == std::bit_cast<std::uint32_t>(y.f);
    });
  }

  const checker::SafetyProblem& p_;
  encoder::Encoding enc_;
  encoder::Evaluator ev_;
  bool repeats_ = false;   // the last scan left the state as it was
  bool repeated_ = false;  // the last scan was not evaluated: it repeats the one before
  bool allowed_ = false;  // the last scan's constraints and assumption
  Inputs last_inputs_;
  std::vector<encoder::Evaluator::Value> before_;
};

std::vector<std::vector<encoder::Evaluator::Value>> distinct(std::vector<std::vector<encoder::Evaluator::Value>> all) {
  std::set<std::vector<std::int64_t>> seen;
  std::vector<std::vector<encoder::Evaluator::Value>> out;
  for (auto& s : all) {
    std::vector<std::int64_t> key;
    for (const auto& v : s) key.insert(key.end(), {v.i, static_cast<std::int64_t>(std::bit_cast<std::uint32_t>(v.f))});
    if (seen.insert(std::move(key)).second) out.push_back(std::move(s));
  }
  return out;
}

using State = std::vector<encoder::Evaluator::Value>;

// SplitMix64's finaliser.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// One variable's share of a cone's hash: a cone's is the sum of its
// variables', kept up to date as they change.
std::uint64_t share_of(std::size_t v, const encoder::Evaluator::Value& x) {
  return mix(mix(mix(v) + static_cast<std::uint64_t>(x.i)) + std::bit_cast<std::uint32_t>(x.f));
}

std::uint64_t hash_of(const State& s) {
  std::uint64_t h = 0x9e3779b97f4a7c15ULL;
  for (const auto& v : s)
    for (std::uint64_t x : {static_cast<std::uint64_t>(v.i), std::uint64_t{std::bit_cast<std::uint32_t>(v.f)}})
      h = mix(x + h);
  return h;
}

// What the runs keep of the states they reach (SamplingOptions::cones): every
// state, or each cone's distinct projections, bounded; and which variables
// never left their initial value (their
// integer and Boolean values; constant_states asks no Float32 variable).
class Keeper {
 public:
  explicit Keeper(const SamplingOptions& o) : max_(o.max_states) {
    for (std::size_t c = 0; c < o.cones.size(); ++c) {
      cones_.push_back(ConeStates{o.cones[c], {}, {}});
      for (std::size_t v : o.cones[c]) {
        if (v >= cones_of_.size()) cones_of_.resize(v + 1);
        cones_of_[v].push_back(c);
      }
    }
    index_.resize(cones_.size());
    last_index_.assign(cones_.size(), kNotKept);
    changed_.assign(cones_.size(), 1);
    hash_.assign(cones_.size(), 0);
  }

  void add(const State& s) {
    if (unchanged_.empty()) {
      initial_ = s;
      unchanged_.assign(s.size(), 1);
    }
    for (std::size_t v = 0; v < s.size(); ++v)
      if (s[v].i != initial_[v].i) unchanged_[v] = 0;
    if (max_ == 0) return;
    if (cones_.empty()) {
      all_.push_back(s);
      return;
    }
    // A state of the product seen before adds nothing (distinct states are
    // counted by a 64-bit hash of the whole state; a collision only lowers
    // a weight).
    if (!seen_.insert(hash_of(s)).second) return;
    // A cone none of whose variables changed since the last state kept here
    // has the same values as then: the same entry, found without a hash (a
    // scan of a trip changes a few cones of hundreds).
    if (last_.empty()) {
      for (std::size_t c = 0; c < cones_.size(); ++c)
        for (std::size_t v : cones_[c].vars) hash_[c] += share_of(v, s[v]);
    } else {
      for (std::size_t v = 0; v < s.size() && v < cones_of_.size(); ++v)
        if (s[v].i != last_[v].i || std::bit_cast<std::uint32_t>(s[v].f) != std::bit_cast<std::uint32_t>(last_[v].f)) {
          const std::uint64_t change = share_of(v, s[v]) - share_of(v, last_[v]);
          for (std::size_t c : cones_of_[v]) {
            changed_[c] = 1;
            hash_[c] += change;
          }
        }
    }
    last_ = s;
    State projected;
    for (std::size_t c = 0; c < cones_.size(); ++c) {
      ConeStates& cs = cones_[c];
      if (!changed_[c]) {
        if (last_index_[c] != kNotKept) ++cs.weights[last_index_[c]];
        continue;
      }
      changed_[c] = 0;
      last_index_[c] = kNotKept;
      // By a 64-bit hash of the cone's values, not the values: a collision
      // only leaves a state out of the filter (more candidates for Houdini).
      const std::uint64_t key = hash_[c];
      if (const auto it = index_[c].find(key); it != index_[c].end()) {
        ++cs.weights[it->second];
        last_index_[c] = it->second;
        continue;
      }
      if (cs.states.size() >= max_) continue;
      last_index_[c] = cs.states.size();
      index_[c].emplace(key, cs.states.size());
      projected.clear();
      for (std::size_t v : cs.vars) projected.push_back(s[v]);
      cs.states.push_back(projected);
      cs.weights.push_back(1);
    }
  }

  void finish(Samples& out) {
    out.unchanged = std::move(unchanged_);
    if (cones_.empty()) out.states = distinct(std::move(all_));
    else out.cones = std::move(cones_);
  }

 private:
  std::size_t max_;
  std::vector<ConeStates> cones_;
  std::vector<std::unordered_map<std::uint64_t, std::size_t>> index_;
  std::unordered_set<std::uint64_t> seen_;
  std::vector<State> all_;
  static constexpr std::size_t kNotKept = SIZE_MAX;
  std::vector<std::vector<std::size_t>> cones_of_;  // by state variable: the cones that hold it
  State last_;                                      // the last state past `seen_`
  std::vector<std::size_t> last_index_;             // by cone: its entry for `last_`, or kNotKept
  std::vector<char> changed_;                       // by cone: a variable changed since `last_`
  std::vector<std::uint64_t> hash_;                 // by cone: the hash of its values in `last_`
  State initial_;
  std::vector<char> unchanged_;
};

// An input's value by name (SamplingOptions::rest, a trip's inputs) as the
// product takes it: a Float32 value of a reduced input as its ordered integer.
encoder::Evaluator::Value input_value(const z3::expr& var, const checker::Value& v) {
  if (var.is_int() && v.is_float) return {checker::float_key(v.f), 0.0f};
  return {v.i, v.f};
}

}  // namespace

Samples sample(const checker::SafetyProblem& p, const SamplingOptions& o) {
  Samples out;
  try {
    const auto& ts = *p.ts;
    Runner runner(p);
    std::set<std::int64_t> k{0, 1};
    std::unordered_set<unsigned> seen;
    for (const auto& s : ts.statevars()) int_numerals(s.next, k, seen);
    int_numerals(p.good, k, seen);
    int_numerals(p.assumption, k, seen);
    std::vector<std::int64_t> values;
    for (std::int64_t c : k) values.insert(values.end(), {c - 1, c, c + 1});
    std::vector<z3::expr> roots{p.good};  // not the constraints' range bounds
    for (const auto& s : ts.statevars()) roots.push_back(s.next);
    std::vector<std::vector<std::int64_t>> near;
    for (const auto& cs : compared_numerals(ts, roots)) {
      near.emplace_back();
      for (std::int64_t c : cs) near.back().insert(near.back().end(), {c - 1, c, c + 1});
    }
    std::vector<int> holds{1, 2, 3};
    for (std::int64_t c : k)
      if (c >= 2 && c <= 2000) holds.insert(holds.end(), {static_cast<int>(c), static_cast<int>(c) + 1, static_cast<int>(c) + 2});
    std::mt19937 rng(o.seed);
    auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
    std::mt19937 near_rng(o.seed + 1);
    auto pick_near = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(near_rng); };
    const auto& ins = ts.inputvars();
    Keeper states(o);
    states.add(runner.state());
    Inputs rest(ins.size());
    for (std::size_t i = 0; i < ins.size() && o.rest; ++i)
      if (const auto v = o.rest(ins[i].name)) rest[i] = input_value(ins[i].var, *v);
    bool near_limits = false;  // this run draws an input near its own limits
    auto draw = [&](Inputs& in, std::size_t i) {
      if (ins[i].var.is_bool()) in[i].i = static_cast<std::int64_t>(pick(2));
      else if (ins[i].var.is_int()) {
        in[i].i = values[pick(values.size())];
        // Its own stream: the runs from rest draw as they would without it.
        if (near_limits && !near[i].empty() && pick_near(4) != 0) in[i].i = near[i][pick_near(near[i].size())];
      }
      else in[i].f = static_cast<float>(values[pick(values.size())]);
    };
    std::vector<Inputs> run;
    int refused = 0;  // draws that broke the constraints or the assumption
    // Holds `in` up to `hold` scans, or up to `length` scans of the run; false
    // when a scan breaks `good` (out.violation is the run, shortened).
    auto play = [&](const Inputs& in, int hold, int length) {
      for (int h = 0; h < hold && static_cast<int>(run.size()) < length; ++h) {
        if (!runner.step(in)) {
          // Back to the state before this scan, and another draw.
          ++refused;
          runner.reset();
          for (const auto& earlier : run) runner.step(earlier);
          return true;
        }
        run.push_back(in);
        if (!runner.good()) {
          out.violation = runner.trace(runner.shorten(std::move(run)));
          return false;
        }
        // A repeated scan's state is the one just kept: nothing to add.
        if (!runner.repeated()) states.add(runner.state());
      }
      return true;
    };
    auto start_run = [&] {
      runner.reset();
      run.clear();
      refused = 0;
    };
    // One to three inputs changed, each back to `base` one time in three.
    auto change_around = [&](Inputs& in, const Inputs& base) {
      for (std::size_t n = 1 + pick(3); n > 0 && !in.empty(); --n) {
        const std::size_t i = pick(in.size());
        if (pick(3) == 0) in[i] = base[i];
        else draw(in, i);
      }
    };
    auto pick_hold = [&] { return pick(2) == 0 ? holds[pick(holds.size())] : 1 + static_cast<int>(pick(4)); };
    for (int r = 0; r < o.runs; ++r) {
      start_run();
      const bool from_rest = o.rest && r % 2 == 1;
      near_limits = !from_rest;
      Inputs in = rest;
      while (refused < 8 && static_cast<int>(run.size()) < o.cycles_per_run) {
        if (from_rest) {
          change_around(in, rest);
        } else {
          for (std::size_t i = 0; i < in.size(); ++i)
            if (run.empty() || pick(2) == 0) draw(in, i);
        }
        if (!play(in, pick_hold(), o.cycles_per_run)) return out;
      }
    }
    // The trips' runs draw from a stream of their own: the runs above are
    // the same with or without them.
    rng.seed(o.seed + 2);
    near_limits = false;
    // `in` with the inputs `set` names at its values.
    auto over = [&](Inputs in, const std::map<std::string, checker::Value>& set) {
      for (std::size_t i = 0; i < ins.size(); ++i)
        if (const auto it = set.find(ins[i].name); it != set.end()) in[i] = input_value(ins[i].var, it->second);
      return in;
    };
    for (const auto& trip : o.trips) {
      start_run();
      const Inputs tripped = over(rest, trip.inputs);
      // The trip without the pulses' inputs: a reset tag's rising edge comes
      // only from a source at rest before.
      Inputs apart = tripped;
      for (const auto& p : trip.pulses)
        for (std::size_t i = 0; i < ins.size(); ++i)
          if (p.count(ins[i].name) != 0) apart[i] = rest[i];
      const int length = o.cycles_per_trip +
                         3 * (trip.hold + (trip.hold + trip.pulse) * static_cast<int>(trip.pulses.size()));
      // Held, then each pulse over it and held again.
      auto pulsed = [&](const Inputs& base) {
        if (!play(base, trip.hold, length)) return false;
        for (const auto& p : trip.pulses)
          if (!play(over(base, p), trip.pulse, length) || !play(base, trip.hold, length)) return false;
        return true;
      };
      // From rest: a latch a pulse's source sets in the whole trip (an effect
      // the reset tag names, latched by a cause of both) holds it after.
      if (!pulsed(apart) || !play(tripped, trip.hold, length)) return out;
      Inputs in = tripped;
      const Inputs* base = &tripped;
      while (refused < 8 && static_cast<int>(run.size()) < length) {
        if (base == &tripped && static_cast<int>(run.size()) >= length / 2) {
          base = &rest;
          in = rest;
          if (!pulsed(rest)) return out;
        }
        change_around(in, *base);
        if (!play(in, pick_hold(), length)) return out;
      }
    }
    states.finish(out);
  } catch (const std::logic_error&) {
    out = {};  // an operator the evaluator does not take: nothing sampled
  }
  return out;
}

}  // namespace cemv::plc_check
