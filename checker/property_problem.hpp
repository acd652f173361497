// A property of the property language as a safety problem of the prover
// interface (checker/prover.hpp): the matrix's encoding (its cone of
// influence, or all of it), the property's monitor compiled into it, and the
// input ranges every replayable trace respects. The checker, the test
// generator and the response-time analysis all state their questions this way.
#pragma once

#include <functional>
#include <vector>

#include "checker/prover.hpp"
#include "encoder/encode.hpp"
#include "model/matrix.hpp"
#include "properties/ast.hpp"

namespace cemv::checker {

// What a problem asks of the property's monitor.
enum class Goal {
  Property,     // `good` in every cycle
  Antecedent,   // never the antecedent (falsified = the antecedent is reachable)
  Assumptions,  // never any cycle at all (falsified = the assumptions can hold)
};

struct ProblemOptions {
  Goal goal = Goal::Property;
  bool sliced = true;  // the property's cone of influence only (docs/encoding.md "Slices")
  // Applied to every encoding before the monitor is compiled (Pono's modifiers/).
  std::function<void(encoder::Encoding&)> modify_encoding;
};

// The factory builds the problem in any context (one per portfolio thread).
// It keeps copies of the matrix and pointers to the property and its file:
// both must outlive the factory. The owner of every built problem is its
// encoder::Encoding.
ProblemFactory property_problem(const model::Matrix& m, const properties::PropertyFile& file,
                                const properties::Property& p, const ProblemOptions& options = {});

}  // namespace cemv::checker
