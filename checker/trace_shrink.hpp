// Counterexample cleanup before it is reported: a solver's model gives every
// input a value, also the ones the violation does not need (odd denormal
// floats, commands issued for nothing), which makes a scenario hard to read
// and defeats the folding of constant stretches into `cycles`. Each input of
// each stretch of equal inputs is set to zero (FALSE, 0, 0.0) where the run
// still violates the property on the encoder's Evaluator, in a fixed order,
// so the result is deterministic.
#pragma once

#include <cstddef>

#include "checker/prover.hpp"

namespace cemv::checker {

// Returns the cleaned trace (possibly shorter: a violation may come earlier).
// Traces whose re-simulation budget (cycles x stretches x inputs) exceeds
// `max_steps` are returned unchanged: an accelerated 18,000-cycle trace would
// take seconds, and its few long stretches fold well as they are.
Trace shrink_counterexample(const SafetyProblem& problem, const Trace& cex, std::size_t max_steps = 1000000);

}  // namespace cemv::checker
