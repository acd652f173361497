#include "checker/engines/bmc.hpp"

#include "checker/engines/solving.hpp"
#include "encoder/unroller.hpp"

namespace cemv::checker {

ProverResult Bmc::prove(const SafetyProblem& problem, const Limits& limits) {
  const auto start = std::chrono::steady_clock::now();
  const auto& ts = *problem.ts;
  z3::context& ctx = ts.ctx();
  encoder::Unroller u(ts);
  z3::solver s(ctx);
  Watchdog watchdog(ctx, limits);
  ProverResult r;
  r.method = name();
  const z3::expr cycle_facts = ts.constraint_formula() && problem.assumption;
  const z3::expr trans = ts.trans_formula();
  try {
    s.add(u.at(ts.init_formula(), 0));
    for (int k = 0; k <= limits.max_depth; ++k) {
      if (limits.over()) {
        r.reason = "time limit";
        r.k = k;
        r.seconds = seconds_since(start);
        return r;
      }
      s.add(u.at(cycle_facts, k));
      z3::expr violated = ctx.bool_const(("bmc.violated@" + std::to_string(k)).c_str());
      s.add(z3::implies(violated, !u.at(problem.good, k)));
      set_timeout(s, limits);
      z3::expr_vector assume(ctx);
      assume.push_back(violated);
      z3::check_result cr = s.check(assume);
      if (cr == z3::sat) {
        // Reading the model is solver work too, and the watchdog may cancel
        // it when the deadline passes: the verdict is set only once the
        // trace is read, never a Falsified without its counterexample.
        Trace cex = trace_from_model(ts, u, s.get_model(), k);
        r.verdict = Verdict::Falsified;
        r.k = k;
        r.cex = std::move(cex);
        r.seconds = seconds_since(start);
        return r;
      }
      if (cr == z3::unknown) {
        r.reason = unknown_reason(s.reason_unknown(), limits);
        r.k = k;
        r.seconds = seconds_since(start);
        return r;
      }
      s.add(u.at(problem.good, k));
      s.add(u.at(trans, k));
    }
  } catch (const z3::exception& e) {
    r.reason = unknown_reason(e.msg(), limits);
    r.seconds = seconds_since(start);
    return r;
  }
  r.reason = "bound reached";
  r.k = limits.max_depth;
  r.seconds = seconds_since(start);
  return r;
}

}  // namespace cemv::checker
