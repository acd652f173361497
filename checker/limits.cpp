#include "checker/limits.hpp"

#include <string>

namespace cemv::checker {

// The count is the context's (its resource limit), reported in the
// statistics of every solver. A solver of the `skip` tactic reports it
// without setting up an SMT solver: a default solver's statistics build one
// (tens of milliseconds of parameter lookups in Z3 4.8.12) and spend work.
z3::solver stats_probe(z3::context& ctx) { return z3::tactic(ctx, "skip").mk_solver(); }

Work resource_count(z3::context& ctx) {
  z3::solver probe = stats_probe(ctx);
  return resource_count(probe);
}

Work resource_count(z3::solver& probe) {
  z3::stats st = probe.statistics();
  for (unsigned i = 0; i < st.size(); ++i)
    if (st.key(i) == "rlimit count")
      return st.is_uint(i) ? st.uint_value(i) : static_cast<Work>(st.double_value(i));
  return 0;
}

WorkMeter::WorkMeter(z3::context& ctx, Work budget)
    : ctx_(ctx), probe_(stats_probe(ctx)), budget_(budget), start_(resource_count(probe_)) {}

WorkMeter::~WorkMeter() { Z3_update_param_value(ctx_, "rlimit", "0"); }

Work WorkMeter::spent() const { return resource_count(probe_) - start_; }

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
