// Safety problems the checker tests and benchmarks share: small hand-made
// transition systems with known answers, and encodings of the example
// matrices with good terms built on their named terms. Each is a factory, so
// a portfolio can build its own copy in each thread's context.
#pragma once

#include <string>
#include <vector>

#include "checker/prover.hpp"
#include "encoder/encode.hpp"

namespace cemv::checker::fixtures {

struct NamedProblem {
  std::string name;
  ProblemFactory make;
  Verdict expected;
  int cex_length = 0;  // cycles of the shortest counterexample, for Falsified
  bool exact_length = true;  // false: cex_length is a lower bound
  // Needs an 18,000-cycle timer: beyond PDR and plain BMC (cemv_checker_measure),
  // decided by relational invariants and the accelerated unrolling.
  bool deep = false;
};

// A saturating counter x (0, 1, ..., limit, limit, ...) counting the cycles in
// which input `go` holds, reset when it does not; good: x <= bound.
NamedProblem saturating_counter(int limit, int bound);
// Two counters of the same input; good: x == y (needs no strengthening past
// 1-induction on x - y = 0... which is the property itself).
NamedProblem twin_counters();
// A flag and a counter that only counts while the flag is set: good x <= 3
// holds only because !flag -> x = 0 and flag is cleared when x reaches 3.
NamedProblem guarded_counter(int bound);

// s: 0 -> 1 -> 1 -> ...; the unreachable state 3 loops on itself and may
// step to the bad state 4. good: s != 4. Not k-inductive for any k (3, 3, ...,
// 3, 4), but 2-inductive on simple paths (only 3 leads to 3).
NamedProblem lasso();

// x counts the rising edges of input `go`; good: x <= 5000. False, but only
// after 10,000 cycles of toggling input: too deep for BMC, not a held-input
// stretch for the accelerated unrolling, and a 5,000-step counter for PDR.
// Nothing decides it in seconds: what a deadline test needs.
NamedProblem edge_counter();

// The example matrix `examples/NAME/matrix.json` encoded with the given roots.
std::unique_ptr<encoder::Encoding> encode_example(z3::context& ctx, const std::string& example,
                                                  const std::vector<model::Node>& roots);
// good = the named term `key` (or its negation) of an example's encoding.
NamedProblem example_term(const std::string& example, const std::vector<model::Node>& roots,
                          const std::string& key, bool negate, Verdict expected, int cex_length = 0);
// pipeline-hipps, roots effect 4, with a monitor m counting the consecutive
// cycles of effect[4].override_active (init 0, next = ite(override_active,
// m + 1, 0)); good: m <= bound.
// Because E.3 lets a toggle start a new override in the cycle the old one
// times out, override_active can hold for longer than 18,000 cycles in a row:
// with bound 18,000 this is falsified.
NamedProblem override_monitor(int bound, Verdict expected, int cex_length = 0);
// The same monitor restarted by the toggle (the HS_310_OVR reset-tag edge,
// T.4): it counts the cycles of one override. good: m <= bound; proved for
// 18,000 (the configured 1800 s at 100 ms), falsified for 17,999.
NamedProblem override_instance_monitor(int bound, Verdict expected, int cex_length = 0);

}  // namespace cemv::checker::fixtures
