// What a timing diagram draws, before any geometry: the rows of a run (which
// signals, drawn how, with which reference lines) and its columns (the cycles
// shown one by one and the constant stretches folded). Internal to
// reports/timing_svg*.cpp; kept apart so the drawing code stays short.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "checker/result.hpp"
#include "model/matrix.hpp"
#include "model/vocabulary.hpp"
#include "reports/timing_svg.hpp"

namespace cemv::reports::timing {

enum class RowKind { Digital, Bus, Analog, Timer, Commands };

// A horizontal reference line of an analog row.
struct Level {
  double value = 0.0;
  std::string label;  // "C1 high limit 85"
  std::string css;    // "limit", "prewarning", "hysteresis"
};

// A stretch of cycles [from, to] in which a row's value, text and quality
// stay the same: a row is held run-length coded, so an 8 h run that changes a
// few hundred times costs a few hundred segments, not one entry per cycle.
struct Segment {
  double value = 0.0;    // 0/1, a count, an analog value
  std::string text;      // a bus's value, the commands of a cycle
  bool bad = false;      // input tags: bad quality
  std::size_t from = 0;  // first cycle, 0-based
  std::size_t to = 0;    // last cycle
};

struct Row {
  RowKind kind = RowKind::Digital;
  std::string label;
  std::string note;                 // second line under the label ("T = 2 s", "unit mbar")
  std::vector<Segment> segments;    // in cycle order, covering every cycle, neighbours differ
  std::vector<Level> levels;        // analog rows
  double duration_ms = 0.0;         // timers: the configured time (0 = unknown)
  bool changes = false;             // some value differs from the first cycle

  // Appends cycle `segments.back().to + 1` (or cycle 0).
  void append(double value, std::string text, bool bad);
  const Segment& at(std::size_t cycle) const;  // the segment holding `cycle`
  std::size_t cycles() const { return segments.empty() ? 0 : segments.back().to + 1; }
  bool any_bad() const;
  // How long a timer row has been non-zero without a break at `cycle`, in cycles.
  std::size_t running_for(std::size_t cycle) const;
};

// The rows of a run, built one cycle at a time from the inputs and the
// runtime's snapshot after it (observables in model::observables(m) order),
// so that a long run is drawn without holding its trace.
class RowBuilder {
 public:
  RowBuilder(const model::Matrix& m, const TimingDiagram& d);
  void add(const model::CycleInput& in, const std::vector<int>& snapshot);
  std::size_t cycles() const { return cycles_; }
  // The rows drawn, in order: input tags that change (or are shown), the
  // operator commands, the shown observables, the other changing ones.
  std::vector<Row> rows() const;

 private:
  const model::Matrix& m_;
  const TimingDiagram& d_;
  std::vector<model::Observable> all_;
  std::vector<Row> inputs_, observables_;
  Row commands_;
  std::size_t cycles_ = 0;
};

// A column: one cycle (first == last) or a folded constant stretch.
struct Column {
  std::size_t first = 0;
  std::size_t last = 0;
  bool folded = false;
};

std::vector<Row> rows_of(const model::Matrix& m, const checker::ConcreteTrace& t, const TimingDiagram& d);

// Cycles where something drawn changes, a command is issued or a mark sits
// keep their column together with a little context around them; longer
// stretches without any of these fold into one column.
std::vector<Column> columns_of(const std::vector<Row>& rows, std::size_t cycles,
                               const std::vector<TimingMark>& marks);

// "0.3 s", "1 min 5.2 s" style time of the start of cycle `cycle` (0-based).
std::string time_text(double ms);

}  // namespace cemv::reports::timing
