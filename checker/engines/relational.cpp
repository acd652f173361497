#include "checker/engines/relational.hpp"

#include <chrono>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "checker/engines/solving.hpp"
#include "encoder/term_memo.hpp"
#include "encoder/unroller.hpp"

namespace cemv::checker {

namespace {

// Float32 operations as uninterpreted functions (header comment). One
// function per (operator, signature), so that fp.leq(x, c) in copy a and
// fp.leq(y, c) in copy b are the same function applied to x and y.
class UfAbstraction {
 public:
  explicit UfAbstraction(z3::context& ctx) : ctx_(ctx) {}

  z3::expr operator()(const z3::expr& e) {
    if (const z3::expr* known = memo_.find(e)) return *known;
    z3::expr out = e;
    if (e.is_app() && e.num_args() > 0) {
      z3::expr_vector args(ctx_);
      bool changed = false, float_arg = false;
      for (unsigned i = 0; i < e.num_args(); ++i) {
        args.push_back((*this)(e.arg(i)));
        changed = changed || !z3::eq(args.back(), e.arg(i));
        float_arg = float_arg || e.arg(i).is_fpa() || e.arg(i).get_sort().sort_kind() == Z3_ROUNDING_MODE_SORT;
      }
      const Z3_decl_kind k = e.decl().decl_kind();
      const bool keep = k == Z3_OP_EQ || k == Z3_OP_ITE || k == Z3_OP_DISTINCT;
      if ((float_arg || e.is_fpa()) && !keep) {
        out = function_of(e, args)(args);
      } else if (changed) {
        out = e.decl()(args);
      }
    }
    return memo_.emplace(e, out);
  }

 private:
  z3::func_decl function_of(const z3::expr& e, const z3::expr_vector& args) {
    z3::func_decl d = e.decl();
    std::string key = d.name().str() + "/" + std::to_string(d.decl_kind()) + "/" + e.get_sort().to_string();
    z3::sort_vector domain(ctx_);
    for (unsigned i = 0; i < args.size(); ++i) {
      domain.push_back(args[static_cast<int>(i)].get_sort());
      key += "/" + args[static_cast<int>(i)].get_sort().to_string();
    }
    auto it = functions_.find(key);
    if (it != functions_.end()) return it->second;
    z3::func_decl f = ctx_.function(("rel.uf." + std::to_string(functions_.size())).c_str(), domain, e.get_sort());
    functions_.emplace(key, f);
    return f;
  }

  z3::context& ctx_;
  encoder::TermMemo<z3::expr> memo_;
  std::unordered_map<std::string, z3::func_decl> functions_;
};

class RelationalInduction : public Prover {
 public:
  Method method() const override { return Method::RelationalInduction; }

  ProverResult prove(const SafetyProblem& problem, const Limits& limits) override {
    const auto start = Clock::now();
    ProverResult r;
    r.method = method();
    const auto& ts = *problem.ts;
    z3::context& ctx = ts.ctx();
    WorkMeter meter(ctx, limits);
    try {
      Watchdog watchdog(ctx, limits);
      encoder::Unroller u(ts);
      UfAbstraction abstract(ctx);
      std::vector<z3::expr> cands;
      for (const auto& l : ts.lemmas()) cands.push_back(l.term);
      // Initiation.
      {
        z3::solver s(ctx);
        s.add(abstract(u.at(ts.init_formula(), 0)));
        keep_valid(s, cands, u, abstract, 0, limits, meter);
      }
      // Consecution: drop what a transition from the candidates breaks.
      const z3::expr facts = abstract(u.at(ts.constraint_formula() && problem.assumption, 0));
      z3::solver s(ctx);
      s.add(facts);
      s.add(abstract(u.at(ts.trans_formula(), 0)));
      for (;;) {
        if (limits.interrupted()) return unknown(r, UnknownReason::TimeLimit, start);
        std::vector<z3::expr> before = cands;
        z3::expr_vector now(ctx);
        for (const auto& c : cands) now.push_back(abstract(u.at(c, 0)));
        s.push();
        if (!now.empty()) s.add(z3::mk_and(now));
        keep_valid(s, cands, u, abstract, 1, limits, meter);
        s.pop();
        if (cands.size() == before.size()) break;
      }
      // `good` from the invariant, in the same cycle.
      z3::solver g(ctx);
      g.add(facts);
      for (const auto& c : cands) g.add(abstract(u.at(c, 0)));
      g.add(!abstract(u.at(problem.good, 0)));
      z3::check_result cr = check_within(g, meter);
      if (cr == z3::unknown) return unknown(r, unknown_reason(g.reason_unknown(), limits, meter, &r.detail), start);
      if (cr == z3::sat) return unknown(r, UnknownReason::BoundReached, start);
      r.verdict = Verdict::Proved;
      r.k = 0;
      for (const auto& c : cands) r.invariant.clauses.push_back(to_smtlib(c));
    } catch (const Stopped& e) {
      return unknown(r, e.reason, start);
    } catch (const z3::exception& e) {
      return unknown(r, unknown_reason(e.msg(), limits, meter, &r.detail), start);
    }
    r.work = meter.spent();
    r.seconds = seconds_since(start);
    return r;
  }

 private:
  static ProverResult unknown(ProverResult& r, UnknownReason why, Clock::time_point start) {
    r.verdict = Verdict::Unknown;
    r.reason = why;
    r.invariant = {};
    r.seconds = seconds_since(start);
    return r;
  }

  // Drops every candidate (at cycle k) that a model of `s` violates, until
  // the rest hold in every model.
  static void keep_valid(z3::solver& s, std::vector<z3::expr>& cands, encoder::Unroller& u, UfAbstraction& abstract,
                         int k, const Limits& limits, WorkMeter& meter) {
    z3::context& ctx = s.ctx();
    for (;;) {
      if (cands.empty()) return;
      if (limits.interrupted()) throw Stopped{UnknownReason::TimeLimit};
      std::vector<z3::expr> at;
      z3::expr_vector some_false(ctx);
      for (const auto& c : cands) {
        at.push_back(abstract(u.at(c, k)));
        some_false.push_back(!at.back());
      }
      s.push();
      s.add(z3::mk_or(some_false));
      z3::check_result r = check_within(s, meter);
      if (r == z3::unsat) {
        s.pop();
        return;
      }
      if (r == z3::unknown) {
        UnknownReason why = unknown_reason(s.reason_unknown(), limits, meter);
        s.pop();
        throw Stopped{why};
      }
      z3::model m = s.get_model();
      std::vector<z3::expr> keep;
      for (std::size_t i = 0; i < cands.size(); ++i)
        if (m.eval(at[i], true).is_true()) keep.push_back(cands[i]);
      s.pop();
      cands = std::move(keep);
    }
  }
};

}  // namespace

std::unique_ptr<Prover> make_relational_prover() { return std::make_unique<RelationalInduction>(); }

}  // namespace cemv::checker
