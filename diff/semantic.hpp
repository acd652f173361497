// The semantic comparison of two versions of a matrix
// (docs/change-acceptance.md): for every effect, and for every output tag of an
// effect whose behaviour changed, whether OLD and NEW are observably
// equivalent over all inputs and operator actions (checker/equivalence.hpp, on
// the product of OLD and NEW relabelled into OLD's numbering), or differ, with
// the shortest run that shows it, replayed on both runtimes. Then the impact
// set: the effects whose behaviour changed and the causes, tags and SIF groups
// involved.
#pragma once

#include <chrono>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "checker/equivalence.hpp"
#include "checker/limits.hpp"
#include "diff/structural.hpp"
#include "model/matrix.hpp"

namespace cemv::diff {

struct EffectBehaviour {
  int old_id = 0;   // 0: added in NEW
  int new_id = 0;   // 0: removed in NEW
  std::string name;
  // Whether the structural comparison lists a change of this effect, of an
  // intersection into it, or of an element of its cone (OLD or NEW).
  bool structurally_changed = false;
  // Whether a critical structural change (6.2.3: the safety logic) touches
  // the effect or its cone in either version: what the semantic verdict is
  // held against to decide whether the two comparisons agree.
  bool critically_changed = false;
  // The effect as a whole; for an added or removed effect, verdict Differs by
  // interface. Keys and ids in `result` are OLD's numbering.
  checker::GroupEquivalence result;
  std::vector<checker::GroupEquivalence> outputs;  // per output tag, when the effect differs
  // The distinguishing run of `result` under NEW's own numbers (after a
  // relabelling the run is mapped back and confirmed on NEW itself): NEW's
  // inputs per cycle, and the differing observable's key in NEW.
  std::vector<model::CycleInput> new_inputs;
  std::string new_key;
  bool behaviour_changed() const { return result.verdict != checker::EquivalenceVerdict::Equivalent; }
};

struct Impact {
  std::vector<int> effects;            // NEW ids (OLD ids for removed effects)
  std::set<int> causes;                // NEW ids of the causes in their cones
  std::set<std::string> tags;          // input and output tags involved
  std::set<int> sif_groups;
};

struct SemanticDiff {
  std::vector<EffectBehaviour> effects;  // OLD effects by id, then added ones
  Impact impact;
  bool relabelled = false;  // NEW was renumbered (a move): runs replayed on NEW itself too
  bool any_changed() const;
  bool any_unknown() const;
};

// Manual 12 and 11.2: "if the comparisons list exactly the changes you made,
// test only those, otherwise test the entire matrix". A partial retest is
// justified when the two comparisons agree: every effect decided, and every
// effect whose behaviour changed has a critical structural change in its cone
// (a behaviour change that no listed change explains means the comparison
// cannot be trusted to list everything). The effects to retest are then the
// impact set's.
struct RetestScope {
  bool partial = false;
  std::string reason;  // one sentence
};
RetestScope retest_scope(const SemanticDiff& d);

struct SemanticOptions {
  checker::Work work = 20 * checker::kMega;  // each engine's budget of work per effect
  double timeout_s = 0.0;                    // --timeout: the user's wall clock per effect (0 = none)
  int jobs = 1;                              // effects decided in parallel (the run's one work queue)
  checker::CancelToken* cancel = nullptr;    // the run's (a failure elsewhere, the caller's bound)
};

// Throws checker::InternalError when a distinguishing run does not replay on
// both runtimes (or on NEW itself after a relabelling).
SemanticDiff compare_behaviour(const model::Matrix& old_m, const model::Matrix& new_m, const StructuralDiff& d,
                               const SemanticOptions& options = {});

}  // namespace cemv::diff
