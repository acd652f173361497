// The plant around a path (docs/response-time.md, "Method"): the causes
// linked to its effects, what holds a cause of the path off (a bypass or
// inhibit that reads another element) and which causes release such holds,
// for the demand runs (response/demand.hpp) to set the plant up with.
#pragma once

#include <cstddef>
#include <set>
#include <vector>

#include "model/matrix.hpp"
#include "response/paths.hpp"

namespace cemv::response {

// The elements whose state holds a cause of the path off through its bypass
// or inhibit tag (an internal reference, 6.1.3). `effects`, `causes`: while
// active (`Effect[x]`, `Cause[x]`, `Effect[x][y]` of an energize-to-trip tag
// read 1 then); `inactive_effects`: while *not* active (`Effect[x][y]` of a
// de-energize-to-trip tag reads 1 until x responds, start-up included).
struct Holders {
  std::set<int> effects, causes, inactive_effects;
};
Holders holders_of(const model::Matrix& m, const Path& p);

// The ids of the effects on a path (its end and the effects its routes cross).
std::set<int> effects_on(const Path& p);

// The causes linked to an effect of the path.
std::set<int> linked_causes(const model::Matrix& m, const Path& p);

// Whether a cause's bypass or inhibit is driven by the logic (an internal
// reference), not by an operator's tag.
bool held_by_logic(const model::Cause& c);

// One cause that activates effect x in the cycle its condition holds: a
// processed intersection without XooN, no time function, external inputs
// only, its own bypass and inhibit not driven by the logic, and not in
// `linked`. Null when there is none.
const model::Cause* activator_of(const model::Matrix& m, int x, const std::set<int>& linked);

// A path cause held off while an effect x is *not* active
// (Holders::inactive_effects) is held off from start-up on, and no demand on
// it counts. The causes that release such holds: for each x, its
// activator_of that no path effect reads, tripped in every cycle of the
// demand runs. Without it the engines must find that release themselves
// (big_matrix's cause 107, bypassed through effect 18's tag 2).
std::vector<const model::Cause*> holds_released_by(const model::Matrix& m, const Path& p);

// The causes linked to the path's effects (not the path's own) that trip at
// rest through an internal reference reading an effect x that is not active
// (`Effect[x]` reads 0 then, `Effect[x][y]` 0 for an energize-to-trip tag y
// and 1 for a de-energize-to-trip one): such a cause answers for the path's
// effect at start-up, and a timed one pulses again whenever x falls
// (big_matrix's cause 123 reads `Effect[127]`, activates effect 127 with its
// 1 s pulse, and so trips again when the pulse ends; its V cell into effect
// 91 answers any demand on cause 82 for the first second). For each such x,
// the cause that activates it (activator_of), tripped in every cycle.
std::vector<const model::Cause*> rest_trips_released_by(const model::Matrix& m, const Path& p);

// The input tags (by index) that hold off the other causes of the path's
// effects and of the elements whose activity holds a path cause off
// (demand_run_alone).
std::set<std::size_t> hold_off_tags(const model::Matrix& m, const Path& p);

}  // namespace cemv::response
