// A concrete run as an IEEE 1364 value change dump (docs/reports.md, "VCD"),
// for waveform viewers such as GTKWave. One scope per matrix holds an
// `inputs` scope (every input tag; analog tags as `real`, Boolean ones as
// 1-bit wires, a `.bad` wire for tags whose quality goes bad), an `operator`
// scope (the number of commands issued per cycle), and one scope per cause
// and per effect with its status fields and outputs; a cause's scope also
// shows its input tags (the same identifier code as in `inputs`, which VCD
// allows). Time unit 1 ms; cycle n starts at (n-1) x cycle time, as in the
// timing tables. Deterministic: the date is the caller's.
#pragma once

#include <string>
#include <vector>

#include "checker/result.hpp"
#include "model/matrix.hpp"

namespace cemv::reports {

struct VcdHeader {
  std::string date;     // "$date" text; empty: no $date section
  std::string version;  // tool version for "$version"
  std::string comment;  // e.g. "counterexample to req5" (one line)
};

std::string vcd(const model::Matrix& m, const checker::ConcreteTrace& trace, const VcdHeader& h);

// Several runs in one dump (`cemv check --vcd FILE`: every counterexample and
// witness): under the matrix scope one scope per run, named `scope`, holding
// the scopes above; every run starts at time 0, and a shorter run keeps its
// last values to the end of the longest.
struct VcdRun {
  std::string scope;  // e.g. the property name (made a VCD word)
  const checker::ConcreteTrace* trace = nullptr;
};
std::string vcd_runs(const model::Matrix& m, const std::vector<VcdRun>& runs, const VcdHeader& h);

}  // namespace cemv::reports
