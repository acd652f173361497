#include "checker/shrink.hpp"

#include <memory>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "checker/concrete_judge.hpp"
#include "checker/engines/solving.hpp"
#include "checker/reduce.hpp"
#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"
#include "encoder/unroller.hpp"

namespace cemv::checker {

namespace {

// `rest` in the representation of `v`: a float the reduction made an ordered
// integer (checker/reduce.hpp) as its key, an integer given for a float as
// that float.
Value in_kind_of(const Value& v, const Value& rest) {
  Value out = v;
  if (v.is_float) out.f = rest.is_float ? rest.f : static_cast<float>(rest.i);
  else out.i = rest.is_float ? float_key(rest.f) : rest.i;
  return out;
}

// The concrete pass: inputs put back at their preferred value wherever the
// violation still happens, first a whole input over every cycle, then runs
// of cycles halved down to single cycles. Deterministic (a fixed order), no
// solver: what is left for the solver's search is what the violation may
// need.
Trace rest_concretely(const SafetyProblem& problem, Trace t, const PreferredValue& preferred,
                      const Limits& limits) {
  ConcreteJudge judge(problem);
  if (!judge.violates(t)) return t;
  const std::size_t n = t.cycles.size();
  for (std::size_t i = 0; i < t.input_names.size(); ++i) {
    std::optional<Value> rest = preferred(t.input_names[i]);
    if (!rest) continue;
    auto try_rest = [&](std::size_t lo, std::size_t hi) {
      Trace trial = t;
      bool changed = false;
      for (std::size_t k = lo; k < hi; ++k) {
        const Value v = in_kind_of(t.cycles[k].inputs[i], *rest);
        if (v == t.cycles[k].inputs[i]) continue;
        trial.cycles[k].inputs[i] = v;
        changed = true;
      }
      if (!changed) return true;
      if (!judge.violates(trial)) return false;
      t = std::move(trial);
      return true;
    };
    auto split = [&](auto&& self, std::size_t lo, std::size_t hi) -> void {
      if (lo >= hi || try_rest(lo, hi) || hi - lo == 1) return;
      const std::size_t mid = lo + (hi - lo) / 2;
      self(self, lo, mid);
      self(self, mid, hi);
    };
    stop_if_interrupted(limits);
    split(split, 0, n);
  }
  return t;
}

z3::expr constant_of(const encoder::TransitionSystem& ts, const z3::expr& var, const Value& v) {
  z3::context& ctx = ts.ctx();
  if (var.is_bool()) return ctx.bool_val(v.i != 0);
  // An analog value the reduction made an integer (checker/reduce.hpp).
  if (var.is_int()) return ctx.int_val(static_cast<int64_t>(v.is_float ? float_key(v.f) : v.i));
  return ts.float_const(v.is_float ? v.f : static_cast<float>(v.i));
}

}  // namespace

PreferredValue plant_at_rest(const std::vector<std::pair<const encoder::Encoding*, const model::Matrix*>>& parts) {
  auto preferred = std::make_shared<std::unordered_map<std::string, Value>>();
  auto name = [](const z3::expr& v) { return v.decl().name().str(); };
  for (const auto& [enc, m] : parts) {
    const model::CycleInput defaults = model::default_cycle_input(*m);
    for (std::size_t i = 0; i < enc->tag_value.size() && i < defaults.tags.size(); ++i) {
      if (enc->tag_value[i] && !preferred->count(name(*enc->tag_value[i]))) {
        Value v;
        if (enc->tag_value[i]->is_fpa()) {
          v.is_float = true;
          v.f = defaults.tags[i].value;
        } else {
          v.i = defaults.tags[i].value != 0.0f ? 1 : 0;
        }
        (*preferred)[name(*enc->tag_value[i])] = v;
      }
      if (enc->tag_bad[i]) (*preferred)[name(*enc->tag_bad[i])] = Value{};
    }
    for (const auto& c : enc->commands) (*preferred)[name(c.var)] = Value{};
  }
  return [preferred](const std::string& input) -> std::optional<Value> {
    auto it = preferred->find(input);
    if (it == preferred->end()) return std::nullopt;
    return it->second;
  };
}

// Solver calls of the grow pass (step 2 below) at most.
constexpr std::size_t kMaxGrowTries = 150;

Trace shrink_trace(const SafetyProblem& problem, const Trace& cex, const PreferredValue& preferred,
                   const Limits& limits, std::size_t max_cycles) {
  const std::size_t n = cex.length();
  if (n == 0 || n > max_cycles || limits.interrupted()) return cex;
  // Most inputs play no part: the concrete pass puts them at rest at once,
  // and the solver's search below starts from its trace, with only the
  // rest to decide. An evaluator that cannot run the system (an operator it
  // does not interpret) leaves that all to the solver.
  Trace start = cex;
  try {
    start = rest_concretely(problem, cex, preferred, limits);
  } catch (const std::logic_error&) {
  }
  const auto& ts = *problem.ts;
  z3::context& ctx = ts.ctx();
  encoder::Unroller u(ts);
  z3::solver s = make_solver(ctx, limits.solvers);
  // The same question BMC answered at depth n - 1: a path of n cycles under
  // the constraints and assumptions, `good` in every cycle but the last.
  s.add(u.at(ts.init_formula(), 0));
  const z3::expr facts = ts.constraint_formula() && problem.assumption;
  const int last = static_cast<int>(n) - 1;
  for (int k = 0; k <= last; ++k) {
    s.add(u.at(facts, k));
    if (k < last) {
      s.add(u.at(problem.good, k));
      s.add(u.at(ts.trans_formula(), k));
    }
  }
  s.add(!u.at(problem.good, last));

  // One literal per (cycle, input with a preferred value), in a fixed order,
  // standing for "this input keeps its preferred value in this cycle".
  std::vector<z3::expr> literals;
  for (int k = 0; k <= last; ++k)
    for (const auto& in : ts.inputvars()) {
      std::optional<Value> v = preferred(in.name);
      if (!v) continue;
      z3::expr lit = ctx.bool_const(("shrink." + std::to_string(k) + "." + in.name).c_str());
      z3::expr at_rest = u.var_at(in.var, k) == constant_of(ts, in.var, *v);
      s.add(z3::implies(lit, at_rest));
      literals.push_back(lit);
    }
  auto vector_of = [&](const std::vector<bool>& on, std::optional<std::size_t> extra = std::nullopt) {
    z3::expr_vector out(ctx);
    for (std::size_t i = 0; i < literals.size(); ++i)
      if (on[i] || extra == i) out.push_back(literals[i]);
    return out;
  };
  try {
    Watchdog watchdog(ctx, limits);
    WorkMeter meter(ctx, limits);
    // 1. Start: the literals the concrete pass's trace keeps at rest, a
    // satisfiable set (that trace is a model of it).
    std::vector<bool> kept(literals.size(), false);
    std::optional<z3::model> model;
    {
      std::size_t l = 0;
      for (int k = 0; k <= last; ++k)
        for (std::size_t in = 0; in < ts.inputvars().size(); ++in) {
          std::optional<Value> v = preferred(ts.inputvars()[in].name);
          if (!v) continue;
          const Value& got = start.cycles[static_cast<std::size_t>(k)].inputs[in];
          kept[l++] = in_kind_of(got, *v) == got;
        }
    }
    // 2. Grow: the concrete pass only put inputs back one by one; the
    // solver may find other values for what the violation needs that let
    // more inputs rest. Take back every dropped literal; then the others, a whole
    // run of them at once and, when that fails, each half in turn, down to
    // single literals (what a single literal cannot take back, a larger set
    // containing it cannot either): what is left is a maximal set of inputs
    // at rest, in a number of solver calls that grows with the inputs the
    // violation needs, not with the length of the trace. The tries are
    // counted and the checks share one budget of work, so the result never
    // depends on the machine's speed: a long trace keeps what the cheap part
    // gives.
    std::vector<std::size_t> open;
    for (std::size_t i = 0; i < literals.size(); ++i)
      if (!kept[i]) open.push_back(i);
    std::size_t tries = 0;
    auto take_back = [&](auto&& self, std::size_t lo, std::size_t hi) -> void {
      if (lo >= hi || ++tries > kMaxGrowTries) return;
      std::vector<bool> trial = kept;
      for (std::size_t j = lo; j < hi; ++j) trial[open[j]] = true;
      if (check_within(s, meter, vector_of(trial)) == z3::sat) {
        kept = std::move(trial);
        model = s.get_model();
        return;
      }
      if (hi - lo == 1) return;
      const std::size_t mid = lo + (hi - lo) / 2;
      self(self, lo, mid);
      self(self, mid, hi);
    };
    take_back(take_back, 0, open.size());
    if (model) return trace_from_model(ts, u, *model, last);
  } catch (const z3::exception&) {
    // A limit or a solver failure: the concrete pass's trace stands.
  }
  return start;
}

Trace rest_inputs_concretely(const SafetyProblem& problem, const Trace& cex, const PreferredValue& preferred,
                             const Limits& limits) {
  try {
    return rest_concretely(problem, cex, preferred, limits);
  } catch (const std::logic_error&) {
    return cex;
  }
}

}  // namespace cemv::checker
