#include "checker/engines/accelerated_bmc.hpp"

#include <algorithm>

#include "checker/engines/macro_unrolling.hpp"
#include "checker/engines/solving.hpp"
#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"
#include "encoder/unroller.hpp"

namespace cemv::checker {

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
        const MacroRun run = macro_run(m, ts, model, J);
        z3::expr_vector same(ctx);
        for (int j = 0; j < J; ++j) same.push_back(m.length(j) == ctx.int_val(run.lengths[j]));
        if (auto last = first_violation(problem, run, limits)) {
          if (*last >= kMaxTraceCycles) {
            r.detail = "a counterexample of " + std::to_string(*last + 1) + " cycles, longer than the " +
                       std::to_string(kMaxTraceCycles) + " cycles cemv holds cycle by cycle";
            return finish(UnknownReason::MemoryLimit);
          }
          r.verdict = Verdict::Falsified;
          r.k = static_cast<int>(*last);
          r.cex = expand(problem, run, *last + 1);
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
