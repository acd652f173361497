// The directed runs cemv response hands the checker before its engines
// (checker::CheckOptions::directed_runs): the demand a path's trigger
// describes, on a quiet plant, in the variants docs/response-time.md
// ("Method") lists. Each is only a candidate: what it shows is replayed and
// judged like any counterexample, and when it does not violate, the engines
// decide.
#pragma once

#include <optional>
#include <vector>

#include "model/matrix.hpp"
#include "model/vocabulary.hpp"
#include "response/paths.hpp"
#include "response/property.hpp"

namespace cemv::response {

// The demand the trigger describes, as a run for the checker to try before
// its engines (checker::CheckOptions::directed_runs): the plant quiet in the
// first cycle (every cause's inputs inside their limits, pass-through process
// values of the path's effects away from the active state); from the second
// on, of each trigger cause (of an XooN, each cause of the demand set) as
// many external inputs as its voting needs beyond the limit with good
// quality, held for `cycles` + 1 cycles, so that "within `cycles`" is
// violated in the last cycle if the outputs have not responded by then.
// Degraded: the first external input of the first voted trigger cause in bad
// quality instead. Only a candidate: what it shows is replayed and checked
// like any counterexample, and when it does not violate, the engines decide.
// `pulses_first`: an XooN's demand set takes its timed (pulse) causes first,
// shortest pulse first, then the longest on-delays (docs/response-time.md,
// "XooN paths"); nullopt when the path has no timed trigger cause.
std::vector<model::CycleInput> demand_run(const model::Matrix& m, const Path& p, Mode mode, long long cycles);
std::optional<std::vector<model::CycleInput>> demand_run_pulses_first(const model::Matrix& m, const Path& p,
                                                                      Mode mode, long long cycles);

// The same demand with the path's effects left to it alone: every other
// cause linked to an effect of the path held off by its bypass and inhibit
// tags (C.8) from the first cycle on, where it has them and they are no tags
// of the path's own elements. Other causes are free in the property (only
// the path's are assumed not bypassed), and a cause tripped at rest (a
// permissive that reads an inactive element, a tag two causes read with
// limits no value meets) would answer the demand for the trigger. Nullopt
// when no such tag exists (the run would be demand_run's).
std::optional<std::vector<model::CycleInput>> demand_run_alone(const model::Matrix& m, const Path& p, Mode mode,
                                                               long long cycles);

// The demand after the plant has settled and the path's effects were reset:
// the quiet plant (others held off as in demand_run_alone, where they can
// be) for as long as the longest timer of the path's effects and of the
// causes linked to them, then one cycle in which every such cause with
// manual acknowledgement is acknowledged and every path effect reset (by
// its reset tag's edge, or the reset_effect command when it has none), one
// quiet cycle more, then the demand held for `cycles` + 1 cycles. An effect
// latched at start-up (an S cell of a pulse cause tripped by a permissive at
// rest) answers the plain demand at once; this run shows it released first.
// Nullopt when the settling would exceed 10,000 cycles.
std::optional<std::vector<model::CycleInput>> demand_run_after_reset(const model::Matrix& m, const Path& p,
                                                                     Mode mode, long long cycles);

// The demand after a reset (as above) on a plant whose rest trips are
// released: a cause linked to the path's effects that trips at rest because
// it reads an effect x that is not active (a timed one pulses at start-up and
// again whenever x falls) is kept quiet by tripping, in every cycle, a cause
// that activates x. Nullopt when there is no such cause.
std::optional<std::vector<model::CycleInput>> demand_run_settled(const model::Matrix& m, const Path& p, Mode mode,
                                                                 long long cycles);

// The plain demand from the first cycle on, without the quiet cycle: a
// trigger cause that trips at rest through an internal reference (it reads
// an effect that is not active at start-up) has requested its trip by the
// second cycle, so that only a demand at start-up is fresh (big_matrix's
// cause 69, an `or` that reads `Effect[68]`).
std::vector<model::CycleInput> demand_run_at_start_up(const model::Matrix& m, const Path& p, Mode mode,
                                                      long long cycles);

// Every run above that applies, in the order a probe tries them: the plain
// demand, the pulses first, the path alone, the demand after a reset, the
// settled demand, the demand at start-up; in degraded mode, an XooN's demand with each other voted
// member in bad quality.
std::vector<std::vector<model::CycleInput>> demand_runs(const model::Matrix& m, const Path& p, Mode mode,
                                                        long long cycles);

}  // namespace cemv::response
