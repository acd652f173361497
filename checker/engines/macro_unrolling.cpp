#include "checker/engines/macro_unrolling.hpp"

#include <string>

#include "checker/engines/solving.hpp"
#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"

namespace cemv::checker {

MacroUnrolling::MacroUnrolling(const SafetyProblem& p) : p_(p), ts_(*p.ts), ctx_(ts_.ctx()), u_(ts_), from_(ctx_) {
  for (const auto& s : ts_.statevars()) from_.push_back(s.var);
  for (const auto& i : ts_.inputvars()) from_.push_back(i.var);
}

z3::expr MacroUnrolling::length(int j) { return ctx_.int_const(("macro.length@" + std::to_string(j)).c_str()); }

// The next-state terms of every state variable (and the cycle's facts, last)
// with the state replaced by `state` and the inputs by the copies of macro
// step j: one substitution of one term holding them all, since a
// substitution per variable is quadratic on a big cone.
std::vector<z3::expr> MacroUnrolling::nexts_and_facts(const std::vector<z3::expr>& state, int j) {
  z3::expr_vector parts(ctx_);
  z3::sort_vector sorts(ctx_);
  for (const auto& s : ts_.statevars()) {
    parts.push_back(s.next);
    sorts.push_back(s.next.get_sort());
  }
  parts.push_back(ts_.constraint_formula() && p_.assumption);
  sorts.push_back(ctx_.bool_sort());
  z3::func_decl bundle = ctx_.function("macro.bundle", sorts, ctx_.bool_sort());
  z3::expr_vector to(ctx_);
  for (const auto& s : state) to.push_back(s);
  for (const auto& i : ts_.inputvars()) to.push_back(u_.var_at(i.var, j));
  z3::expr all = bundle(parts).substitute(from_, to);
  std::vector<z3::expr> out;
  for (unsigned i = 0; i < all.num_args(); ++i) out.push_back(all.arg(i));
  return out;
}

z3::expr MacroUnrolling::step(int j) {
  const z3::expr n = length(j);
  const std::size_t count = ts_.statevars().size();
  z3::expr_vector single(ctx_), stretch(ctx_);
  std::vector<z3::expr> start, last;
  for (const auto& s : ts_.statevars()) start.push_back(u_.var_at(s.var, j));
  const std::vector<z3::expr> first = nexts_and_facts(start, j);
  for (std::size_t v = 0; v < count; ++v) {
    const auto& s = ts_.statevars()[v];
    z3::expr now = start[v];
    z3::expr after = u_.var_at(s.var, j + 1);
    const z3::expr& next_now = first[v];
    single.push_back(after == next_now);
    if (s.var.is_int()) {
      z3::expr counts = ctx_.bool_const(("macro.counts." + s.name + "@" + std::to_string(j)).c_str());
      stretch.push_back(next_now == z3::ite(counts, now + 1, now));
      stretch.push_back(after == z3::ite(counts, now + n, now));
      last.push_back(z3::ite(counts, now + n - 1, now));
    } else {
      stretch.push_back(next_now == now);
      stretch.push_back(after == now);
      last.push_back(now);
    }
  }
  // The last cycle of the stretch, from its own start state, ends where the
  // stretch ends, under the cycle's facts.
  const std::vector<z3::expr> final_cycle = nexts_and_facts(last, j);
  for (std::size_t v = 0; v < count; ++v) stretch.push_back(u_.var_at(ts_.statevars()[v].var, j + 1) == final_cycle[v]);
  stretch.push_back(final_cycle[count]);
  return n >= 1 && first[count] && z3::ite(n == 1, z3::mk_and(single), z3::mk_and(stretch));
}

z3::expr MacroUnrolling::init() { return u_.at(ts_.init_formula(), 0); }

z3::expr MacroUnrolling::violation(int j) { return u_.at(ts_.constraint_formula() && p_.assumption && !p_.good, j); }

MacroRun macro_run(MacroUnrolling& m, const encoder::TransitionSystem& ts, const z3::model& model, int steps) {
  MacroRun run;
  for (int j = 0; j <= steps; ++j) {
    std::vector<Value> in;
    for (const auto& i : ts.inputvars()) in.push_back(value_in(model, m.unroller().var_at(i.var, j)));
    run.inputs.push_back(std::move(in));
    run.lengths.push_back(j < steps ? model.eval(m.length(j), true).get_numeral_int64() : 1);
  }
  return run;
}

namespace {

std::vector<encoder::Evaluator::Value> evaluator_inputs(const std::vector<Value>& inputs) {
  std::vector<encoder::Evaluator::Value> in(inputs.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    in[i].i = inputs[i].i;
    in[i].f = inputs[i].f;
  }
  return in;
}

}  // namespace

std::optional<std::int64_t> first_violation(const SafetyProblem& p, const MacroRun& run, const Limits& limits) {
  const auto& ts = *p.ts;
  encoder::Encoding enc(ts.ctx());
  enc.ts = ts;
  enc.ts.name_term("checker.good", p.good);
  enc.ts.name_term("checker.facts", ts.constraint_formula() && p.assumption);
  encoder::Evaluator ev(enc);
  std::int64_t cycle = 0;
  for (std::size_t j = 0; j < run.inputs.size(); ++j) {
    const std::vector<encoder::Evaluator::Value> in = evaluator_inputs(run.inputs[j]);
    for (std::int64_t c = 0; c < run.lengths[j]; ++c, ++cycle) {
      if (cycle % 4096 == 4095) stop_if_interrupted(limits);
      ev.step_raw(in);
      if (!ev.value("checker.facts")) return std::nullopt;
      if (!ev.value("checker.good")) return cycle;
    }
  }
  return std::nullopt;
}

Trace expand(const SafetyProblem& p, const MacroRun& run, std::int64_t cycles) {
  const auto& ts = *p.ts;
  encoder::Encoding enc(ts.ctx());
  enc.ts = ts;
  encoder::Evaluator ev(enc);
  Trace t;
  for (const auto& i : ts.inputvars()) t.input_names.push_back(i.name);
  const bool states = cycles <= kMaxTraceStateCycles;
  if (states)
    for (const auto& s : ts.statevars()) t.state_names.push_back(s.name);
  t.cycles.reserve(static_cast<std::size_t>(cycles));
  for (std::size_t j = 0; j < run.inputs.size() && static_cast<std::int64_t>(t.cycles.size()) < cycles; ++j) {
    const std::vector<encoder::Evaluator::Value> in = evaluator_inputs(run.inputs[j]);
    for (std::int64_t c = 0; c < run.lengths[j] && static_cast<std::int64_t>(t.cycles.size()) < cycles; ++c) {
      Trace::Cycle cycle;
      cycle.inputs = run.inputs[j];
      for (std::size_t v = 0; v < ts.statevars().size() && states; ++v)
        cycle.state.push_back(Value{ts.statevars()[v].var.is_fpa(), ev.state()[v].i, ev.state()[v].f});
      ev.step_raw(in);
      t.cycles.push_back(std::move(cycle));
    }
  }
  return t;
}

}  // namespace cemv::checker
