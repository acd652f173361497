#include "checker/engines/pdr.hpp"

#include "checker/engines/bmc.hpp"
#include "checker/engines/solving.hpp"

namespace cemv::checker {

namespace {

// The conjuncts of `e` (flattening nested ands), as separate clauses.
void conjuncts(const z3::expr& e, std::vector<z3::expr>& out) {
  if (e.is_app() && e.decl().decl_kind() == Z3_OP_AND) {
    for (unsigned i = 0; i < e.num_args(); ++i) conjuncts(e.arg(i), out);
    return;
  }
  if (e.is_true()) return;
  out.push_back(e);
}

}  // namespace

ProverResult Pdr::prove(const SafetyProblem& problem, const Limits& limits) {
  const auto start = Clock::now();
  const auto& ts = *problem.ts;
  z3::context& ctx = ts.ctx();
  ProverResult r;
  r.method = method();
  WorkMeter meter(ctx, limits);
  try {
    z3::fixedpoint fp(ctx);
    // Declared after the fixedpoint, so destroyed (clearing the interrupt)
    // before it: see Watchdog.
    Watchdog watchdog(ctx, limits);
    z3::params p(ctx);
    p.set("engine", "spacer");
    fp.set(p);

    z3::sort_vector domain(ctx);
    z3::expr_vector state(ctx), next(ctx), all(ctx);
    for (const auto& s : ts.statevars()) {
      domain.push_back(s.var.get_sort());
      state.push_back(s.var);
      next.push_back(s.next_var);
      all.push_back(s.var);
      all.push_back(s.next_var);
    }
    for (const auto& i : ts.inputvars()) all.push_back(i.var);
    z3::func_decl inv = ctx.function("pdr.Inv", domain, ctx.bool_sort());
    z3::func_decl bad = ctx.function("pdr.Bad", z3::sort_vector(ctx), ctx.bool_sort());
    fp.register_relation(inv);
    fp.register_relation(bad);
    const z3::expr facts = ts.constraint_formula() && problem.assumption;
    z3::expr init_rule = z3::forall(all, z3::implies(ts.init_formula(), inv(state)));
    z3::expr step_rule = z3::forall(all, z3::implies(inv(state) && facts && ts.trans_formula(), inv(next)));
    z3::expr bad_rule = z3::forall(all, z3::implies(inv(state) && facts && !problem.good, bad()));
    fp.add_rule(init_rule, ctx.str_symbol("pdr.init"));
    fp.add_rule(step_rule, ctx.str_symbol("pdr.step"));
    fp.add_rule(bad_rule, ctx.str_symbol("pdr.bad"));
    z3::expr query = bad();
    // A fixedpoint query takes no `rlimit` of its own: the context's, which
    // the meter sets, bounds it.
    z3::check_result cr = meter.arm() ? fp.query(query) : z3::unknown;
    if (cr == z3::unsat) {
      z3::func_decl inv_decl = inv;
      z3::expr cover = fp.get_cover_delta(-1, inv_decl);
      // The cover is over de Bruijn variables, one per argument of Inv.
      z3::expr invariant = cover.substitute(state);
      std::vector<z3::expr> clauses;
      conjuncts(invariant.simplify(), clauses);
      for (const auto& c : clauses) r.invariant.clauses.push_back(to_smtlib(c));
      r.verdict = Verdict::Proved;
      r.k = 0;
    } else if (cr == z3::sat) {
      // Spacer knows a counterexample exists; BMC finds a shortest one,
      // within what is left of the budget.
      const Work spent = meter.spent();
      Limits rest = limits.with_depth(std::max(limits.max_depth, 100000));
      if (limits.work != 0) rest.work = limits.work > spent ? limits.work - spent : 1;
      ProverResult b = Bmc().prove(problem, rest);
      if (b.verdict == Verdict::Falsified) {
        r.verdict = Verdict::Falsified;
        r.k = b.k;
        r.cex = std::move(b.cex);
      } else {
        r.reason = b.reason;
        r.detail = b.detail;
      }
    } else {
      r.reason = unknown_reason(fp.reason_unknown(), limits, meter, &r.detail);
    }
  } catch (const z3::exception& e) {
    r.reason = unknown_reason(e.msg(), limits, meter, &r.detail);
  }
  r.work = meter.spent();
  r.seconds = seconds_since(start);
  return r;
}

}  // namespace cemv::checker
