// "Why, per step" (docs/checker.md): a counterexample or witness explained by
// the runtime's own evaluation. The trace's inputs are run again on the
// reference runtime with explanations on (runtime/explain.hpp); for every
// change of a signal the property reads (its observables, and the input tags
// it reads), the step says what changed and which rule of docs/semantics.md
// changed it. The checker returns plain traces; this is the command line's.
#pragma once

#include <vector>

#include "checker/result.hpp"
#include "model/matrix.hpp"
#include "properties/ast.hpp"

namespace cemv::cli {

// The steps of one trace for the given signals (observable keys, InputTable
// indices). Throws std::logic_error when the re-run does not reproduce the
// trace's observables (a runtime that is not deterministic: an internal error).
std::vector<checker::StepNote> explain_trace(const model::Matrix& m, const checker::ConcreteTrace& t,
                                             const std::vector<std::string>& observables,
                                             const std::vector<std::size_t>& inputs);

// Fills `explanation` of every result with a trace, each with the signals of
// its property in `files` (found by file and name).
void explain_results(const model::Matrix& m, const std::vector<properties::PropertyFile>& files,
                     checker::CheckResult& r);

}  // namespace cemv::cli
