// `cemv simulate [MATRIX] SCENARIO [--trace out.json]`: replays a
// cemv-scenario/1 file on the reference runtime (docs/scenario.md, "cemv
// simulate"). Without MATRIX the scenario's `matrix` key names the matrix.
// Exit 0 when every expectation holds, 1 when one fails, 2 on invalid input.
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/trace_pictures.hpp"
#include "formats/matrix_json.hpp"
#include "formats/scenario.hpp"
#include "formats/trace.hpp"
#include "model/vocabulary.hpp"
#include "reports/timing_table.hpp"
#include "runtime/runtime.hpp"

namespace cemv::cli {

namespace {

// The output tag names, in the order of the output observables (effect[j].tag[k]).
std::vector<std::string> output_tag_names(const model::Matrix& m, const std::vector<model::Observable>& obs) {
  std::vector<std::string> names;
  for (const auto& o : obs)
    if (o.field == "tag") names.push_back(m.find_effect(o.id)->tags[static_cast<std::size_t>(o.tag - 1)].name);
  return names;
}

// What the runtime gives an expectation's target after the current cycle: an
// output tag by name, a status field from the observable snapshot.
class RuntimeValues {
 public:
  RuntimeValues(const runtime::Runtime& rt, const std::vector<model::Observable>& obs,
                const std::vector<int>& snapshot)
      : rt_(rt), snapshot_(snapshot) {
    for (std::size_t i = 0; i < obs.size(); ++i) index_[obs[i].key] = i;
  }
  std::optional<int> operator()(const formats::ExpectTarget& target) const {
    if (target.kind == formats::ExpectTarget::Kind::OutputTag) {
      auto v = rt_.output(target.output_tag);
      if (!v) return std::nullopt;
      return static_cast<int>(*v);
    }
    auto it = index_.find(target.observable.key);
    if (it == index_.end()) return std::nullopt;
    return snapshot_[it->second];
  }

 private:
  const runtime::Runtime& rt_;
  const std::vector<int>& snapshot_;
  std::map<std::string, std::size_t> index_;
};

// Without MATRIX, the scenario's `matrix` key (docs/scenario.md, "Top level").
std::filesystem::path matrix_of(const std::vector<std::string>& files) {
  if (files.size() == 2) return files[0];
  auto named = formats::scenario_matrix_path(files[0]);
  if (!named)
    throw formats::LoadError({{files[0], "the scenario names no matrix: give MATRIX SCENARIO, or add "
                                          "\"matrix\": \"PATH\" (relative to the scenario file)"}});
  return *named;
}

int run_simulate(const std::vector<std::string>& files, const std::string& trace_file, TracePictures pictures) {
  const std::string scenario_file = files.back();
  model::Matrix m = formats::load_valid_matrix(matrix_of(files), "simulated");
  formats::Scenario sc = formats::load_scenario(scenario_file, m);
  formats::ExpandedScenario ex = formats::expand_scenario(sc, m);

  runtime::Runtime rt(m);
  const model::InputTable& inputs = rt.inputs();
  const std::vector<model::Observable> obs = model::observables(m);
  const std::vector<std::string> outputs = output_tag_names(m, obs);
  reports::TimingTable timing(inputs, obs);
  formats::TraceWriter trace(m, inputs, obs, outputs);
  formats::ExpectationChecker checker(ex);

  std::vector<int> snap;
  const RuntimeValues values(rt, obs, snap);
  std::uint64_t refused_total = 0;
  for (std::size_t c = 0; c < ex.cycles.size(); ++c) {
    const model::CycleInput& in = ex.cycles[c];
    rt.step(in);
    rt.snapshot(snap);
    refused_total += static_cast<std::uint64_t>(rt.commands_refused());
    timing.record(c + 1, in, snap);
    pictures.record(in, snap);
    if (!trace_file.empty()) {
      std::vector<std::optional<bool>> output_values;
      for (const auto& name : outputs) output_values.push_back(rt.output(name));
      trace.add_cycle(c, ex.step_of_cycle[c], in, rt.commands_refused(), snap, output_values);
    }
    for (const auto& outcome : checker.after_cycle(c, values))
      if (!outcome.ok) {
        std::cout << outcome.failure_text(m.cycle_ms) << "\n";
        pictures.mark(outcome, m.cycle_ms);
      }
  }

  timing.print(std::cout, m.cycle_ms);
  std::string sig = formats::signature(m);
  std::cout << "matrix " << m.name << " signature " << sig << "\n";
  std::cout << "scenario " << scenario_file << ": " << sc.steps.size() << " steps, "
            << ex.cycles.size() << " cycles, " << checker.checked() << " expectations, "
            << checker.failed() << " failed";
  if (refused_total)
    std::cout << ", " << refused_total << (refused_total == 1 ? " command" : " commands") << " refused";
  std::cout << "\n";
  pictures.write(m, "Scenario " + scenario_file + " on matrix " + m.name, std::cout);
  std::cout << (checker.failed() ? "FAIL" : "PASS") << "\n";

  if (!trace_file.empty() && !trace.write(trace_file, sig)) {
    std::cerr << "error: " << trace_file << ": cannot write the trace\n";
    return 2;
  }
  return checker.failed() ? 1 : 0;
}

}  // namespace

void add_simulate_commands(CLI::App& app, Context& ctx) {
  auto* cmd = app.add_subcommand(
      "simulate", "Run a cemv-scenario/1 file on the reference runtime and check its expectations");
  static std::vector<std::string> files;
  static std::string trace_file;
  cmd->add_option("FILES", files,
                  "[MATRIX] SCENARIO: the cemv-matrix/1 file (default: the scenario's \"matrix\" key) "
                  "and the cemv-scenario/1 file")
      ->required()
      ->expected(1, 2);
  cmd->add_option("--trace", trace_file, "write the per-cycle trace (inputs, every observable) as JSON");
  static std::string svg_file, vcd_file;
  cmd->add_option("--svg", svg_file, "write the run's timing diagram as SVG")->type_name("FILE");
  cmd->add_option("--vcd", vcd_file, "write the run as a value change dump (VCD, IEEE 1364)")->type_name("FILE");
  cmd->callback([&ctx]() { ctx.exit_code = run_simulate(files, trace_file, TracePictures(svg_file, vcd_file)); });
}

}  // namespace cemv::cli
