#include "checker/engines/accelerated_bmc.hpp"

#include <algorithm>

#include "checker/engines/solving.hpp"
#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"
#include "encoder/unroller.hpp"

namespace cemv::checker {

namespace {

// One macro step of the unrolling: its start state and inputs live in the
// Unroller's copies at index j; `length` is its number of cycles.
class MacroUnrolling {
 public:
  MacroUnrolling(const SafetyProblem& p)
      : p_(p), ts_(*p.ts), ctx_(ts_.ctx()), u_(ts_), from_(ctx_) {
    for (const auto& s : ts_.statevars()) from_.push_back(s.var);
    for (const auto& i : ts_.inputvars()) from_.push_back(i.var);
  }

  z3::expr length(int j) { return ctx_.int_const(("macro.length@" + std::to_string(j)).c_str()); }

  // The next-state terms of every state variable (and the cycle's facts, last)
  // with the state replaced by `state` and the inputs by the copies of macro
  // step j: one substitution of one term holding them all, since a
  // substitution per variable is quadratic on a big cone.
  std::vector<z3::expr> nexts_and_facts(const std::vector<z3::expr>& state, int j) {
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

  // Macro step j: from state@j with inputs@j to state@(j+1).
  z3::expr step(int j) {
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

  z3::expr init() { return u_.at(ts_.init_formula(), 0); }
  z3::expr violation(int j) { return u_.at(ts_.constraint_formula() && p_.assumption && !p_.good, j); }
  encoder::Unroller& unroller() { return u_; }

 private:
  const SafetyProblem& p_;
  const encoder::TransitionSystem& ts_;
  z3::context& ctx_;
  encoder::Unroller u_;
  z3::expr_vector from_;
};

// Expands macro steps into cycles on the Evaluator; returns the trace up to
// the first violating cycle, or nothing when the run does not violate `good`
// (or breaks the assumption first).
// Where the macro trace first violates the property when run cycle by cycle
// on the Evaluator (0-based), if it does; nullopt when it is spurious (it
// breaks a constraint, or never violates). Holds nothing per cycle, so a
// trace of millions of cycles costs time, not memory; stops when interrupted.
std::optional<std::int64_t> first_violation(const SafetyProblem& p, const std::vector<std::vector<Value>>& inputs,
                                            const std::vector<std::int64_t>& lengths, const Limits& limits) {
  const auto& ts = *p.ts;
  encoder::Encoding enc(ts.ctx());
  enc.ts = ts;
  enc.ts.name_term("checker.good", p.good);
  enc.ts.name_term("checker.facts", ts.constraint_formula() && p.assumption);
  encoder::Evaluator ev(enc);
  std::int64_t cycle = 0;
  for (std::size_t j = 0; j < inputs.size(); ++j) {
    std::vector<encoder::Evaluator::Value> in(inputs[j].size());
    for (std::size_t i = 0; i < in.size(); ++i) {
      in[i].i = inputs[j][i].i;
      in[i].f = inputs[j][i].f;
    }
    for (std::int64_t c = 0; c < lengths[j]; ++c, ++cycle) {
      if (cycle % 4096 == 4095) stop_if_interrupted(limits);
      ev.step_raw(in);
      if (!ev.value("checker.facts")) return std::nullopt;
      if (!ev.value("checker.good")) return cycle;
    }
  }
  return std::nullopt;
}

// The macro trace's first `cycles` cycles, each with its inputs and the state
// at its start (for display and the re-check).
Trace expand(const SafetyProblem& p, const std::vector<std::vector<Value>>& inputs,
             const std::vector<std::int64_t>& lengths, std::int64_t cycles) {
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
  for (std::size_t j = 0; j < inputs.size() && static_cast<std::int64_t>(t.cycles.size()) < cycles; ++j) {
    std::vector<encoder::Evaluator::Value> in(inputs[j].size());
    for (std::size_t i = 0; i < in.size(); ++i) {
      in[i].i = inputs[j][i].i;
      in[i].f = inputs[j][i].f;
    }
    for (std::int64_t c = 0; c < lengths[j] && static_cast<std::int64_t>(t.cycles.size()) < cycles; ++c) {
      Trace::Cycle cycle;
      cycle.inputs = inputs[j];
      for (std::size_t v = 0; v < ts.statevars().size() && states; ++v)
        cycle.state.push_back(Value{ts.statevars()[v].var.is_fpa(), ev.state()[v].i, ev.state()[v].f});
      ev.step_raw(in);
      t.cycles.push_back(std::move(cycle));
    }
  }
  return t;
}

}  // namespace

ProverResult AcceleratedBmc::prove(const SafetyProblem& problem, const Limits& limits) {
  const auto start = Clock::now();
  const auto& ts = *problem.ts;
  z3::context& ctx = ts.ctx();
  ProverResult r;
  r.method = method();
  WorkMeter meter(ctx, limits);
  auto finish = [&](UnknownReason reason) {
    r.reason = reason;
    r.work = meter.spent();
    r.seconds = seconds_since(start);
    return r;
  };
  const int max_steps = std::min(kMaxMacroSteps, limits.max_depth);
  try {
    Watchdog watchdog(ctx, limits);
    MacroUnrolling m(problem);
    encoder::Unroller& u = m.unroller();
    z3::solver s = make_solver(ctx, limits.solvers);
    s.add(m.init());
    for (int J = 0; J <= max_steps; ++J) {
      if (limits.interrupted()) return finish(UnknownReason::TimeLimit);
      if (J > 0) s.add(m.step(J - 1));
      z3::expr violated = ctx.bool_const(("macro.violated@" + std::to_string(J)).c_str());
      s.add(z3::implies(violated, m.violation(J)));
      for (int attempt = 0; attempt < kMaxRefinements; ++attempt) {
        if (limits.interrupted()) return finish(UnknownReason::TimeLimit);
        z3::expr_vector assume(ctx);
        assume.push_back(violated);
        z3::check_result cr = check_within(s, meter, assume);
        if (cr == z3::unknown) return finish(unknown_reason(s.reason_unknown(), limits, meter, &r.detail));
        if (cr == z3::unsat) break;
        z3::model model = s.get_model();
        std::vector<std::vector<Value>> inputs;
        std::vector<std::int64_t> lengths;
        z3::expr_vector same(ctx);
        for (int j = 0; j <= J; ++j) {
          std::vector<Value> in;
          for (const auto& i : ts.inputvars()) in.push_back(value_in(model, u.var_at(i.var, j)));
          inputs.push_back(std::move(in));
          std::int64_t n = j < J ? model.eval(m.length(j), true).get_numeral_int64() : 1;
          lengths.push_back(n);
          if (j < J) same.push_back(m.length(j) == ctx.int_val(n));
        }
        if (auto last = first_violation(problem, inputs, lengths, limits)) {
          if (*last >= kMaxTraceCycles) {
            r.detail = "a counterexample of " + std::to_string(*last + 1) + " cycles, longer than the " +
                       std::to_string(kMaxTraceCycles) + " cycles cemv holds cycle by cycle";
            return finish(UnknownReason::MemoryLimit);
          }
          r.verdict = Verdict::Falsified;
          r.k = static_cast<int>(*last);
          r.cex = expand(problem, inputs, lengths, *last + 1);
          return finish(UnknownReason::None);
        }
        // Spurious (the stretch is not what its end points claimed): exclude
        // these lengths and ask again.
        s.add(same.empty() ? ctx.bool_val(false) : !z3::mk_and(same));
      }
    }
  } catch (const z3::exception& e) {
    return finish(unknown_reason(e.msg(), limits, meter, &r.detail));
  } catch (const std::logic_error& e) {
    r.detail = e.what();
    return finish(UnknownReason::CannotRun);
  }
  return finish(UnknownReason::BoundReached);
}

}  // namespace cemv::checker
