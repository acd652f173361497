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
#include "reports/timing_svg.hpp"

namespace cemv::reports::timing {

enum class RowKind { Digital, Bus, Analog, Timer, Commands };

// A horizontal reference line of an analog row.
struct Level {
  double value = 0.0;
  std::string label;  // "C1 high limit 85"
  std::string css;    // "limit", "prewarning", "hysteresis"
};

struct Row {
  RowKind kind = RowKind::Digital;
  std::string label;
  std::string note;                 // second line under the label ("T = 2 s", "unit mbar")
  std::vector<double> value;        // per cycle: 0/1, a count, an analog value
  std::vector<std::string> text;    // per cycle: a bus's value, the commands of a cycle
  std::vector<bool> bad;            // input tags: bad quality per cycle
  std::vector<Level> levels;        // analog rows
  double duration_ms = 0.0;         // timers: the configured time (0 = unknown)
  bool changes = false;             // some value differs from the first cycle
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
