#include <optional>

#include "checker/engines/invariants.hpp"
#include "checker/engines/multi.hpp"
#include "checker/engines/solving.hpp"
#include "encoder/unroller.hpp"

namespace cemv::checker {

namespace {

// One incremental solver holding what every member shares; a member's
// question is its own term under a fresh literal.
class SharedSolver {
 public:
  SharedSolver(z3::context& ctx, SolverSetup setup, WorkMeter& meter, const char* tag)
      : s_(make_solver(ctx, setup)), meter_(meter), tag_(tag) {}
  void add(const z3::expr& e) { s_.add(e); }
  // Unsat: the member's question has no model (its proof obligation holds).
  z3::check_result ask(const z3::expr& question, std::size_t member) {
    z3::expr lit = s_.ctx().bool_const((std::string(tag_) + "." + std::to_string(member)).c_str());
    s_.add(z3::implies(lit, question));
    z3::expr_vector a(s_.ctx());
    a.push_back(lit);
    return check_within(s_, meter_, a);
  }

 private:
  z3::solver s_;
  WorkMeter& meter_;
  const char* tag_;
};

ProverResult proved(int k, const std::vector<std::string>& invariant) {
  ProverResult r;
  r.verdict = Verdict::Proved;
  r.method = Method::KInduction;
  r.k = k;
  r.invariant.clauses = invariant;
  return r;
}

}  // namespace

std::vector<ProverResult> prove_each(const MultiProblem& p, const std::vector<bool>& open,
                                     const std::vector<bool>& strengthen, const Limits& limits) {
  const auto& ts = *p.ts;
  z3::context& ctx = ts.ctx();
  std::vector<ProverResult> out(p.goods.size());
  for (auto& r : out) r.reason = UnknownReason::BoundReached;
  std::vector<bool> left = open;
  auto any_left = [&] {
    for (bool b : left)
      if (b) return true;
    return false;
  };
  if (!any_left()) return out;
  WorkMeter meter(ctx, limits);
  try {
    Watchdog watchdog(ctx, limits);
    encoder::Unroller u(ts);
    const z3::expr facts = ts.constraint_formula() && p.assumption;
    // k = 0, no strengthening: `good` follows from the cycle's own definitions.
    SharedSolver plain(ctx, limits.solvers, meter, "multi.plain");
    plain.add(u.at(facts, 0));
    for (std::size_t i = 0; i < p.goods.size(); ++i)
      if (left[i] && plain.ask(!u.at(p.goods[i], 0), i) == z3::unsat) {
        out[i] = proved(0, {});
        left[i] = false;
      }
    for (std::size_t i = 0; i < left.size(); ++i) left[i] = left[i] && strengthen[i];
    if (!any_left() || limits.interrupted()) return out;
    // The encoder's lemmas that are inductive under the assumption.
    std::vector<z3::expr> lemmas;
    for (const auto& l : ts.lemmas()) lemmas.push_back(l.term);
    const std::vector<z3::expr> kept = lemmas.empty() ? lemmas : houdini(p.member(0), lemmas, limits, meter);
    std::vector<std::string> invariant;
    z3::expr_vector s_parts(ctx);
    for (const auto& c : kept) {
      invariant.push_back(to_smtlib(c));
      s_parts.push_back(c);
    }
    const z3::expr S = s_parts.empty() ? ctx.bool_val(true) : z3::mk_and(s_parts);
    // k = 0 strengthened.
    SharedSolver step0(ctx, limits.solvers, meter, "multi.step0");
    step0.add(u.at(S && facts, 0));
    for (std::size_t i = 0; i < p.goods.size(); ++i)
      if (left[i] && step0.ask(!u.at(p.goods[i], 0), i) == z3::unsat) {
        out[i] = proved(0, invariant);
        left[i] = false;
      }
    if (!any_left() || limits.interrupted()) return out;
    // k = 1: no violation in the first cycle, and one good cycle under S is
    // followed by another.
    SharedSolver base(ctx, limits.solvers, meter, "multi.base");
    base.add(u.at(ts.init_formula(), 0));
    base.add(u.at(facts, 0));
    SharedSolver step1(ctx, limits.solvers, meter, "multi.step1");
    step1.add(u.at(S && facts && ts.trans_formula(), 0));
    step1.add(u.at(S && facts, 1));
    for (std::size_t i = 0; i < p.goods.size(); ++i) {
      if (!left[i]) continue;
      if (base.ask(!u.at(p.goods[i], 0), i) != z3::unsat) continue;
      if (step1.ask(u.at(p.goods[i], 0) && !u.at(p.goods[i], 1), i) != z3::unsat) continue;
      out[i] = proved(1, invariant);
      left[i] = false;
    }
  } catch (const Stopped&) {
  } catch (const z3::exception&) {
    // A limit or a solver failure: what is proved so far stands, each proof
    // to be re-checked; the rest go to their own portfolios.
  }
  for (std::size_t i = 0; i < out.size(); ++i)
    if (open[i] && out[i].verdict == Verdict::Unknown)
      out[i].reason = limits.interrupted() ? UnknownReason::TimeLimit
                      : meter.exhausted()  ? UnknownReason::WorkLimit
                                           : UnknownReason::BoundReached;
  return out;
}

}  // namespace cemv::checker
