#include "testgen/sweep.hpp"

#include <algorithm>
#include <memory>
#include <optional>

#include "checker/context_pool.hpp"
#include "checker/engines/accelerated_bmc.hpp"
#include "checker/engines/macro_unrolling.hpp"
#include "checker/engines/solving.hpp"
#include "checker/property_problem.hpp"
#include "checker/random_runs.hpp"
#include "checker/shrink.hpp"
#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"
#include "encoder/unroller.hpp"
#include "properties/monitor.hpp"
#include "testgen/search.hpp"

namespace cemv::testgen::detail {

namespace {

constexpr float kAnalogRange = 1e9f;  // as Searcher's questions (testgen/search.cpp)

z3::expr float_cmp(const encoder::Encoding& enc, const z3::expr& var, float v, bool geq) {
  z3::context& ctx = var.ctx();
  const z3::expr c = enc.ts.float_const(v);
  return z3::expr(ctx, geq ? Z3_mk_fpa_geq(ctx, var, c) : Z3_mk_fpa_leq(ctx, var, c));
}

// Each analog input within +/- 1e9 and one of the values an engineer sets
// (the end of the prefix held), the question Searcher::find asks first.
z3::expr input_ranges(const model::Matrix& m, const encoder::Encoding& enc, const model::CycleInput& hold) {
  z3::context& ctx = enc.ts.ctx();
  z3::expr all = ctx.bool_val(true);
  for (const auto& in : enc.ts.inputvars())
    if (in.var.is_fpa())
      all = all && float_cmp(enc, in.var, -kAnalogRange, true) && float_cmp(enc, in.var, kAnalogRange, false);
  const model::InputTable table(m);
  for (std::size_t i = 0; i < table.size() && i < enc.tag_value.size(); ++i) {
    if (table.tags()[i].kind != model::TagKind::Analog || !enc.tag_value[i] || !enc.tag_value[i]->is_fpa()) continue;
    z3::expr any = ctx.bool_val(false);
    for (float v : checker::analog_test_values(m, table.tags()[i], hold.tags[i].value))
      any = any || z3::expr(ctx, Z3_mk_fpa_eq(ctx, *enc.tag_value[i], enc.ts.float_const(v)));
    all = all && any;
  }
  return all;
}


// Every open target the solver's model reaches, then each other one in
// catalogue order that the same run can reach as well (its literal added to
// those kept, one incremental call each); `reached` gets their indices. The
// model of the last satisfiable call.
z3::model keep_compatible(z3::solver& s, checker::WorkMeter& meter, const std::vector<std::optional<z3::expr>>& lit,
                          const std::vector<std::optional<z3::expr>>& target, std::vector<std::size_t>& reached) {
  z3::model model = s.get_model();
  std::vector<z3::expr> kept;
  for (std::size_t i = 0; i < lit.size(); ++i)
    if (lit[i] && model.eval(*target[i], true).is_true()) {
      kept.push_back(*lit[i]);
      reached.push_back(i);
    }
  for (std::size_t i = 0; i < lit.size(); ++i) {
    if (!lit[i] || model.eval(*target[i], true).is_true()) continue;
    z3::expr_vector more(s.ctx());  // a fresh vector: z3's copies share theirs
    for (const auto& e : kept) more.push_back(e);
    more.push_back(*lit[i]);
    const z3::check_result c = checker::check_within(s, meter, more);
    if (c == z3::unknown) break;  // the work left goes to the witness as found so far
    if (c != z3::sat) continue;
    model = s.get_model();
    kept.push_back(*lit[i]);
    reached.push_back(i);
  }
  return model;
}

// The question's system: the union of the cones, every target's monitor
// compiled in, the state the prefix leaves as the initial state.
struct Built {
  std::shared_ptr<encoder::Encoding> enc;
  std::vector<properties::Monitor> monitors;
  z3::expr assumption;
  std::vector<bool> open;  // the targets asked
};

Built build(z3::context& ctx, const model::Matrix& m, const SweepQuestion& q, const model::CycleInput& hold) {
  std::shared_ptr<encoder::Encoding> enc = encoder::encode(ctx, m, q.roots);
  std::vector<properties::Monitor> monitors;
  for (const properties::Property* p : q.targets) monitors.push_back(properties::compile_monitor(*enc, *p, q.file->assumptions));
  const z3::expr assumption = monitors.front().assumption && input_ranges(m, *enc, hold);
  checker::start_after(*enc, q.prefix ? *q.prefix : std::vector<model::CycleInput>{});
  // Only the targets that share the first one's assumptions are asked: one
  // unrolling assumes one thing in every cycle.
  std::vector<bool> open(monitors.size());
  for (std::size_t i = 0; i < monitors.size(); ++i) open[i] = z3::eq(monitors[i].assumption, monitors.front().assumption);
  return Built{std::move(enc), std::move(monitors), assumption, std::move(open)};
}

// The witness found (every kept target reached in its last cycle) made
// readable: inputs it does not need keep their held value.
SweepAnswer finish(const model::Matrix& m, const TestgenOptions& options, const SweepQuestion& q, const Built& b,
                   const model::CycleInput& hold, const checker::Limits& limits,
                   const std::optional<checker::Trace>& found, SweepAnswer& out) {
  z3::context& ctx = b.enc->ts.ctx();
  const std::vector<properties::Monitor>& monitors = b.monitors;
  const encoder::TransitionSystem& ts = b.enc->ts;
  const z3::expr& assumption = b.assumption;
  const std::shared_ptr<encoder::Encoding>& enc = b.enc;
  checker::stop_if_interrupted(limits);
  if (!found) {
    if (out.reason.empty())
      out.reason = std::string("not found (") + (q.held ? "held sweep, steps " : "sweep, depth ") + std::to_string(q.max_depth) + ")";
    return out;
  }
  z3::expr good = ctx.bool_val(false);
  for (std::size_t i : out.reached) good = good || monitors[i].good;
  const checker::SafetyProblem problem{&ts, good, assumption};
  const checker::Trace readable =
      checker::shrink_trace(problem, *found, held_inputs(*enc, hold), limits.with_work(options.shrink_work));
  checker::stop_if_interrupted(limits);
  out.cycles = witness_inputs(readable, *enc, m, hold);
  return out;
}

SweepAnswer sweep_cycles(const model::Matrix& m, const TestgenOptions& options, const SweepQuestion& q) {
  SweepAnswer out;
  checker::PooledContext pooled;
  z3::context& ctx = pooled;
  const model::CycleInput hold = !q.prefix || q.prefix->empty() ? model::default_cycle_input(m) : q.prefix->back();
  const Built b = build(ctx, m, q, hold);
  const std::shared_ptr<encoder::Encoding>& enc = b.enc;
  const std::vector<properties::Monitor>& monitors = b.monitors;
  const z3::expr& assumption = b.assumption;
  const std::vector<bool>& open = b.open;
  const encoder::TransitionSystem& ts = enc->ts;

  checker::Limits limits;
  limits.cancel = options.cancel;
  checker::WorkMeter meter(ctx, q.budget);
  std::optional<checker::Trace> found;
  try {
    checker::Watchdog watchdog(ctx, limits);
    encoder::Unroller u(ts);
    z3::solver s(ctx);
    s.add(u.at(ts.init_formula(), 0));
    const z3::expr facts = ts.constraint_formula() && assumption;
    for (int k = 0; k < q.max_depth && !found; ++k) {
      checker::stop_if_interrupted(limits);
      s.add(u.at(facts, k));
      // One activation literal per open target at this depth.
      std::vector<std::optional<z3::expr>> lit(monitors.size());
      z3::expr_vector any(ctx);
      for (std::size_t i = 0; i < monitors.size(); ++i) {
        if (!open[i]) continue;
        lit[i] = ctx.bool_const(("sweep." + std::to_string(k) + "." + std::to_string(i)).c_str());
        s.add(z3::implies(*lit[i], !u.at(monitors[i].good, k)));
        any.push_back(*lit[i]);
      }
      if (any.empty()) break;
      z3::expr some = ctx.bool_const(("sweep.any." + std::to_string(k)).c_str());
      s.add(z3::implies(some, z3::mk_or(any)));
      z3::expr_vector a(ctx);
      a.push_back(some);
      z3::check_result cr = checker::check_within(s, meter, a);
      if (cr == z3::unknown) {
        out.reason = std::string(checker::to_string(checker::unknown_reason(s.reason_unknown(), limits, meter))) + " (sweep, depth " +
                     std::to_string(k) + ")";
        break;
      }
      if (cr == z3::sat) {
        std::vector<std::optional<z3::expr>> reached_at(monitors.size());
        for (std::size_t i = 0; i < monitors.size(); ++i)
          if (lit[i]) reached_at[i] = !u.at(monitors[i].good, k);
        z3::model model = keep_compatible(s, meter, lit, reached_at, out.reached);
        std::sort(out.reached.begin(), out.reached.end());
        found = checker::trace_from_model(ts, u, model, k);
        break;
      }
      s.add(u.at(ts.trans_formula(), k));
    }
  } catch (const z3::exception& e) {
    checker::stop_if_interrupted(limits);
    out.reached.clear();
    out.reason = std::string(checker::to_string(checker::unknown_reason(e.msg(), limits, meter))) + " (sweep)";
    return out;
  }
  return finish(m, options, q, b, hold, limits, found, out);
}

// Macro steps of held inputs instead of cycles: a timer's stretch is one step.
SweepAnswer sweep_held(const model::Matrix& m, const TestgenOptions& options, const SweepQuestion& q) {
  SweepAnswer out;
  checker::PooledContext pooled;
  z3::context& ctx = pooled;
  const model::CycleInput hold = !q.prefix || q.prefix->empty() ? model::default_cycle_input(m) : q.prefix->back();
  const Built b = build(ctx, m, q, hold);
  const encoder::TransitionSystem& ts = b.enc->ts;
  // The stretches' facts: the cycle's constraints and the question's assumption.
  const checker::SafetyProblem facts{&ts, ctx.bool_val(true), b.assumption};
  checker::Limits limits;
  limits.cancel = options.cancel;
  checker::WorkMeter meter(ctx, q.budget);
  std::optional<checker::Trace> found;
  try {
    checker::Watchdog watchdog(ctx, limits);
    checker::MacroUnrolling mu(facts);
    encoder::Unroller& u = mu.unroller();
    z3::solver s(ctx);
    s.add(mu.init());
    z3::expr total = ctx.int_val(1);  // the last cycle
    for (int J = 0; J <= q.max_depth && !found && out.reason.empty(); ++J) {
      checker::stop_if_interrupted(limits);
      if (J > 0) {
        s.add(mu.step(J - 1));
        total = total + mu.length(J - 1);
        s.add(total <= ctx.int_val(static_cast<int64_t>(q.max_cycles)));
      }
      s.add(u.at(ts.constraint_formula() && b.assumption, J));
      std::vector<std::optional<z3::expr>> lit(b.monitors.size()), reached_at(b.monitors.size());
      z3::expr_vector any(ctx);
      for (std::size_t i = 0; i < b.monitors.size(); ++i) {
        if (!b.open[i]) continue;
        lit[i] = ctx.bool_const(("held." + std::to_string(J) + "." + std::to_string(i)).c_str());
        reached_at[i] = !u.at(b.monitors[i].good, J);
        s.add(z3::implies(*lit[i], *reached_at[i]));
        any.push_back(*lit[i]);
      }
      if (any.empty()) break;
      const z3::expr some = ctx.bool_const(("held.any." + std::to_string(J)).c_str());
      s.add(z3::implies(some, z3::mk_or(any)));
      for (int attempt = 0; attempt < checker::AcceleratedBmc::kMaxRefinements && !found; ++attempt) {
        z3::expr_vector a(ctx);
        a.push_back(some);
        const z3::check_result cr = checker::check_within(s, meter, a);
        if (cr == z3::unknown) {
          out.reason = std::string(checker::to_string(checker::unknown_reason(s.reason_unknown(), limits, meter))) +
                       " (held sweep, step " + std::to_string(J) + ")";
          break;
        }
        if (cr == z3::unsat) break;
        std::vector<std::size_t> reached;
        const z3::model model = keep_compatible(s, meter, lit, reached_at, reached);
        const checker::MacroRun run = checker::macro_run(mu, ts, model, J);
        z3::expr good = ctx.bool_val(false);
        for (std::size_t i : reached) good = good || b.monitors[i].good;
        const checker::SafetyProblem kept{&ts, good, b.assumption};
        if (auto last = checker::first_violation(kept, run, limits)) {
          std::sort(reached.begin(), reached.end());
          out.reached = std::move(reached);
          found = checker::expand(kept, run, *last + 1);
          break;
        }
        // The stretches only approximated these targets: exclude the lengths.
        z3::expr_vector same(ctx);
        for (int j = 0; j < J; ++j) same.push_back(mu.length(j) == ctx.int_val(static_cast<int64_t>(run.lengths[j])));
        s.add(same.empty() ? ctx.bool_val(false) : !z3::mk_and(same));
      }
    }
  } catch (const z3::exception& e) {
    checker::stop_if_interrupted(limits);
    out.reached.clear();
    out.reason = std::string(checker::to_string(checker::unknown_reason(e.msg(), limits, meter))) + " (held sweep)";
    return out;
  }
  return finish(m, options, q, b, hold, limits, found, out);
}

}  // namespace

SweepAnswer sweep(const model::Matrix& m, const TestgenOptions& options, const SweepQuestion& q) {
  if (q.targets.empty()) return SweepAnswer{};
  return q.held ? sweep_held(m, options, q) : sweep_cycles(m, options, q);
}

}  // namespace cemv::testgen::detail
