#include "checker/check/recheck.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <unordered_map>

#include "checker/context_pool.hpp"
#include "checker/engines/solving.hpp"
#include "checker/limits.hpp"
#include "checker/reduce_terms.hpp"
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

// From this many clauses an invariant's induction step is re-checked in
// chunks (step_by_chunks): the generated 32 x 32 program's 9,045 clauses
// over 1,047 state variables took 45-55 s as one query. Below it, as one.
constexpr std::size_t kChunkedClauses = 1024;
constexpr std::size_t kChunkClauses = 128;

// The state variables a term reads (indices into ts.statevars()).
class StateReads {
 public:
  explicit StateReads(const encoder::TransitionSystem& ts) {
    for (std::size_t i = 0; i < ts.statevars().size(); ++i) index_.emplace(ts.statevars()[i].var.id(), i);
  }
  std::set<std::size_t> of(const z3::expr& e) const {
    std::set<std::size_t> out;
    for (unsigned id : reduce_terms::variables_of(e))
      if (const auto it = index_.find(id); it != index_.end()) out.insert(it->second);
    return out;
  }

 private:
  std::unordered_map<unsigned, std::size_t> index_;
};

// The conjuncts of `e`.
std::vector<z3::expr> conjuncts_of(const z3::expr& e) {
  std::vector<z3::expr> out;
  reduce_terms::conjuncts(e, out);
  return out;
}

// Whether `premise` and not `goal` is unsat, asked in a scope of `s`.
bool unsat_under(z3::solver& s, const z3::expr& premise, const z3::expr& goal, const Limits* limits) {
  z3::check_result cr = z3::unknown;
  try {
    s.push();
    s.add(premise);
    s.add(!goal);
    cr = s.check();
    s.pop();
  } catch (const z3::exception&) {
    if (limits) stop_if_interrupted(*limits);
    throw;
  }
  if (cr == z3::unknown && limits) stop_if_interrupted(*limits);
  return cr == z3::unsat;
}

// The premises of a large invariant's queries: its clauses, then the
// conjuncts of the facts, each with the state variables it reads.
using Premises = std::vector<std::pair<z3::expr, std::set<std::size_t>>>;
Premises premises_of(const SafetyProblem& p, const std::vector<z3::expr>& clauses, const StateReads& reads) {
  Premises premises;
  for (const auto& c : clauses) premises.push_back({c, reads.of(c)});
  for (const auto& f : conjuncts_of(p.ts->constraint_formula() && p.assumption)) premises.push_back({f, reads.of(f)});
  return premises;
}

// Every premise (and `also`, the transition) in cycle 0, unrolled on first
// use: the cut premises decide nearly every query, and unrolling tens of
// thousands of clauses for none of them cost a large re-check much of its
// time.
class WholePremise {
 public:
  WholePremise(z3::context& ctx, const Premises& premises, encoder::Unroller& u,
               std::optional<z3::expr> also = std::nullopt)
      : ctx_(ctx), premises_(premises), u_(u), also_(std::move(also)) {}
  const z3::expr& get() {
    if (!whole_) {
      z3::expr_vector all(ctx_);
      for (const auto& [f, vars] : premises_) all.push_back(f);
      if (also_) all.push_back(*also_);
      whole_ = u_.at(z3::mk_and(all), 0);
    }
    return *whole_;
  }

 private:
  z3::context& ctx_;
  const Premises& premises_;
  encoder::Unroller& u_;
  std::optional<z3::expr> also_;
  std::optional<z3::expr> whole_;
};

// The induction step of invariant `clauses` (S and facts and trans implies
// S'), one chunk of consecutive clauses at a time, each first asked under
// a premise cut to what can decide it: the transitions of the variables the
// chunk reads, and the clauses and facts over those and what their
// next-state functions read. A premise cut only weakens what is assumed, so
// unsat there is unsat under the whole premise; anything else asks the
// chunk again under the whole premise. Each query is unsat, or the proof
// fails: the name of the failed chunk, nullopt when none.
std::optional<std::string> step_by_chunks(const SafetyProblem& p, const std::vector<z3::expr>& clauses,
                                          z3::solver& s, const Limits* limits) {
  const auto& ts = *p.ts;
  z3::context& ctx = ts.ctx();
  encoder::Unroller u(ts);
  const StateReads reads(ts);
  std::vector<std::set<std::size_t>> next_reads;
  for (const auto& v : ts.statevars()) next_reads.push_back(reads.of(v.next));
  const auto premises = premises_of(p, clauses, reads);
  WholePremise whole(ctx, premises, u, ts.trans_formula());
  auto unsat = [&](const z3::expr& premise, const z3::expr& goal) { return unsat_under(s, premise, goal, limits); };
  std::vector<char> in(ts.statevars().size());
  for (std::size_t first = 0; first < clauses.size(); first += kChunkClauses) {
    const std::size_t last = std::min(clauses.size(), first + kChunkClauses);
    z3::expr_vector chunk(ctx), local(ctx);
    std::fill(in.begin(), in.end(), 0);
    for (std::size_t i = first; i < last; ++i) {
      chunk.push_back(clauses[i]);
      for (std::size_t v : premises[i].second) {
        if (!in[v]) local.push_back(ts.statevars()[v].next_var == ts.statevars()[v].next);
        in[v] = 2;
      }
    }
    for (std::size_t v = 0; v < in.size(); ++v)
      if (in[v] == 2)
        for (std::size_t w : next_reads[v]) in[w] = in[w] ? in[w] : 1;
    for (const auto& [f, vars] : premises)
      if (std::all_of(vars.begin(), vars.end(), [&](std::size_t v) { return in[v] != 0; })) local.push_back(f);
    const z3::expr goal = u.at(z3::mk_and(chunk), 1);
    if (unsat(u.at(z3::mk_and(local), 0), goal) || unsat(whole.get(), goal)) continue;
    return "invariant-step (clauses " + std::to_string(first + 1) + " to " + std::to_string(last) + ")";
  }
  return std::nullopt;
}

// The step of a proof at k = 0 (S and the facts imply `good` in the same
// cycle) for a large invariant, one conjunct of `good` at a time (an output
// of a group), each first under the clauses and facts over the state
// variables it reads, then, when that is not unsat, under the whole
// premise. The name of the conjunct that fails, nullopt when none.
std::optional<std::string> good_by_conjuncts(const SafetyProblem& p, const std::vector<z3::expr>& clauses,
                                             z3::solver& s, const Limits* limits) {
  const auto& ts = *p.ts;
  encoder::Unroller u(ts);
  const StateReads reads(ts);
  const auto premises = premises_of(p, clauses, reads);
  WholePremise whole(ts.ctx(), premises, u);
  const std::vector<z3::expr> goods = conjuncts_of(p.good);
  for (std::size_t i = 0; i < goods.size(); ++i) {
    const std::set<std::size_t> in = reads.of(goods[i]);
    z3::expr_vector cut(ts.ctx());
    for (const auto& [f, vars] : premises)
      if (std::includes(in.begin(), in.end(), vars.begin(), vars.end())) cut.push_back(f);
    const z3::expr goal = u.at(goods[i], 0);
    if (unsat_under(s, u.at(z3::mk_and(cut), 0), goal, limits) || unsat_under(s, whole.get(), goal, limits)) continue;
    return "step (conjunct " + std::to_string(i + 1) + " of " + std::to_string(goods.size()) + " of the property)";
  }
  return std::nullopt;
}

// Every variable a Boolean or an integer (a product of plc_check's, reduced:
// analog values as ordered integers): the chunks' queries are linear integer
// arithmetic, which Z3's QF_LIA solver answers in about three quarters of
// its default solver's time (the generated 32 x 32 program's chunked
// induction step, 4.3 s against 3.2 s), and in less again with its
// simplex-based arithmetic (linear_integer_solver).
bool linear_integer(const encoder::TransitionSystem& ts) {
  auto simple = [](const auto& vars) {
    return std::all_of(vars.begin(), vars.end(), [](const auto& v) { return v.var.is_bool() || v.var.is_int(); });
  };
  return simple(ts.statevars()) && simple(ts.inputvars());
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
  const bool chunked = result.invariant.clauses.size() >= kChunkedClauses;
  // A large invariant's clauses, read once for the obligations asked in parts.
  const std::vector<z3::expr> clauses =
      chunked ? conjuncts_of(invariant_term(*problem.ts, result.invariant)) : std::vector<z3::expr>{};
  for (const auto& o : obs) {
    if (chunked && (o.name == "invariant-step" || (o.name == "step" && result.k == 0))) {
      z3::solver chunks = linear_integer(*problem.ts) ? linear_integer_solver(problem.ts->ctx()) : s;
      const auto failed = o.name == "step" ? good_by_conjuncts(problem, clauses, chunks, limits)
                                           : step_by_chunks(problem, clauses, chunks, limits);
      if (failed)
        throw InternalError(result.method_text() + " proof (k=" + std::to_string(result.k) + ") fails its re-check: " +
                            *failed + " is not unsat\ninvariant:\n" + result.invariant.text());
      continue;
    }
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
