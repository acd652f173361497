// What bounds a question to an engine: work, never seconds, so that an
// answer does not depend on the machine or its load (docs/checker.md,
// "Budgets"). Work is counted in Z3's own deterministic effort measure (its
// resource limit, `rlimit`), depth in cycles or k. The wall clock bounds only
// what the user asked it to bound (--timeout, --total-timeout): when it runs
// out, the open question is abandoned and reported unknown ("time limit"),
// never answered differently.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <optional>

#include <z3++.h>

namespace cemv::checker {

using Clock = std::chrono::steady_clock;

// Z3 resource units. One million is about 0.5 to 1 s of solver time on the
// reference machine (docs/performance.md); the figure varies with the problem,
// the count does not.
using Work = std::uint64_t;
constexpr Work kMega = 1000000;

// The one cancel token of a run (one work queue, checker/work_queue.hpp): set
// when a worker fails, when the run's wall-clock bound (--total-timeout) is
// reached, or by the caller. Every engine polls it through Limits.
class CancelToken {
 public:
  CancelToken() = default;
  explicit CancelToken(Clock::time_point deadline) : deadline_(deadline) {}
  CancelToken(const CancelToken&) = delete;
  CancelToken& operator=(const CancelToken&) = delete;

  void cancel() { cancelled_ = true; }
  // Cancelled, or the run's deadline has passed.
  bool cancelled() const { return cancelled_.load() || (deadline_ != Clock::time_point::max() && Clock::now() >= deadline_); }
  Clock::time_point deadline() const { return deadline_; }

 private:
  std::atomic<bool> cancelled_{false};
  Clock::time_point deadline_ = Clock::time_point::max();
};

// How an engine makes its Z3 solvers and reads the work it spends
// (docs/performance.md, "Solver set-up"). Both give answers that are checked
// alike; they differ in what a budget of work buys, and in which of several
// valid models and unsat cores Z3 returns, so a caller whose output is
// committed byte for byte keeps the set-up it was made with.
enum class SolverSetup {
  // Z3's default solver, which pairs its SMT kernel with the tactic of a
  // one-shot check (built at a solver's first check, about 10 ms in Z3
  // 4.8.12); the work read through a fresh default solver at every reading,
  // which sets one up and spends work itself (about 100 units, 7 ms). What
  // the committed test suites (examples/*/acceptance) were generated with.
  DefaultSolver,
  // Z3's SMT kernel alone (what the default solver answers incremental checks
  // with), and the work read through one solver of the `skip` tactic per
  // meter, which spends none. What `check` uses (CheckOptions::solvers).
  SmtKernel,
};

struct Limits {
  // Work this call may spend (0: no bound of its own; an engine then stops
  // at its depth bound only).
  Work work = 0;
  int max_depth = 1000;  // cycles (BMC), k (k-induction), macro steps (accelerated BMC)
  // The user's wall-clock bound of this question (--timeout).
  Clock::time_point deadline = Clock::time_point::max();
  const CancelToken* cancel = nullptr;
  // How the engines make solvers and read work (the caller's choice; test
  // generation keeps DefaultSolver, check passes SmtKernel).
  SolverSetup solvers = SolverSetup::DefaultSolver;

  // The question was interrupted: the wall clock or the cancel token. Its
  // answer, whatever an engine had, is abandoned.
  bool interrupted() const {
    return (cancel && cancel->cancelled()) || (deadline != Clock::time_point::max() && Clock::now() >= deadline);
  }
  // The same limits with another work budget or depth.
  Limits with_work(Work w) const {
    Limits l = *this;
    l.work = w;
    return l;
  }
  Limits with_depth(int d) const {
    Limits l = *this;
    l.max_depth = d;
    return l;
  }
};

// The longest counterexample or witness that cemv holds cycle by cycle: its
// inputs and states here, the runtime's observables when it is replayed, its
// rows when it is shrunk and drawn. A longer one found by macro steps (a
// property over millions of held cycles) is confirmed cycle by cycle without
// being held, and the question stays Unknown ("memory limit"), so that no
// property the language accepts takes more than about 1 GB.
inline constexpr std::int64_t kMaxTraceCycles = 150000;
// A trace longer than this carries its inputs only: the states of every cycle
// serve display and the re-check that an engine's states are the formulas';
// the replay of the inputs (on the formulas, then on the runtime) remains.
inline constexpr std::int64_t kMaxTraceStateCycles = 10000;

// Thrown where an interrupted question cannot end with an answer of its own
// (a re-check, a replay, a search over many engines): the question is then
// Unknown ("time limit").
struct Interrupted {};

// Throws Interrupted when `limits` say the question is interrupted.
inline void stop_if_interrupted(const Limits& limits) {
  if (limits.interrupted()) throw Interrupted{};
}

// The work an engine has spent against its budget. Every solver check and
// fixedpoint query of the engine is armed first: the context's resource limit
// is set to what is left, so that Z3 stops exactly there on every machine.
class WorkMeter {
 public:
  WorkMeter(z3::context& ctx, Work budget, SolverSetup setup = SolverSetup::DefaultSolver);
  // Limits::work within Limits::solvers.
  WorkMeter(z3::context& ctx, const Limits& limits) : WorkMeter(ctx, limits.work, limits.solvers) {}
  // Leaves the context without a resource limit, for whoever checks next.
  ~WorkMeter();
  WorkMeter(const WorkMeter&) = delete;
  WorkMeter& operator=(const WorkMeter&) = delete;
  // Sets the context's resource limit to the work left (or none). False when
  // nothing is left: the caller stops with UnknownReason::WorkLimit.
  bool arm();
  Work spent() const;
  bool exhausted() const { return budget_ != 0 && spent() >= budget_; }
  Work budget() const { return budget_; }

 private:
  Work read() const;
  z3::context& ctx_;
  // SmtKernel: the solver of the `skip` tactic that reads the count (its
  // statistics report the context's count without setting anything up).
  mutable std::optional<z3::solver> probe_;
  Work budget_;
  Work start_;
};

// Z3's count of resource units spent in `ctx` so far, read through a fresh
// default solver (SolverSetup::DefaultSolver: that reading spends work).
Work resource_count(z3::context& ctx);
// The same, read through `probe` (a solver of the `skip` tactic: no work).
Work resource_count(z3::solver& probe);
// A solver for incremental checks (under assumptions, or after a push) in
// `setup`: the default solver, or Z3's SMT kernel alone.
z3::solver make_solver(z3::context& ctx, SolverSetup setup);
// Z3's solver for QF_LIA with its simplex-based arithmetic (smt.arith.solver
// 2) instead of its default one: on the queries of a problem of Booleans and
// integers (a plc-check product reduced: analog values and counters as
// integers, mostly bounds and equalities) it gives the same answers in a
// fraction of the time (the generated 128 x 128 x 1024 program's Houdini by
// layers, 33.8 s against 119.6 s of CPU, the same 39,443 clauses kept; its
// re-check's chunks, 24.5 s against 35.9 s).
z3::solver linear_integer_solver(z3::context& ctx);

}  // namespace cemv::checker
