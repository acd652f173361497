// The pictures of one replayed run (`cemv simulate --svg FILE --vcd FILE`):
// records the cycles as the replay goes and, at the end, writes the timing
// diagram and the value change dump through cli/output.hpp (docs/reports.md).
#pragma once

#include <cstddef>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "checker/result.hpp"
#include "formats/scenario.hpp"
#include "model/matrix.hpp"
#include "reports/timing_svg.hpp"

namespace cemv::cli {

class TracePictures {
 public:
  // Empty names: nothing is recorded or written. The destinations are checked
  // here, before the run.
  TracePictures(std::string svg_file, std::string vcd_file);
  // `m` must outlive this object (the diagram is drawn as the run goes).
  void record(const model::Matrix& m, const model::CycleInput& in, const std::vector<int>& snapshot);
  // A failed expectation, marked at its cycle.
  void mark(const formats::ExpectationOutcome& failed, std::uint32_t cycle_ms);
  // Writes the files and names them on `out`, one line each.
  void write(const model::Matrix& m, const std::string& title, std::ostream& out) const;

 private:
  std::string svg_file_, vcd_file_;
  checker::ConcreteTrace trace_;               // for the VCD only
  mutable std::unique_ptr<reports::TimingRecorder> svg_;  // the diagram, drawn as the run goes
  std::vector<reports::TimingMark> marks_;
};

// The timing diagram of a generated acceptance test (`cemv testgen`): its
// inputs run on the reference runtime, every observable that changes drawn,
// the cycles at which it checks its expectations ticked.
std::string test_diagram(const model::Matrix& m, const std::string& title, const std::vector<model::CycleInput>& inputs,
                         const std::vector<std::size_t>& checkpoints);

// "DIR/T001-x.scenario.json" -> "DIR/T001-x.svg" (any other name: NAME.svg).
std::string diagram_name(const std::string& scenario_file);

}  // namespace cemv::cli
