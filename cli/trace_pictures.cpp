#include "cli/trace_pictures.hpp"

#include "cli/output.hpp"
#include "reports/vcd.hpp"
#include "runtime/runtime.hpp"

namespace cemv::cli {

namespace {

std::unique_ptr<reports::TimingRecorder> recorder(const model::Matrix& m) {
  reports::TimingDiagram d;
  d.all_changing = true;
  return std::make_unique<reports::TimingRecorder>(m, std::move(d));
}

}  // namespace

TracePictures::TracePictures(std::string svg_file, std::string vcd_file)
    : svg_file_(std::move(svg_file)), vcd_file_(std::move(vcd_file)) {
  if (!svg_file_.empty()) check_writable(svg_file_);
  if (!vcd_file_.empty()) check_writable(vcd_file_);
}

void TracePictures::record(const model::Matrix& m, const model::CycleInput& in, const std::vector<int>& snapshot) {
  if (!svg_file_.empty()) {
    if (!svg_) svg_ = recorder(m);
    svg_->add(in, snapshot);
  }
  if (vcd_file_.empty()) return;
  trace_.inputs.push_back(in);
  trace_.observables.push_back(snapshot);
}

void TracePictures::mark(const formats::ExpectationOutcome& failed, std::uint32_t cycle_ms) {
  std::string text = failed.failure_text(cycle_ms);
  // "FAIL steps[1] (cycle 21, t = 2000 ms): WHAT": the diagram says the cycle itself.
  auto colon = text.find("): ");
  marks_.push_back({failed.cycle, "expectation failed: " + (colon == std::string::npos ? text : text.substr(colon + 3))});
}

void TracePictures::write(const model::Matrix& m, const std::string& title, std::ostream& out) const {
  if (!svg_file_.empty()) {
    if (!svg_) svg_ = recorder(m);  // a run of no cycles
    svg_->diagram().title = title;
    svg_->diagram().marks = marks_;
    write_output(svg_file_, svg_->svg());
    out << "diagram: " << svg_file_ << "\n";
  }
  if (!vcd_file_.empty()) {
    write_output(vcd_file_, reports::vcd(m, trace_, {"", CEMV_VERSION, title}));
    out << "waveforms: " << vcd_file_ << "\n";
  }
}

std::string test_diagram(const model::Matrix& m, const std::string& title, const std::vector<model::CycleInput>& inputs,
                         const std::vector<std::size_t>& checkpoints) {
  reports::TimingDiagram d;
  d.title = title;
  d.all_changing = true;
  d.checks = checkpoints;
  // Drawn as the runtime steps: an 8 h test is not held as a trace.
  reports::TimingRecorder picture(m, std::move(d));
  runtime::Runtime rt(m);
  std::vector<int> snap;
  for (const auto& in : inputs) {
    rt.step(in);
    rt.snapshot(snap);
    picture.add(in, snap);
  }
  return picture.svg();
}

std::string diagram_name(const std::string& scenario_file) {
  const std::string suffix = ".scenario.json";
  const std::string& f = scenario_file;
  if (f.size() > suffix.size() && f.compare(f.size() - suffix.size(), suffix.size(), suffix) == 0)
    return f.substr(0, f.size() - suffix.size()) + ".svg";
  return f + ".svg";
}

}  // namespace cemv::cli
