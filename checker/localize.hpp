// Localization abstraction (Kurshan; Pono's and ABC's "localization"): the
// state variables outside a chosen set lose their initial value and their
// next-state function and become inputs, free in every cycle. What they fed
// then reads any value it could read before and more, so the localized
// problem has every run of the original (seen through the kept variables)
// and more runs besides:
// - a proof of the localized problem is a proof of the original. Its
//   evidence (an invariant and an induction depth over kept variables) is
//   re-checked on the original with a fresh solver before it counts
//   (checker/check/recheck.hpp), so the claim never rests on this file;
// - a counterexample of the localized problem may be spurious: it counts
//   only after its inputs replay to a violation on the original.
// After the freeing, the exact cone of influence (checker/reduce.hpp) drops
// whatever only the freed variables read.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "checker/prover.hpp"
#include "model/node.hpp"

namespace cemv::checker {

struct Localization {
  std::size_t state_vars_before = 0, state_vars_after = 0;
  std::size_t freed = 0;  // state variables made inputs
};

// Which state variables stay state (by name).
using KeepState = std::function<bool(const std::string& state_name)>;

// Keeps the state of the given matrix elements and everything that belongs
// to no element (first_cycle, group deactivation, first-out groups, the
// property's monitor): the encoder names an element's state variables with
// the element's key first, `cause[i].`/`effect[j].`, and the previous value
// of a reference with `prev.` before it (docs/encoding.md, "State").
KeepState keep_elements(const std::vector<model::Node>& elements);

// The localized problem, or nullopt when `keep` frees nothing. Its owner
// keeps the original's owner alive.
std::optional<OwnedProblem> localize(const OwnedProblem& original, const KeepState& keep,
                                     Localization* what = nullptr);

// A counterexample of the localized problem as a run of the original: the
// original's inputs as the localized trace gave them, the freed variables
// left to the original's own next-state functions. Nullopt when that run
// does not violate `good` (within the trace's length) with the assumption
// held: the localized trace was spurious.
std::optional<Trace> concretize(const SafetyProblem& original, const Trace& localized);

}  // namespace cemv::checker
