#include "checker/check/recheck.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <set>

#include "checker/context_pool.hpp"
#include "checker/engines/solving.hpp"
#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"
#include "encoder/unroller.hpp"

namespace cemv::checker::check {

namespace {

struct Obligation {
  std::string name;
  z3::expr formula;  // must be unsat
};

// The obligations of ProverResult's proof rule for invariant S and depth k.
std::vector<Obligation> obligations(const SafetyProblem& p, const ProverResult& r) {
  const auto& ts = *p.ts;
  z3::context& ctx = ts.ctx();
  encoder::Unroller u(ts);
  const z3::expr S = invariant_term(ts, r.invariant);
  const z3::expr facts = ts.constraint_formula() && p.assumption;
  const z3::expr trans = ts.trans_formula();
  std::vector<Obligation> out;
  out.push_back({"invariant-init", u.at(ts.init_formula(), 0) && !u.at(S, 0)});
  out.push_back({"invariant-step", u.at(S && facts && trans, 0) && !u.at(S, 1)});
  const int k = r.k;
  if (k >= 1) {
    z3::expr_vector path(ctx), bad(ctx);
    path.push_back(u.at(ts.init_formula(), 0));
    for (int j = 0; j < k; ++j) {
      path.push_back(u.at(facts, j));
      if (j + 1 < k) path.push_back(u.at(trans, j));
      bad.push_back(!u.at(p.good, j));
    }
    out.push_back({"base", z3::mk_and(path) && z3::mk_or(bad)});
  }
  z3::expr_vector step(ctx);
  for (int j = 0; j <= k; ++j) {
    step.push_back(u.at(S && facts, j));
    if (j < k) {
      step.push_back(u.at(p.good, j));
      step.push_back(u.at(trans, j));
    }
  }
  if (r.simple_path)
    for (int j = 1; j <= k; ++j)
      for (int i = 0; i < j; ++i) {
        z3::expr_vector differ(ctx);
        for (const auto& s : ts.statevars()) differ.push_back(u.var_at(s.var, i) != u.var_at(s.var, j));
        step.push_back(differ.empty() ? ctx.bool_val(false) : z3::mk_or(differ));
      }
  step.push_back(!u.at(p.good, k));
  out.push_back({"step", z3::mk_and(step)});
  return out;
}

// The problem built again, by its factory, in a context that holds no term,
// solver or model of the engine that found the answer.
template <class F>
auto in_fresh_context(const ProblemFactory& make, F&& f) {
  PooledContext ctx;
  OwnedProblem owned = make(ctx);
  return f(owned.problem);
}

}  // namespace

void recheck_proof(const SafetyProblem& problem, const ProverResult& result, const Limits* limits) {
  if (result.verdict != Verdict::Proved) throw InternalError("recheck_proof: not a proof");
  std::vector<Obligation> obs;
  try {
    obs = obligations(problem, result);
  } catch (const z3::exception& e) {
    if (limits) stop_if_interrupted(*limits);  // an interrupted context refuses any parse
    throw InternalError(result.method_text() + " proof: the invariant does not parse: " + e.msg());
  }
  // One fresh solver for the obligations, each in its own scope: in
  // incremental mode Z3 skips the per-query preprocessing that dominated
  // re-checking the many small proofs of a standard property set.
  z3::solver s = make_solver(problem.ts->ctx(), limits ? limits->solvers : SolverSetup::DefaultSolver);
  std::optional<Watchdog> watchdog;
  if (limits) watchdog.emplace(problem.ts->ctx(), *limits);
  for (const auto& o : obs) {
    z3::check_result cr = z3::unknown;
    // Once the watchdog has interrupted the context, every call on it throws
    // "canceled" (push and add too), which is the user's time limit, not a bug.
    try {
      s.push();
      s.add(o.formula);
      cr = s.check();
    } catch (const z3::exception&) {
      if (limits) stop_if_interrupted(*limits);
      throw;
    }
    if (cr == z3::unknown && limits) stop_if_interrupted(*limits);
    if (cr != z3::unsat)
      throw InternalError(result.method_text() + " proof (k=" + std::to_string(result.k) + ") fails its re-check: " +
                          o.name + " is " + (cr == z3::sat ? "sat" : "unknown (" + s.reason_unknown() + ")") +
                          "\ninvariant:\n" + result.invariant.text());
    try {
      s.pop();
    } catch (const z3::exception&) {
      if (limits) stop_if_interrupted(*limits);
      throw;
    }
  }
}

std::optional<std::vector<z3::expr>> proof_core(const SafetyProblem& problem, const ProverResult& result,
                                                const std::vector<z3::expr>& literals,
                                                const std::vector<z3::expr>& fixed, Work work, const Limits& limits) {
  std::vector<Obligation> obs;
  try {
    obs = obligations(problem, result);
  } catch (const z3::exception&) {
    return std::nullopt;  // an invariant over variables this problem does not have
  }
  z3::context& ctx = problem.ts->ctx();
  z3::solver s = make_solver(ctx, limits.solvers);
  for (const auto& f : fixed) s.add(f);
  z3::expr_vector assumptions(ctx);
  for (const auto& l : literals) assumptions.push_back(l);
  std::vector<z3::expr> core;
  std::set<unsigned> in_core;
  Watchdog watchdog(ctx, limits);
  WorkMeter meter(ctx, work, limits.solvers);
  for (const auto& o : obs) {
    z3::check_result cr = z3::unknown;
    try {
      s.push();
      s.add(o.formula);
      cr = check_within(s, meter, assumptions);
    } catch (const z3::exception&) {
      stop_if_interrupted(limits);
      return std::nullopt;
    }
    stop_if_interrupted(limits);
    if (cr != z3::unsat) return std::nullopt;
    try {
      const z3::expr_vector used = s.unsat_core();
      for (unsigned i = 0; i < used.size(); ++i)
        if (in_core.insert(used[i].id()).second) core.push_back(used[i]);
      s.pop();
    } catch (const z3::exception&) {
      stop_if_interrupted(limits);
      return std::nullopt;
    }
  }
  return core;
}

void recheck_proof(const ProblemFactory& make, const ProverResult& result, const Limits* limits) {
  in_fresh_context(make, [&](const SafetyProblem& p) {
    recheck_proof(p, result, limits);
    return 0;
  });
}

namespace {
void replay_on_evaluator(const SafetyProblem& problem, const Trace& cex, const Limits* limits);
}  // namespace

void replay_counterexample(const SafetyProblem& problem, const Trace& cex, const Limits* limits) {
  try {
    replay_on_evaluator(problem, cex, limits);
  } catch (const std::logic_error& e) {
    // An operator the Evaluator does not interpret: the trace cannot be
    // re-checked, so it must not be reported.
    throw InternalError(std::string("counterexample cannot be re-simulated: ") + e.what());
  }
}

namespace {
void replay_on_evaluator(const SafetyProblem& problem, const Trace& cex, const Limits* limits) {
  const auto& ts = *problem.ts;
  if (cex.cycles.empty()) throw InternalError("counterexample without cycles");
  // The Evaluator runs an Encoding; a copy of the system with the property's
  // terms named lets it evaluate them as well.
  encoder::Encoding enc(ts.ctx());
  enc.ts = ts;
  enc.ts.name_term("checker.good", problem.good);
  enc.ts.name_term("checker.assumption", problem.assumption);
  enc.ts.name_term("checker.constraints", ts.constraint_formula());
  std::vector<std::size_t> slot;  // trace column of each input variable
  for (const auto& i : ts.inputvars()) {
    std::size_t c = 0;
    while (c < cex.input_names.size() && cex.input_names[c] != i.name) ++c;
    if (c == cex.input_names.size()) throw InternalError("counterexample lacks input " + i.name);
    slot.push_back(c);
  }
  encoder::Evaluator ev(enc);
  const bool has_states = cex.state_names.size() == ts.statevars().size();
  for (std::size_t k = 0; k < cex.cycles.size(); ++k) {
    if (limits && k % 4096 == 4095) stop_if_interrupted(*limits);
    // The engine's states (for display) must be the ones the formulas compute.
    if (has_states)
      for (std::size_t i = 0; i < ts.statevars().size(); ++i) {
        const Value& want = cex.cycles[k].state.at(i);
        const auto& got = ev.state()[i];
        bool same = want.is_float ? std::bit_cast<std::uint32_t>(want.f) == std::bit_cast<std::uint32_t>(got.f)
                                  : want.i == got.i;
        if (!same)
          throw InternalError("counterexample state " + ts.statevars()[i].name + " is " + want.text() +
                              " in the trace but the re-simulation gives " +
                              (want.is_float ? Value{true, 0, got.f}.text() : std::to_string(got.i)) +
                              " at the start of cycle " + std::to_string(k));
      }
    std::vector<encoder::Evaluator::Value> in(slot.size());
    for (std::size_t i = 0; i < slot.size(); ++i) {
      const Value& v = cex.cycles[k].inputs.at(slot[i]);
      in[i].i = v.i;
      in[i].f = v.f;
    }
    ev.step_raw(in);
    const std::string at = " in cycle " + std::to_string(k) + " of " + std::to_string(cex.cycles.size());
    if (!ev.value("checker.constraints")) throw InternalError("counterexample breaks the input constraints" + at);
    if (!ev.value("checker.assumption")) throw InternalError("counterexample breaks the assumption" + at);
  }
  if (ev.value("checker.good")) throw InternalError("counterexample does not violate the property in its last cycle");
}
}  // namespace

void replay_counterexample(const ProblemFactory& make, const Trace& cex, const Limits* limits) {
  in_fresh_context(make, [&](const SafetyProblem& p) {
    replay_counterexample(p, cex, limits);
    return 0;
  });
}

void recheck(const ProblemFactory& make, const ProverResult& result, const Limits* limits) {
  if (result.verdict == Verdict::Proved) recheck_proof(make, result, limits);
  else if (result.verdict == Verdict::Falsified) replay_counterexample(make, result.cex, limits);
}

std::vector<ProofObligation> proof_obligations_smtlib(const SafetyProblem& problem, const ProverResult& result) {
  z3::context& ctx = problem.ts->ctx();
  Z3_set_ast_print_mode(ctx, Z3_PRINT_SMTLIB2_COMPLIANT);
  std::vector<ProofObligation> out;
  for (const auto& o : obligations(problem, result)) {
    std::string comment = "cemv " + result.method_text() + " proof obligation " + o.name + " (expected: unsat)";
    out.push_back({o.name, Z3_benchmark_to_smtlib_string(ctx, comment.c_str(), "ALL", "unsat", "", 0, nullptr,
                                                         o.formula)});
  }
  return out;
}

}  // namespace cemv::checker::check
