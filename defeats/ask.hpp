// One defeat question decided by `checker::check_properties` on response/'s
// requirement property (docs/defeats.md, "Questions to the checker"): the
// engine portfolio within budgets of work, every proof re-proved in a fresh
// context, every counterexample replayed on the runtime. The enumeration asks
// it for each minimal set it reports (the set's counterexample) and for a set
// its one encoding leaves undecided.
#pragma once

#include <string>
#include <vector>

#include "defeats/analysis.hpp"
#include "defeats/enumerate.hpp"
#include "defeats/runs.hpp"

namespace cemv::defeats {

// The property's name for a set: the path's key and the set's action numbers
// (1-based), "defeat.c1.e2.a3_7"; the empty set "defeat.c1.e2.none".
std::string set_name(const PathDefeats& pd, const std::vector<int>& set);

// Whether exactly the actions of `set` may occur defeats the path, named
// `property`. `group`: a question that only needs a proof (the proof engines
// alone, within a quarter of the budget); `write`: its counterexample may be
// reported (written under the out folder).
Question ask_checker(const model::Matrix& m, const PathDefeats& pd, const std::vector<int>& set,
                     const std::string& property, bool group, bool write, const std::vector<Run>& demand_runs,
                     const AskOptions& o);

// Ends a path's enumeration, whichever enumeration made it: complete or
// unknown with `reason` (a cancelled run is the time limit), its sets in
// order (size, then actions), its defeat distance the smallest indirect set.
void finish_path(PathDefeats& pd, bool complete, std::string reason, bool cancelled);

}  // namespace cemv::defeats
