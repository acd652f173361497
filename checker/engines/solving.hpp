// What every engine needs around a Z3 solver: checks within the engine's
// budget of work (checker/limits.hpp), a watchdog that interrupts the context
// when the user's wall clock or the run's cancel token says so, values and
// traces read from a model, and invariants moved between contexts as SMT-LIB
// text.
#pragma once

#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <z3++.h>

#include "checker/prover.hpp"
#include "encoder/unroller.hpp"

namespace cemv::checker {

// Interrupts `ctx` once the deadline passes or the cancel token is set, and
// again every few milliseconds until destroyed, so a solver call that starts
// late is stopped too. Destroy it before the Z3 objects the engine made (a
// fixedpoint in particular): it clears the cancellation on the way out.
class Watchdog {
 public:
  Watchdog(z3::context& ctx, const Limits& limits);
  ~Watchdog();
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

 private:
  void watch();
  z3::context& ctx_;
  Limits limits_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  bool fired_ = false;
  std::thread thread_;
};

// One solver check within the meter's budget; unknown, without a call, when
// nothing is left.
z3::check_result check_within(z3::solver& s, WorkMeter& meter);
z3::check_result check_within(z3::solver& s, WorkMeter& meter, const z3::expr_vector& assumptions);

// Why a check returned unknown: TimeLimit once the question is interrupted
// (wall clock, cancel), WorkLimit once the meter's budget is spent,
// MemoryLimit for Z3's memory-out, else SolverGaveUp with Z3's words in
// `detail`.
UnknownReason unknown_reason(const std::string& z3_reason, const Limits& limits, const WorkMeter& meter,
                             std::string* detail = nullptr);
// The same where no meter ran (an exception outside a check).
UnknownReason unknown_reason(const std::string& z3_reason, const Limits& limits, std::string* detail = nullptr);

// Thrown by an engine's inner loop (Houdini, mining) when its limits end the
// question; the engine turns it into its Unknown.
struct Stopped {
  UnknownReason reason;
};

// The concrete value of `e` (Bool, Int or Float32 term) in `m`.
Value value_in(const z3::model& m, const z3::expr& e);
// A counterexample of cycles 0..last read from a model of an unrolling.
Trace trace_from_model(const encoder::TransitionSystem& ts, encoder::Unroller& u,
                       const z3::model& m, int last);

// A term over the state variables as SMT-LIB text, and back in any context
// holding a system with the same variable names.
std::string to_smtlib(const z3::expr& e);
z3::expr from_smtlib(const encoder::TransitionSystem& ts, const std::string& term);
// The terms that read, in their order, read in one parse where all of them
// do (a parse declares every variable of the system); the ones that do not
// read are left out.
std::vector<z3::expr> from_smtlib_readable(const encoder::TransitionSystem& ts, const std::vector<std::string>& terms);
z3::expr invariant_term(const encoder::TransitionSystem& ts, const Invariant& inv);

// Seconds since `start`.
double seconds_since(std::chrono::steady_clock::time_point start);

}  // namespace cemv::checker
