// The independent check of every counterexample and witness (docs/checker.md,
// "Checking the answers"): the engine's trace, which lives in the encoder's
// variables, becomes plain cycle inputs; the reference runtime executes them;
// the concrete property evaluator judges the runtime's own observables. Only
// a run that the runtime reproduces is ever reported.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "checker/prover.hpp"
#include "checker/result.hpp"
#include "encoder/encode.hpp"
#include "model/matrix.hpp"

namespace cemv::checker {

// The cycle inputs of an engine's trace: each encoded tag's value and quality
// (tags outside the encoding keep the scenario defaults, which nothing encoded
// reads), and the commands issued, in the matrix's fixed command order
// (model::CommandOrder).
std::vector<model::CycleInput> cycle_inputs(const Trace& trace, const encoder::Encoding& enc,
                                            const model::Matrix& m);

// The inverse of cycle_inputs: runtime cycle inputs as a trace of the
// encoding's transition system `ts` (the encoding's system, possibly with a
// monitor compiled into it). Every input of `ts` must be an encoded tag's
// value or quality or a command; nullopt when one is not, or when a cycle
// issues a command that is none of the encoding's command inputs. With
// `dropped`, such commands are left out instead and counted there (a
// slice's encoding has no input for a command on an element outside its
// cone, which cannot act on it).
std::optional<Trace> encoded_trace(const std::vector<model::CycleInput>& inputs, const encoder::Encoding& enc,
                                   const encoder::TransitionSystem& ts, std::size_t* dropped = nullptr);

// Runs the inputs on a fresh reference runtime.
ConcreteTrace run_on_runtime(const model::Matrix& m, const std::vector<model::CycleInput>& inputs);

// Runs the inputs on the encoding's concrete evaluator (the encoder's side of
// a disagreement, for the internal-error report).
ConcreteTrace run_on_encoding(const encoder::Encoding& enc, const model::Matrix& m,
                              const std::vector<model::CycleInput>& inputs);

// Both traces side by side from the first cycle where an observable differs:
// what an internal error shows.
std::string describe_disagreement(const model::Matrix& m, const ConcreteTrace& runtime,
                                  const ConcreteTrace& encoding);

}  // namespace cemv::checker
