// Counterexamples people can read. An engine's trace is whatever model the
// solver found: analog inputs at 4.9e-32, tags in bad quality and operator
// commands that play no part in the violation. shrink_trace looks for a trace
// of the same length, violating in the same last cycle, in which as many
// inputs as possible keep a preferred value (the plant at rest: scenario
// defaults, good quality, no command). First concretely, on the encoding's
// own evaluator: each input put back at rest over every cycle, then over
// halves of the cycles, down to single cycles, wherever the violation still
// happens (microseconds a try). Then the solver, with one assumption literal
// per (cycle, input), takes back what it can of the rest: other values of
// what the violation needs may let more inputs rest. What remains differs
// from the plant at rest only where the violation needs it.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "checker/prover.hpp"
#include "encoder/encode.hpp"
#include "model/matrix.hpp"

namespace cemv::checker {

// The value an input should keep when nothing requires otherwise; nullopt
// leaves the input free.
using PreferredValue = std::function<std::optional<Value>(const std::string& input_name)>;

// The plant at rest (scenario defaults, good quality, no command) for the
// inputs of one or more encodings (the two copies of a product): the first
// encoding that names an input gives its value.
PreferredValue plant_at_rest(const std::vector<std::pair<const encoder::Encoding*, const model::Matrix*>>& parts);

// A trace of cex.length() cycles violating `good` in its last cycle, as close
// to the preferred values as the two passes get, the solver's within
// `limits.work`; `cex` itself when the trace is longer than `max_cycles` (a
// long accelerated trace is already mostly held inputs). Deterministic;
// throws Interrupted when the limits' wall clock or cancel token end it.
Trace shrink_trace(const SafetyProblem& problem, const Trace& cex, const PreferredValue& preferred,
                   const Limits& limits, std::size_t max_cycles = 400);

// The first pass alone, without the solver: each input put back at its
// preferred value over every cycle, then over halves of the cycles down to
// single cycles, wherever the violation still happens on the encoding's own
// evaluator. Microseconds a try; for a trace a seeded run found, which
// already changes few inputs, it is most of what the solver's pass would
// give. `cex` itself when the evaluator cannot run the problem.
Trace rest_inputs_concretely(const SafetyProblem& problem, const Trace& cex, const PreferredValue& preferred,
                             const Limits& limits);

}  // namespace cemv::checker
