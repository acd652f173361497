// Seeded random runs of a plant and its operators, for the searches that a
// reference runtime answers faster than a solver: the witness of a coverage
// objective that needs many cycles and analog values (testgen/explore.*), and
// a run on which a mutant differs from its original (checker/equivalence.*).
// A run is a list of segments: some inputs change (to the values a test
// engineer sets: at rest, at each limit and the next float on the safe side,
// at each hysteresis threshold, ...), an operator command may be issued, and
// the inputs are then held for a number of cycles taken from the matrix's own
// durations (each time function, output delay and timeout in cycles, and one
// cycle either side), so a run reaches a timer's expiry or stops one cycle
// short of it. Runs are found, never trusted: every caller replays what it
// keeps on the reference runtime and judges it there.
//
// Deterministic: the same matrix, space and seed give the same runs on every
// machine (a fixed generator and integer arithmetic only, no library
// distributions).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "model/matrix.hpp"
#include "model/vocabulary.hpp"

namespace cemv::checker {

// The analog values an engineer would set on `tag` for the causes reading it
// (docs/semantics.md C.3-C.5), plus `hold`; sorted, without repeats.
std::vector<float> analog_test_values(const model::Matrix& m, const model::InputTag& tag, float hold);

// One stretch of a run: the changes at its start (tags by name, so that one
// run drives two matrices with different input tables), the commands of its
// first cycle, then `cycles` cycles with those inputs held.
struct RunSegment {
  struct Change {
    std::string tag;
    model::TagValue value;
  };
  std::vector<Change> changes;
  std::vector<model::Command> commands;
  std::size_t cycles = 1;
};
using Run = std::vector<RunSegment>;

// What random runs vary.
struct RunSpace {
  struct Tag {
    std::string name;
    std::vector<float> values;
  };
  std::vector<Tag> tags;
  std::vector<model::Command> commands;
  std::vector<std::size_t> holds;  // cycles a segment may last, ascending
  // Segments that trip one cause, or every cause of an effect's XooN
  // assignment (E.2): every tag they vote with beyond its limit (or at its
  // trip level), in good quality, held for the longest duration that fits.
  // Empty: none drawn. A question about a cause's activity, or an XooN of
  // causes, is reached by runs that trip causes whole, where changing one
  // tag at a time rarely trips two.
  std::vector<std::vector<RunSegment::Change>> trips;
  // The same tags back at rest (the scenario defaults, good quality), one
  // list per trip: a latch released, then reset, is a run that trips, rests
  // and resets.
  std::vector<std::vector<RunSegment::Change>> rests;
};

// The trip segments of the causes of `m` whose tags are all among `tags`,
// and of the XooN assignments whose causes all are (RunSpace::trips).
std::vector<std::vector<RunSegment::Change>> cause_trips(const model::Matrix& m, const std::vector<std::string>& tags);
// The changes that trip cause `c` when all its tags are among `tags` (a
// trip segment of RunSpace::trips); empty otherwise.
std::vector<RunSegment::Change> cause_trip(const model::Cause& c, const std::vector<std::string>& tags);
// Each trip's tags back at their scenario defaults, in good quality
// (RunSpace::rests).
std::vector<std::vector<RunSegment::Change>> rests_of(const model::Matrix& m,
                                                      const std::vector<std::vector<RunSegment::Change>>& trips);

// The space of `m` (and of `other`, when given: its tag values and durations
// join, so a run can tell a changed limit or duration apart). Only the tags
// named in `tags` and the given commands when those are non-empty; simulation
// commands are never issued (a simulated value reaches anything without the
// logic).
RunSpace run_space(const model::Matrix& m, const model::Matrix* other = nullptr,
                   const std::vector<std::string>& tags = {}, const std::vector<model::Command>& commands = {});

class RandomRuns {
 public:
  RandomRuns(RunSpace space, std::uint64_t seed) : space_(std::move(space)), state_(seed ? seed : 1) {}
  // A run of `segments` segments lasting at most `max_cycles` cycles (holds
  // longer than what is left are not drawn).
  Run next(std::size_t segments, std::size_t max_cycles = 5000);
  const RunSpace& space() const { return space_; }

 private:
  std::uint64_t draw(std::uint64_t n);  // uniform in [0, n)
  RunSpace space_;
  std::uint64_t state_;
};

// The cycle inputs of a run for matrix `m`, starting from `start`'s values
// (held; its commands are not repeated). Changes of tags `m` does not read are
// skipped; the commands of a cycle go in the matrix's processing order
// (model::CommandOrder), without those naming an element `m` lacks.
std::vector<model::CycleInput> expand(const model::Matrix& m, const Run& run, const model::CycleInput& start);
// The same cycle inputs one at a time, each given to `each` until it returns
// false: a run of a million cycles judged without holding them.
void for_each_cycle(const model::Matrix& m, const Run& run, const model::CycleInput& start,
                    const std::function<bool(const model::CycleInput&)>& each);

// The number of cycles a run lasts.
std::size_t run_cycles(const Run& run);

// A shorter run that still `keeps` (cut after cycle `cut`, segments dropped
// one by one, holds brought down to one cycle where that keeps): a readable
// run. `keep` returns the cycle that matters (a witness, a difference) or -1.
Run minimise_run(Run run, const std::function<long(const Run&)>& keep);

}  // namespace cemv::checker
