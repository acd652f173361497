#include "checker/shrink.hpp"

#include <unordered_set>

#include "checker/engines/solving.hpp"
#include "encoder/unroller.hpp"

namespace cemv::checker {

namespace {

z3::expr constant_of(const encoder::TransitionSystem& ts, const z3::expr& var, const Value& v) {
  z3::context& ctx = ts.ctx();
  if (var.is_bool()) return ctx.bool_val(v.i != 0);
  if (var.is_int()) return ctx.int_val(static_cast<int64_t>(v.i));
  return ts.float_const(v.is_float ? v.f : static_cast<float>(v.i));
}

}  // namespace

Trace shrink_trace(const SafetyProblem& problem, const Trace& cex, const PreferredValue& preferred,
                   const Limits& limits, std::size_t max_cycles) {
  const std::size_t n = cex.length();
  if (n == 0 || n > max_cycles || limits.over()) return cex;
  const auto& ts = *problem.ts;
  z3::context& ctx = ts.ctx();
  encoder::Unroller u(ts);
  z3::solver s(ctx);
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

  // One literal per (cycle, input with a preferred value), in a fixed order.
  z3::expr_vector literals(ctx);
  for (int k = 0; k <= last; ++k)
    for (const auto& in : ts.inputvars()) {
      std::optional<Value> v = preferred(in.name);
      if (!v) continue;
      z3::expr lit = ctx.bool_const(("shrink." + std::to_string(k) + "." + in.name).c_str());
      s.add(z3::implies(lit, u.var_at(in.var, k) == constant_of(ts, in.var, *v)));
      literals.push_back(lit);
    }
  try {
    Watchdog watchdog(ctx, limits);
    for (int round = 0; round < 64; ++round) {
      set_timeout(s, limits);
      z3::check_result r = s.check(literals);
      if (r == z3::sat) return trace_from_model(ts, u, s.get_model(), last);
      if (r != z3::unsat) return cex;
      z3::expr_vector core = s.unsat_core();
      if (core.size() == 0) return cex;
      std::unordered_set<unsigned> drop;
      for (unsigned i = 0; i < core.size(); ++i) drop.insert(core[i].id());
      z3::expr_vector kept(ctx);
      for (unsigned i = 0; i < literals.size(); ++i)
        if (!drop.count(literals[i].id())) kept.push_back(literals[i]);
      literals = kept;
    }
  } catch (const z3::exception&) {
    // A limit or a solver failure: the engine's own (already re-checked)
    // trace stands.
  }
  return cex;
}

}  // namespace cemv::checker
