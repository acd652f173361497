// `cemv simulate MATRIX SCENARIO [--trace out.json]`: replays a cemv-scenario/1
// file on the reference runtime (issue 3 section 4, docs/scenario.md).
// Exit 0 when every expectation holds, 1 when one fails, 2 on invalid input.
#include <charconv>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "formats/matrix_json.hpp"
#include "model/vocabulary.hpp"
#include "formats/scenario.hpp"
#include "model/validate.hpp"
#include "runtime/runtime.hpp"

namespace cemv::cli {

namespace {

using nlohmann::json;

// Shortest text that reads back as the same float: deterministic on any machine.
std::string real_text(float v) {
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  if (ec != std::errc{}) return "?";
  return std::string(buf, end);
}

std::string observable_text(const model::Observable& o, int v) {
  if (o.type == model::FieldType::Voting) return model::to_string(static_cast<model::Voting>(v));
  return std::to_string(v);
}

json observable_json(const model::Observable& o, int v) {
  switch (o.type) {
    case model::FieldType::Bool: return json(v != 0);
    case model::FieldType::Int: return json(v);
    case model::FieldType::Voting: return json(model::to_string(static_cast<model::Voting>(v)));
  }
  return json(v);
}

std::string input_text(const model::InputTag& t, const model::TagValue& v) {
  std::string s = t.kind == model::TagKind::Bool ? (v.value != 0.0f ? "1" : "0") : real_text(v.value);
  if (v.bad_quality) s += "(bad)";
  return s;
}

json input_json(const model::InputTag& t, const model::TagValue& v) {
  if (t.kind == model::TagKind::Bool) return json(v.value != 0.0f);
  // Through the shortest float text, so the trace shows 0.1 and not 0.100000001.
  return json(std::stod(real_text(v.value)));
}

json command_json(const model::Command& c) {
  json j;
  j["op"] = model::to_string(c.op);
  if (c.cause) j["cause"] = c.cause;
  if (c.effect) j["effect"] = c.effect;
  if (c.op == model::CommandOp::SoftBypassTag) j["tag"] = c.tag;
  if (c.group) j["group"] = c.group;
  switch (c.op) {
    case model::CommandOp::SoftBypassCause:
    case model::CommandOp::SoftBypassTag:
    case model::CommandOp::SoftBypassEffect: j["on"] = c.on; break;
    case model::CommandOp::SimulateTag:
      j["tag"] = c.tag_name;
      j["value"] = std::stod(real_text(c.value));
      break;
    case model::CommandOp::StopSimulation:
      if (!c.tag_name.empty()) j["tag"] = c.tag_name;
      break;
    default: break;
  }
  return j;
}

// One signal of the timing table: its value at the first cycle and at every
// cycle where it changes.
struct Timeline {
  std::string name;
  std::vector<std::pair<std::uint64_t, std::string>> points;
  void record(std::uint64_t cycle, std::string v) {
    if (points.empty() || points.back().second != v) points.emplace_back(cycle, std::move(v));
  }
};

void print_timing(std::ostream& out, const std::vector<Timeline>& lines, std::uint32_t cycle_ms) {
  std::size_t width = 0;
  for (const auto& l : lines)
    if (l.points.size() > 1) width = std::max(width, l.name.size());
  out << "timing (cycle:value at the first cycle and at each change; cycle n is t = (n-1)*"
      << cycle_ms << " ms):\n";
  bool any = false;
  for (const auto& l : lines) {
    if (l.points.size() <= 1) continue;
    any = true;
    out << "  " << l.name << std::string(width - l.name.size(), ' ');
    for (const auto& [c, v] : l.points) out << "  " << c << ":" << v;
    out << "\n";
  }
  if (!any) out << "  (no signal changes)\n";
}

int run_simulate(const std::string& matrix_file, const std::string& scenario_file,
                 const std::string& trace_file) {
  model::Matrix m = formats::load_matrix(matrix_file);
  auto diags = model::validate(m);
  if (model::has_errors(diags)) {
    std::cerr << "error: " << matrix_file
              << ": the matrix has validation errors; it cannot be simulated:\n";
    for (const auto& d : diags)
      if (d.severity == model::Severity::Error)
        std::cerr << "  " << d.rule << " " << d.element << " (" << d.section << "): " << d.message
                  << "\n";
    return 2;
  }
  formats::Scenario sc = formats::load_scenario(scenario_file, m);
  formats::ExpandedScenario ex = formats::expand_scenario(sc, m);

  runtime::Runtime rt(m);
  const model::InputTable& inputs = rt.inputs();
  const std::vector<model::Observable> obs = model::observables(m);
  std::map<std::string, std::size_t> obs_index;
  for (std::size_t i = 0; i < obs.size(); ++i) obs_index[obs[i].key] = i;

  std::vector<Timeline> timing;
  for (const auto& t : inputs.tags()) timing.push_back({t.name, {}});
  for (const auto& o : obs) timing.push_back({o.key, {}});
  std::vector<std::string> output_names;
  for (const auto& o : obs)
    if (o.field == "tag") {
      const model::Effect* e = m.find_effect(o.id);
      output_names.push_back(e->tags[static_cast<std::size_t>(o.tag - 1)].name);
    }

  json trace_cycles = json::array();
  std::vector<int> snap;
  std::size_t next_check = 0, checked = 0, failed = 0;
  std::uint64_t refused_total = 0;
  for (std::size_t c = 0; c < ex.cycles.size(); ++c) {
    const model::CycleInput& in = ex.cycles[c];
    rt.step(in);
    rt.snapshot(snap);
    std::uint64_t cycle_no = c + 1;
    refused_total += static_cast<std::uint64_t>(rt.commands_refused());
    for (std::size_t i = 0; i < inputs.size(); ++i)
      timing[i].record(cycle_no, input_text(inputs.tags()[i], in.tags[i]));
    for (std::size_t i = 0; i < obs.size(); ++i)
      timing[inputs.size() + i].record(cycle_no, observable_text(obs[i], snap[i]));

    if (!trace_file.empty()) {
      json cy;
      cy["cycle"] = cycle_no;
      cy["t_ms"] = static_cast<std::uint64_t>(c) * m.cycle_ms;
      cy["step"] = ex.step_of_cycle[c];
      json iv = json::array(), bad = json::array(), ov = json::array(), outv = json::array();
      for (std::size_t i = 0; i < inputs.size(); ++i) {
        iv.push_back(input_json(inputs.tags()[i], in.tags[i]));
        if (in.tags[i].bad_quality) bad.push_back(inputs.tags()[i].name);
      }
      for (std::size_t i = 0; i < obs.size(); ++i) ov.push_back(observable_json(obs[i], snap[i]));
      for (const auto& name : output_names) {
        auto v = rt.output(name);
        outv.push_back(v ? json(*v) : json(nullptr));
      }
      json cmds = json::array();
      for (const auto& cmd : in.commands) cmds.push_back(command_json(cmd));
      cy["inputs"] = iv;
      cy["bad_quality"] = bad;
      cy["commands"] = cmds;
      cy["commands_refused"] = rt.commands_refused();
      cy["observables"] = ov;
      cy["outputs"] = outv;
      trace_cycles.push_back(std::move(cy));
    }

    while (next_check < ex.checks.size() && ex.checks[next_check].cycle == c) {
      const auto& chk = ex.checks[next_check];
      for (const auto& x : *chk.expect) {
        ++checked;
        std::string actual;
        bool ok = false;
        if (x.target.kind == formats::ExpectTarget::Kind::OutputTag) {
          auto v = rt.output(x.target.output_tag);
          actual = v ? (*v ? "true" : "false") : "unknown";
          ok = v && static_cast<int>(*v) == x.expected;
        } else {
          auto it = obs_index.find(x.target.observable.key);
          if (it == obs_index.end()) {
            actual = "unknown";
          } else {
            int v = snap[it->second];
            if (x.type == model::FieldType::Bool) v = v != 0;
            actual = formats::expectation_value_text(x.type, v);
            ok = v == x.expected;
          }
        }
        if (!ok) {
          ++failed;
          std::cout << "FAIL steps[" << chk.step << "] (cycle " << cycle_no << ", t = "
                    << c * m.cycle_ms << " ms): " << x.key << " expected "
                    << formats::expectation_value_text(x.type, x.expected) << ", actual " << actual
                    << "\n";
        }
      }
      ++next_check;
    }
  }

  print_timing(std::cout, timing, m.cycle_ms);
  std::string sig = formats::signature(m);
  std::cout << "matrix " << m.name << " signature " << sig << "\n";
  std::cout << "scenario " << scenario_file << ": " << sc.steps.size() << " steps, "
            << ex.cycles.size() << " cycles, " << checked << " expectations, " << failed
            << " failed";
  if (refused_total)
    std::cout << ", " << refused_total << (refused_total == 1 ? " command" : " commands") << " refused";
  std::cout << "\n" << (failed ? "FAIL" : "PASS") << "\n";

  if (!trace_file.empty()) {
    json trace;
    trace["format"] = "cemv-trace/1";
    trace["matrix"] = m.name;
    trace["signature"] = sig;
    trace["cycle_ms"] = m.cycle_ms;
    json in_names = json::array(), obs_keys = json::array();
    for (const auto& t : inputs.tags()) in_names.push_back(t.name);
    for (const auto& o : obs) obs_keys.push_back(o.key);
    trace["inputs"] = in_names;
    trace["observables"] = obs_keys;
    trace["outputs"] = output_names;
    // One line per cycle keeps long traces readable and diffable; the header
    // fields come first in key order.
    std::ofstream f(trace_file, std::ios::binary);
    f << "{\n";
    for (const auto& [k, v] : trace.items()) f << " " << json(k).dump() << ": " << v.dump() << ",\n";
    f << " \"cycles\": [\n";
    for (std::size_t i = 0; i < trace_cycles.size(); ++i)
      f << "  " << trace_cycles[i].dump() << (i + 1 < trace_cycles.size() ? ",\n" : "\n");
    f << " ]\n}\n";
    if (!f) {
      std::cerr << "error: " << trace_file << ": cannot write the trace\n";
      return 2;
    }
  }
  return failed ? 1 : 0;
}

}  // namespace

void add_simulate_commands(CLI::App& app, Context& ctx) {
  auto* cmd = app.add_subcommand(
      "simulate", "Run a cemv-scenario/1 file on the reference runtime and check its expectations");
  static std::string matrix_file, scenario_file, trace_file;
  cmd->add_option("MATRIX", matrix_file, "cemv-matrix/1 file")->required();
  cmd->add_option("SCENARIO", scenario_file, "cemv-scenario/1 file")->required();
  cmd->add_option("--trace", trace_file, "write the per-cycle trace (inputs, every observable) as JSON");
  cmd->callback([&ctx]() { ctx.exit_code = run_simulate(matrix_file, scenario_file, trace_file); });
}

}  // namespace cemv::cli
