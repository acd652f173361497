#include "checker/engines/multi.hpp"
#include "checker/engines/solving.hpp"
#include "encoder/unroller.hpp"

namespace cemv::checker {

std::vector<ProverResult> reach_each(const encoder::TransitionSystem& ts, const std::vector<z3::expr>& targets,
                                     const z3::expr& assumption, const std::vector<bool>& open,
                                     const Limits& limits) {
  z3::context& ctx = ts.ctx();
  std::vector<ProverResult> out(targets.size());
  std::vector<bool> left = open;
  std::size_t count = 0;
  for (bool b : left) count += b;
  WorkMeter meter(ctx, limits);
  UnknownReason stop = UnknownReason::BoundReached;
  try {
    Watchdog watchdog(ctx, limits);
    encoder::Unroller u(ts);
    z3::solver s = make_solver(ctx, limits.solvers);
    const z3::expr facts = ts.constraint_formula() && assumption;
    s.add(u.at(ts.init_formula(), 0));
    for (int k = 0; k <= limits.max_depth && count > 0; ++k) {
      if (limits.interrupted()) {
        stop = UnknownReason::TimeLimit;
        break;
      }
      s.add(u.at(facts, k));
      // One question a depth while some target is reached there: any open
      // target, then every target the model shows is taken from it.
      while (count > 0) {
        z3::expr_vector any(ctx);
        for (std::size_t i = 0; i < targets.size(); ++i)
          if (left[i]) any.push_back(u.at(targets[i], k));
        z3::expr lit = ctx.bool_const(("multi.reach." + std::to_string(k) + "." + std::to_string(count)).c_str());
        s.add(z3::implies(lit, z3::mk_or(any)));
        z3::expr_vector a(ctx);
        a.push_back(lit);
        const z3::check_result cr = check_within(s, meter, a);
        if (cr == z3::unknown) {
          stop = unknown_reason(s.reason_unknown(), limits, meter);
          count = 0;
          break;
        }
        if (cr == z3::unsat) break;
        const z3::model model = s.get_model();
        Trace trace;
        bool read = false;
        for (std::size_t i = 0; i < targets.size(); ++i) {
          if (!left[i] || !model.eval(u.at(targets[i], k), true).is_true()) continue;
          if (!read) trace = trace_from_model(ts, u, model, k);
          read = true;
          out[i].verdict = Verdict::Falsified;
          out[i].method = Method::Bmc;
          out[i].k = k;
          out[i].cex = trace;
          left[i] = false;
          --count;
        }
      }
      if (count > 0) s.add(u.at(ts.trans_formula(), k));
    }
  } catch (const z3::exception& e) {
    stop = unknown_reason(e.msg(), limits, meter);
  }
  for (std::size_t i = 0; i < out.size(); ++i)
    if (open[i] && out[i].verdict == Verdict::Unknown) out[i].reason = stop;
  return out;
}

}  // namespace cemv::checker
