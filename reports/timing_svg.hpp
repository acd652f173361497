// Timing diagrams of a concrete run as self-contained SVG (docs/reports.md,
// "Timing diagrams"), drawn the way the manual explains time behaviour
// (chapter 13): one row per signal, time running to the right. Digital signals
// are waveforms, counts and votings are buses with their value written in,
// analog inputs are stepped plots with the limit, prewarning and hysteresis
// lines of every cause that reads them, timers are bars that grow while they
// run, operator commands are markers, and the cycle of a violation or of a
// failed expectation is marked. Long stretches in which nothing drawn changes
// are folded into one narrow column that says how many cycles it hides, so
// runs of 3 to 3,000 cycles stay readable. No scripts, no external resources;
// the same run always gives the same bytes.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "checker/result.hpp"
#include "model/matrix.hpp"

namespace cemv::reports {

// A marked cycle: a violation, a witness, a failed expectation.
struct TimingMark {
  std::size_t cycle = 0;  // 0-based
  std::string label;      // "violated: req5.stored_holds"
};

struct TimingDiagram {
  std::string title;
  // Observables drawn whether or not they change, in this order (keys as
  // model::observables spells them). Unknown keys are ignored.
  std::vector<std::string> shown;
  // Also draw every other observable that changes during the run (after the
  // shown ones, in model::observables order). Input tags are drawn when they
  // change, always.
  bool all_changing = false;
  // Input tags drawn whether or not they change (names as the matrix spells
  // them): a run that holds a transmitter over its limit from the first cycle
  // needs it drawn, though it never changes.
  std::vector<std::string> inputs_shown;
  std::vector<TimingMark> marks;
  // Cycles (0-based) at which a test checks its expectations: small ticks
  // under the cycle axis, without a line of text each (a test has many).
  std::vector<std::size_t> checks;
  // Lines written under the picture, before the legend: the explanation of
  // a counterexample, one line per change (checker::StepNote).
  std::vector<std::string> notes;
};

// The diagram of `trace` (inputs indexed by model::InputTable(m), observables
// in model::observables(m) order).
std::string timing_svg(const model::Matrix& m, const checker::ConcreteTrace& trace, const TimingDiagram& d);

namespace timing {
class RowBuilder;
}

// The diagram of a run drawn as it goes: each cycle's inputs and the
// runtime's snapshot after it are added one at a time and kept run-length
// coded, so memory grows with the changes drawn, not with the run's length
// (an 8 h test of 576,000 cycles). svg() gives the bytes timing_svg gives for
// the same run.
class TimingRecorder {
 public:
  TimingRecorder(const model::Matrix& m, TimingDiagram d);
  ~TimingRecorder();
  void add(const model::CycleInput& in, const std::vector<int>& snapshot);
  // Its title, marks, checks and notes may still change before svg(); which
  // rows are drawn (shown, inputs_shown, all_changing) is fixed at construction.
  TimingDiagram& diagram() { return *d_; }
  std::string svg() const;

 private:
  const model::Matrix& m_;
  std::unique_ptr<TimingDiagram> d_;  // the builder refers to it
  std::unique_ptr<timing::RowBuilder> rows_;
};

// The diagram of one property result with a trace (a counterexample or a
// witness): its inputs that change, the signals it reads, the violation marked.
TimingDiagram diagram_of(const checker::PropertyResult& p);

}  // namespace cemv::reports
