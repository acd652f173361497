// The support of a proof (docs/checker.md, "Support"): the matrix elements a
// proved property needs, as a deletion-based inductive validity core. An
// element is a cell of the matrix (an intersection) or an option of a cause or
// effect (bypass, inhibit and reset tags, time functions, output delays,
// overrides). Starting from every candidate in the property's cone, each one
// is deleted in turn and the property re-proved on the smaller matrix; the
// deletion stays when the proof still goes through. What remains is minimal:
// deleting any one more element breaks the proof (or leaves it undecided
// within the budget, in which case the element is kept and the support is
// marked not minimal).
#pragma once

#include <functional>
#include <vector>

#include "checker/result.hpp"
#include "model/graph.hpp"
#include "model/matrix.hpp"

namespace cemv::checker {

// A deletion the support search can try: a key for people, and the edit.
struct Deletion {
  SupportElement element;
  std::function<void(model::Matrix&)> apply;
};

// The candidate deletions among the elements of `cone`, in a fixed order
// (intersections by cause then effect, then options of causes, then effects).
std::vector<Deletion> candidate_deletions(const model::Matrix& m, const std::vector<model::Node>& cone);

enum class ReproveOutcome { Proved, NotProved, Undecided };

// Greedy minimisation. `reprove` decides the property on an edited matrix.
// Returns the kept elements; `minimal` is false when some re-proof was
// undecided. `reduced` receives the matrix with every deletion that stayed:
// the one whose proof the support claims.
std::vector<SupportElement> minimal_support(const model::Matrix& m, const std::vector<Deletion>& candidates,
                                            const std::function<ReproveOutcome(const model::Matrix&)>& reprove,
                                            bool& minimal, model::Matrix* reduced = nullptr);

}  // namespace cemv::checker
