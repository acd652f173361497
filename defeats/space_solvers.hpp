// The solvers of one path's ActionSpace and the meter of a test's work
// (docs/defeats.md, "One encoding per path"). Internal to defeats/: shared
// by space.cpp (the encoding, the candidates, the runs) and space_test.cpp
// (a set's test).
#pragma once

#include <algorithm>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include <z3++.h>

#include "checker/engines/solving.hpp"
#include "checker/limits.hpp"
#include "defeats/space.hpp"
#include "defeats/space_problem.hpp"
#include "encoder/unroller.hpp"

namespace cemv::defeats {

// The induction depth and the BMC depth past the requirement's T of a test:
// a defeat's counterexample is a demand held T + 1 cycles after the few
// cycles that take the actions (a timed soft bypass, an override).
constexpr int kMaxInductionK = 24;
constexpr int kBmcMargin = 12;
constexpr int kMaxBmcDepth = 200;

inline bool in(const std::vector<int>& s, int i) { return std::binary_search(s.begin(), s.end(), i); }

// The work a test spends against its budget, as checker::WorkMeter counts it
// (Z3's `rlimit count`, the context's resource limit armed to what is left
// before each check), read through one solver of the `skip` tactic that
// lives as long as the path: checker::resource_count makes a default solver
// for each reading, a third of this enumeration's time when every set is a
// few short checks.
class Meter {
 public:
  Meter(z3::context& ctx, z3::solver& probe, checker::Work budget)
      : ctx_(ctx), probe_(probe), budget_(budget), start_(count()) {}
  ~Meter() { Z3_update_param_value(ctx_, "rlimit", "0"); }
  Meter(const Meter&) = delete;
  Meter& operator=(const Meter&) = delete;
  bool arm() {
    if (budget_ == 0) {
      Z3_update_param_value(ctx_, "rlimit", "0");
      return true;
    }
    const checker::Work used = spent();
    if (used >= budget_) return false;
    checker::Work left = budget_ - used;
    if (left > 4000000000ULL) left = 4000000000ULL;  // Z3's limit is an unsigned int
    Z3_update_param_value(ctx_, "rlimit", std::to_string(left).c_str());
    return true;
  }
  checker::Work spent() const { return count() - start_; }
  bool exhausted() const { return budget_ != 0 && spent() >= budget_; }

 private:
  checker::Work count() const {
    const z3::stats st = probe_.statistics();
    for (unsigned i = 0; i < st.size(); ++i)
      if (st.key(i) == "rlimit count")
        return st.is_uint(i) ? st.uint_value(i) : static_cast<checker::Work>(st.double_value(i));
    return 0;
  }
  z3::context& ctx_;
  z3::solver& probe_;
  checker::Work budget_;
  checker::Work start_;
};

inline z3::check_result check_within(z3::solver& s, Meter& meter, const z3::expr_vector& assumptions) {
  if (!meter.arm()) return z3::unknown;
  return s.check(assumptions);
}

inline checker::UnknownReason unknown_reason(const std::string& z3_reason, const checker::Limits& limits,
                                      const Meter& meter) {
  if (limits.interrupted()) return checker::UnknownReason::TimeLimit;
  if (meter.exhausted()) return checker::UnknownReason::WorkLimit;
  return checker::unknown_reason(z3_reason, limits);
}

struct ActionSpace::Solvers {
  explicit Solvers(const model::Matrix& m, const PathDefeats& pd)
      : builder(m, pd), built(builder.build(ctx)), frame(ctx), trans(ctx), base(ctx), step(ctx), houdini(ctx),
        probe(z3::tactic(ctx, "skip").mk_solver()),
        any_violation(ctx) {}

  Builder builder;
  z3::context ctx;
  Built built;
  std::unique_ptr<encoder::Unroller> u;
  std::vector<z3::expr> exclude;  // exclude[i]: the literal assuming action i never occurs
  std::unordered_map<unsigned, int> action_of;  // literal id -> action
  std::unordered_map<unsigned, std::size_t> cand_of;  // literal id -> candidate
  z3::expr frame, trans;          // one cycle: constraints, assumption, guarded exclusions; the transition
  z3::solver base, step, houdini;
  z3::solver probe;  // reads the work spent (Meter)
  z3::expr any_violation;         // base: a violation in some cycle up to bmc_depth
  int bmc_depth = 0;
  bool any_made = false;
  std::vector<z3::expr> so_far, base_bad, step_on, step_good, step_bad;
  std::vector<z3::expr> cands, lits;  // initiated invariant candidates and their literals
  std::vector<z3::expr> cands_next;   // each candidate in cycle 1 of Houdini's unrolling (made once:
                                      // an unrolling substitutes every variable)
  std::vector<std::size_t> start;     // Houdini's start: what the empty set keeps (its largest fixpoint)
  bool start_known = false;
  int rounds = 0;

  const encoder::TransitionSystem& ts() const { return *built.problem.problem.ts; }
  const z3::expr& good() const { return built.problem.problem.good; }

  // The base case unrolls from the initial state. A violation in cycle t
  // counts when the assumptions held in cycles 0..t (`so_far[t]`), never
  // asking anything of later cycles: the assumption of a later cycle can be
  // unsatisfiable in some states (an override that has become active).
  void base_frames(int k);
  // The inductive step's cycles, each behind a literal of its own: a step of
  // k assumes the cycles 0..k and nothing of those after.
  void step_frames(int k);
};

}  // namespace cemv::defeats
