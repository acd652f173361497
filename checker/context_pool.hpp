// Z3 contexts, reused. Creating and destroying a z3::context costs
// milliseconds (every theory plugin is set up and torn down), which was a third
// of the time of a standard property set, whose properties each build several
// small problems. A PooledContext borrows a context that an earlier problem
// has finished with (its terms, solvers and models all released, so it holds
// nothing of that problem) or makes one.
// A re-check (checker/check/) borrows one too: the problem is built again
// and checked by a new solver, so nothing of the engine's reaches it.
#pragma once

#include <memory>

#include <z3++.h>

namespace cemv::checker {

// A context that Z3_interrupt has reached is not handed on: Z3 4.8.12 keeps
// it cancelled until a later check, and a borrower must not meet that.
// Called by the Watchdog (checker/engines/solving.hpp) when it interrupts.
void discard_when_released(const z3::context& ctx);

class PooledContext {
 public:
  PooledContext();
  // Back to the pool, unless an exception is unwinding through the owner: a
  // context left in the middle of an operation is not handed on.
  ~PooledContext();
  PooledContext(const PooledContext&) = delete;
  PooledContext& operator=(const PooledContext&) = delete;

  z3::context& operator*() { return *ctx_; }
  operator z3::context&() { return *ctx_; }

 private:
  std::unique_ptr<z3::context> ctx_;
  int exceptions_;
};

}  // namespace cemv::checker
