// What every engine needs around a Z3 solver: the wall-clock limit enforced
// both by Z3's own `timeout` and by a watchdog that interrupts the context (a
// `timeout` alone does not stop every tactic), values and traces read from a
// model, and invariants moved between contexts as SMT-LIB text.
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

// Interrupts `ctx` once the deadline passes or the cancel flag is set, and
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

// The remaining time as the solver's `timeout` parameter (ms, at least 1).
void set_timeout(z3::solver& s, const Limits& limits);
// Why a check returned unknown: "time limit" once the deadline (or a cancel)
// has passed, "memory limit" for Z3's memory-out, else Z3's own reason.
std::string unknown_reason(const std::string& z3_reason, const Limits& limits);

// The concrete value of `e` (Bool, Int or Float32 term) in `m`.
Value value_in(const z3::model& m, const z3::expr& e);
// A counterexample of cycles 0..last read from a model of an unrolling.
Trace trace_from_model(const encoder::TransitionSystem& ts, encoder::Unroller& u,
                       const z3::model& m, int last);

// A term over the state variables as SMT-LIB text, and back in any context
// holding a system with the same variable names.
std::string to_smtlib(const z3::expr& e);
z3::expr from_smtlib(const encoder::TransitionSystem& ts, const std::string& term);
z3::expr invariant_term(const encoder::TransitionSystem& ts, const Invariant& inv);

// Seconds since `start`.
double seconds_since(std::chrono::steady_clock::time_point start);

}  // namespace cemv::checker
