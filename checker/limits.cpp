#include "checker/limits.hpp"

#include <string>

namespace cemv::checker {

Work resource_count(z3::context& ctx) {
  z3::solver s(ctx);
  return resource_count(s);
}

Work resource_count(z3::solver& probe) {
  z3::stats st = probe.statistics();
  for (unsigned i = 0; i < st.size(); ++i)
    if (st.key(i) == "rlimit count")
      return st.is_uint(i) ? st.uint_value(i) : static_cast<Work>(st.double_value(i));
  return 0;
}

z3::solver make_solver(z3::context& ctx, SolverSetup setup) {
  if (setup == SolverSetup::SmtKernel) return z3::solver(ctx, z3::solver::simple());
  return z3::solver(ctx);
}

z3::solver linear_integer_solver(z3::context& ctx) {
  z3::solver s(ctx, "QF_LIA");
  z3::params params(ctx);
  params.set("arith.solver", 2u);
  s.set(params);
  return s;
}

WorkMeter::WorkMeter(z3::context& ctx, Work budget, SolverSetup setup) : ctx_(ctx), budget_(budget) {
  if (setup == SolverSetup::SmtKernel) probe_.emplace(z3::tactic(ctx, "skip").mk_solver());
  start_ = read();
}

Work WorkMeter::read() const { return probe_ ? resource_count(*probe_) : resource_count(ctx_); }

WorkMeter::~WorkMeter() { Z3_update_param_value(ctx_, "rlimit", "0"); }

Work WorkMeter::spent() const { return read() - start_; }

bool WorkMeter::arm() {
  if (budget_ == 0) {
    Z3_update_param_value(ctx_, "rlimit", "0");
    return true;
  }
  const Work used = spent();
  if (used >= budget_) return false;
  // The limit is relative to the count when a check starts (Z3's
  // scoped_rlimit), and an unsigned int.
  Work left = budget_ - used;
  if (left > 4000000000ULL) left = 4000000000ULL;
  Z3_update_param_value(ctx_, "rlimit", std::to_string(left).c_str());
  return true;
}

}  // namespace cemv::checker
