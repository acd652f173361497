// The symbolic monitor: one property (properties/ast.hpp) as Z3 terms over an
// encoding's transition system, so that the checker's engines can prove or
// refute it. The past-time operators become state variables of the system
// (named `monitor.*`) with an initial value and a next-state function, so a
// property is a plain safety property: `good` must hold in every cycle.
//
// This is the symbolic one of the two independent implementations of
// docs/properties.md ("The symbolic monitor"); the concrete evaluator
// (properties/evaluator.*) is the other, and the two share no code.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <z3++.h>

#include "encoder/encode.hpp"
#include "model/matrix.hpp"
#include "model/node.hpp"
#include "properties/ast.hpp"

namespace cemv::properties {

// All terms range over the state and input variables of one cycle (the
// encoder's timing convention, docs/encoding.md).
struct Monitor {
  // Must hold in every cycle. Invariant: the body; Never and Reachable: not
  // the body (for Reachable, a violation of `good` is the witness); Response:
  // no trigger has gone N+1 cycles, its own included, without a response.
  z3::expr good;
  // Assumed in every cycle: the file's and the property's assumptions.
  z3::expr assumption;
  // What a vacuity check must be able to reach (docs/properties.md
  // "Vacuity"): the trigger of a Response, the left side of an Invariant
  // `a implies b`, the first conjunct of a Never `a and b`; else none.
  std::optional<z3::expr> antecedent;
  // The state variables this monitor added to the system, in creation order.
  std::vector<std::string> state_vars;
};

// Compiles `p` (with the file's assumptions) into `enc`'s transition system.
// The encoding must contain the cone of influence of property_roots(): an
// observable the encoding lacks is a std::logic_error. An input tag the
// encoding does not read becomes a fresh, unconstrained input variable
// (registered in Encoding::tag_value / tag_bad, so the encoder's Evaluator
// feeds it), which is exact because nothing encoded reads it.
Monitor compile_monitor(encoder::Encoding& enc, const Property& p,
                        const std::vector<Assumption>& file_assumptions);

// The processed causes and effects the property reads (sorted, unique): the
// element of every observable, every element reading an input tag the
// property reads, and the targets of its command patterns (every element
// such a command can name when the pattern leaves the target open), so that
// encoder::encode(ctx, m, roots) contains every command input a pattern can
// match.
std::vector<model::Node> property_roots(const Property& p,
                                        const std::vector<Assumption>& file_assumptions,
                                        const model::Matrix& m);

}  // namespace cemv::properties
