#include "checker/engines/bmc.hpp"

#include "checker/engines/solving.hpp"
#include "encoder/unroller.hpp"

namespace cemv::checker {

ProverResult Bmc::prove(const SafetyProblem& problem, const Limits& limits) {
  const auto start = Clock::now();
  const auto& ts = *problem.ts;
  z3::context& ctx = ts.ctx();
  encoder::Unroller u(ts);
  z3::solver s = make_solver(ctx, limits.solvers);
  Watchdog watchdog(ctx, limits);
  WorkMeter meter(ctx, limits);
  ProverResult r;
  r.method = method();
  auto finish = [&](int k, UnknownReason why) {
    r.reason = why;
    r.k = k;
    r.work = meter.spent();
    r.seconds = seconds_since(start);
    return r;
  };
  const z3::expr cycle_facts = ts.constraint_formula() && problem.assumption;
  const z3::expr trans = ts.trans_formula();
  try {
    s.add(u.at(ts.init_formula(), 0));
    for (int k = 0; k <= limits.max_depth; ++k) {
      if (limits.interrupted()) return finish(k, UnknownReason::TimeLimit);
      s.add(u.at(cycle_facts, k));
      z3::expr violated = ctx.bool_const(("bmc.violated@" + std::to_string(k)).c_str());
      s.add(z3::implies(violated, !u.at(problem.good, k)));
      z3::expr_vector assume(ctx);
      assume.push_back(violated);
      z3::check_result cr = check_within(s, meter, assume);
      if (cr == z3::sat) {
        // Reading the model is solver work too, and the watchdog may cancel
        // it: the verdict is set only once the trace is read, never a
        // Falsified without its counterexample.
        Trace cex = trace_from_model(ts, u, s.get_model(), k);
        r.verdict = Verdict::Falsified;
        r.cex = std::move(cex);
        return finish(k, UnknownReason::None);
      }
      if (cr == z3::unknown) return finish(k, unknown_reason(s.reason_unknown(), limits, meter, &r.detail));
      s.add(u.at(problem.good, k));
      s.add(u.at(trans, k));
    }
  } catch (const z3::exception& e) {
    return finish(r.k, unknown_reason(e.msg(), limits, meter, &r.detail));
  }
  return finish(limits.max_depth, UnknownReason::BoundReached);
}

}  // namespace cemv::checker
