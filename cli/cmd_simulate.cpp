// `cemv simulate [MATRIX] SCENARIO [--trace out.json]`: replays a
// cemv-scenario/1 file on the reference runtime (docs/scenario.md, "cemv
// simulate"). Without MATRIX the scenario's `matrix` key names the matrix.
// Exit 0 when every expectation holds, 1 when one fails, 2 on invalid input.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <sstream>
#include <stdexcept>
#include <string_view>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
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

// Without MATRIX, the scenario's `matrix` key (docs/scenario.md, "Top level"),
// relative to the scenario's folder (the working folder for standard input),
// and inside the working folder unless the paths are trusted.
std::string matrix_of(const std::vector<std::string>& files, const std::string& scenario_text, bool trust_paths) {
  if (files.size() == 2) return files[0];
  const std::string name = input_name(files[0]);
  auto key = formats::scenario_matrix_key(scenario_text, name);
  if (!key)
    throw formats::LoadError({{"", "the scenario names no matrix: give MATRIX SCENARIO, or add "
                                   "\"matrix\": \"PATH\" (relative to the scenario file)", name}});
  const std::filesystem::path base = files[0] == "-" ? std::filesystem::path() : std::filesystem::path(files[0]).parent_path();
  return formats::resolve_inner_path(*key, base, std::filesystem::current_path(), trust_paths, scenario_text, name,
                                     "matrix")
      .string();
}

struct SimulateOptions {
  std::vector<std::string> files;
  std::string trace_file;
  std::string svg_file, vcd_file;  // the run's timing diagram and value change dump
  bool trace_changes = false;
  std::string format = "text";
  std::string out = "-";
  bool trust_paths = false;  // --trust-paths: follow the `matrix` key anywhere
};

// A sink that collects small writes into large ones (a trace line per cycle
// would otherwise be one write(2) each).
class BufferedOutput {
 public:
  explicit BufferedOutput(Output& out) : out_(out) {}
  void write(std::string_view text) {
    buffer_.append(text);
    if (buffer_.size() >= kChunk) flush();
  }
  void flush() {
    out_.write(buffer_);
    buffer_.clear();
  }

 private:
  static constexpr std::size_t kChunk = 1 << 16;
  Output& out_;
  std::string buffer_;
};

// An expected or observed value as JSON: Boolean, integer or voting text.
nlohmann::ordered_json value_json(model::FieldType type, int v) {
  switch (type) {
    case model::FieldType::Bool: return v != 0;
    case model::FieldType::Int: return v;
    case model::FieldType::Voting: return formats::expectation_value_text(type, v);
  }
  return v;
}

// Option conflicts, after every destination has been checked.
void check_option_conflicts(const SimulateOptions& o, bool quiet) {
  const bool tracing = !o.trace_file.empty();
  if (o.trace_changes && !tracing) throw std::invalid_argument("simulate: --trace-changes needs --trace FILE");
  if (tracing && o.trace_file == o.out && o.out != "-")
    throw std::invalid_argument("simulate: --trace and -o name the same file");
  if (tracing && o.trace_file == "-" && (o.out == "-" && (o.format == "json" || !quiet)))
    throw std::invalid_argument("simulate: --trace - writes the trace to standard output; give -o FILE for "
                                "the result, or --quiet");
  if (o.files.size() == 2 && o.files[0] == "-" && o.files[1] == "-")
    throw std::invalid_argument("simulate: '-' (standard input) can be read only once");
}

// The JSON steps whose expectations are due in cycle c, with their outcomes.
void add_due_steps(const formats::Scenario& sc, const formats::ExpandedScenario& ex, std::size_t c, std::uint32_t cycle_ms,
                   const std::vector<formats::ExpectationOutcome>& outcomes, nlohmann::ordered_json& steps) {
  for (const auto& check : ex.checks) {
    if (check.cycle != c) continue;
    const formats::ScenarioStep& st = sc.steps[check.step];
    nlohmann::ordered_json step;
    step["step"] = check.step;
    if (!st.description.empty()) step["description"] = st.description;
    step["cycle"] = c + 1;
    step["t_ms"] = static_cast<std::uint64_t>(c) * cycle_ms;
    nlohmann::ordered_json expectations = nlohmann::ordered_json::array();
    for (const auto& outcome : outcomes) {
      if (outcome.step != check.step) continue;
      const formats::Expectation& x = *outcome.expectation;
      expectations.push_back({{"key", x.key},
                              {"expected", value_json(x.type, x.expected)},
                              {"observed", outcome.actual ? value_json(x.type, *outcome.actual)
                                                          : nlohmann::ordered_json(nullptr)},
                              {"pass", outcome.ok}});
    }
    step["expectations"] = std::move(expectations);
    steps.push_back(std::move(step));
  }
}

// What a run of the scenario counted, for its summary.
struct RunSummary {
  std::string matrix_file, scenario_file, signature;
  std::size_t steps = 0, cycles = 0, checked = 0, failed = 0;
  std::uint64_t refused = 0;
};

std::string simulation_json(const model::Matrix& m, const RunSummary& r, nlohmann::ordered_json steps) {
  nlohmann::ordered_json j;
  j["format"] = "cemv-simulation/1";
  j["matrix"] = m.name;
  j["signature"] = r.signature;
  j["matrix_file"] = input_name(r.matrix_file);
  j["scenario"] = r.scenario_file;
  j["cycle_ms"] = m.cycle_ms;
  j["cycles"] = r.cycles;
  j["expectations"] = r.checked;
  j["failed"] = r.failed;
  j["commands_refused"] = r.refused;
  j["steps"] = std::move(steps);
  j["verdict"] = r.failed == 0 ? "PASS" : "FAIL";
  return j.dump(2) + "\n";
}

std::string simulation_text(const model::Matrix& m, const RunSummary& r, const reports::TimingTable& timing,
                            const std::string& pictures_named) {
  std::ostringstream text;
  timing.print(text, m.cycle_ms);
  text << "matrix " << m.name << " signature " << r.signature << "\n";
  text << "scenario " << r.scenario_file << ": " << r.steps << " steps, " << r.cycles << " cycles, " << r.checked
       << " expectations, " << r.failed << " failed";
  if (r.refused) text << ", " << r.refused << (r.refused == 1 ? " command" : " commands") << " refused";
  text << "\n" << pictures_named << (r.failed == 0 ? "PASS" : "FAIL") << "\n";
  return text.str();
}

int run_simulate(const SimulateOptions& o, bool quiet) {
  // Every destination is checked before the scenario runs.
  check_writable(o.out);
  const bool tracing = !o.trace_file.empty();
  if (tracing) check_writable(o.trace_file);
  TracePictures pictures(o.svg_file, o.vcd_file);  // checks its destinations now, before the run
  check_option_conflicts(o, quiet);
  const bool json_format = o.format == "json";

  RunSummary summary;
  summary.scenario_file = input_name(o.files.back());
  // The matrix first when both are given, so its errors come first.
  std::optional<model::Matrix> given;
  if (o.files.size() == 2) given = load_valid_matrix(o.files[0], "simulated");
  const std::string scenario_text = read_input(o.files.back());
  summary.matrix_file = matrix_of(o.files, scenario_text, o.trust_paths);
  model::Matrix m = given ? std::move(*given) : load_valid_matrix(summary.matrix_file, "simulated");
  formats::Scenario sc = formats::parse_scenario(scenario_text, m, summary.scenario_file);
  formats::ExpandedScenario ex = formats::expand_scenario(sc, m);
  summary.signature = formats::signature(m);

  runtime::Runtime rt(m);
  const model::InputTable& inputs = rt.inputs();
  const std::vector<model::Observable> obs = model::observables(m);
  const std::vector<std::string> outputs = output_tag_names(m, obs);
  reports::TimingTable timing(inputs, obs);
  formats::ExpectationChecker checker(ex);

  Output result(o.out);
  std::optional<Output> trace_out;
  std::optional<BufferedOutput> trace_buffer;
  std::optional<formats::TraceWriter> trace;
  if (tracing) {
    trace_out.emplace(o.trace_file);
    trace_buffer.emplace(*trace_out);
    trace.emplace(m, inputs, obs, outputs, summary.signature, [&](std::string_view t) { trace_buffer->write(t); },
                  formats::TraceWriter::Options{o.trace_changes});
  }

  nlohmann::ordered_json steps = nlohmann::ordered_json::array();
  std::vector<int> snap;
  const RuntimeValues values(rt, obs, snap);
  std::vector<std::optional<bool>> output_values;
  for (std::size_t c = 0; c < ex.cycles.size(); ++c) {
    const model::CycleInput& in = ex.cycles[c];
    rt.step(in);
    rt.snapshot(snap);
    pictures.record(m, in, snap);
    summary.refused += static_cast<std::uint64_t>(rt.commands_refused());
    if (!json_format) timing.record(c + 1, in, snap);
    if (trace) {
      output_values.clear();
      for (const auto& name : outputs) output_values.push_back(rt.output(name));
      trace->add_cycle(c, ex.step_of_cycle[c], in, rt.commands_refused(), snap, output_values);
    }
    std::vector<formats::ExpectationOutcome> outcomes = checker.after_cycle(c, values);
    for (const auto& outcome : outcomes)
      if (!outcome.ok) pictures.mark(outcome, m.cycle_ms);
    if (json_format) {
      add_due_steps(sc, ex, c, m.cycle_ms, outcomes, steps);
      continue;
    }
    for (const auto& outcome : outcomes)
      if (!outcome.ok) result.write(outcome.failure_text(m.cycle_ms) + "\n");
  }

  summary.steps = sc.steps.size();
  summary.cycles = ex.cycles.size();
  summary.checked = checker.checked();
  summary.failed = checker.failed();
  std::ostringstream pictures_named;  // one line per file written
  pictures.write(m, "Scenario " + summary.scenario_file + " on matrix " + m.name, pictures_named);
  if (json_format)
    result.write(simulation_json(m, summary, std::move(steps)));
  else if (!quiet)
    result.write(simulation_text(m, summary, timing, pictures_named.str()));
  // The trace is complete before the result is: a reader that sees PASS finds
  // the whole trace in place.
  if (trace) {
    trace->finish();
    trace_buffer->flush();
    trace_out->commit();
  }
  result.commit();
  return summary.failed == 0 ? 0 : 1;
}

}  // namespace

void add_simulate_commands(CLI::App& app, Context& ctx) {
  auto* cmd = app.add_subcommand(
      "simulate", "Run a cemv-scenario/1 file on the reference runtime and check its expectations");
  auto o = std::make_shared<SimulateOptions>();
  cmd->add_option("FILES", o->files,
                  "[MATRIX] SCENARIO: the cemv-matrix/1 file (default: the scenario's \"matrix\" key; "
                  "'-' = standard input) and the cemv-scenario/1 file")
      ->required()
      ->expected(1, 2);
  cmd->add_option("--trace", o->trace_file,
                  "Write the per-cycle trace (cemv-trace/1: inputs, every observable) to this file, "
                  "streamed as the scenario runs and replaced atomically at the end");
  cmd->add_flag("--trace-changes", o->trace_changes,
                "With --trace: write only the cycles whose row changes (and the first and last)");
  cmd->add_option("--format", o->format, "text (default: failures, timing table, summary) or json "
                                         "(cemv-simulation/1, docs/scenario.md)")
      ->check(CLI::IsMember({"text", "json"}));
  cmd->add_option("--svg", o->svg_file, "write the run's timing diagram as SVG")->type_name("FILE");
  cmd->add_option("--vcd", o->vcd_file, "write the run as a value change dump (VCD, IEEE 1364)")->type_name("FILE");
  cmd->add_option("-o,--output", o->out, "Write the result here instead of standard output");
  cmd->add_flag("--trust-paths", o->trust_paths,
                "follow the scenario's \"matrix\" key even when it is absolute or leads outside the working "
                "folder (refused by default: a scenario in a pull request is untrusted)");
  add_quiet_flag(cmd, ctx);
  cmd->callback([o, &ctx]() { ctx.exit_code = run_simulate(*o, ctx.quiet); });
}

}  // namespace cemv::cli
