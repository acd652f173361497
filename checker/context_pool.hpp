// The Z3 context of one problem. Every borrower gets a fresh context, and
// the context is destroyed when the problem is done.
//
// Contexts used to be handed on between problems: creating and destroying one
// costs milliseconds (every theory plugin is set up and torn down), a third of
// a standard property set's time. But a Z3 model depends on the context's
// history (term ids are recycled, so the same problem is numbered differently
// in a context that has held another), and which context a portfolio lane
// was handed depended on thread timing. The same check then reported
// different counterexamples and witnesses on two runs (pipeline-hipps'
// req3 cover: a simulated PT_301B in one run, a soft-bypassed tag in the
// next; `cemv response` scenarios alike). Output must be byte-identical for
// the same inputs, so the reuse is gone: tests/checker/test_pools.cpp
// `ContextPool.SameCheckTwiceInOneProcessGivesTheSameTraces` keeps it so.
#pragma once

#include <memory>

#include <z3++.h>

namespace cemv::checker {

// Called by the Watchdog (checker/engines/solving.hpp) when it interrupts a
// context. With fresh contexts nothing is handed on, so there is nothing to
// withhold; kept so that the watchdog states what it did.
void discard_when_released(const z3::context& ctx);

class PooledContext {
 public:
  PooledContext();
  ~PooledContext();
  PooledContext(const PooledContext&) = delete;
  PooledContext& operator=(const PooledContext&) = delete;

  z3::context& operator*() { return *ctx_; }
  operator z3::context&() { return *ctx_; }

 private:
  std::unique_ptr<z3::context> ctx_;
};

}  // namespace cemv::checker
