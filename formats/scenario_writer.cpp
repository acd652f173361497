#include "formats/scenario_writer.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "formats/scenario.hpp"
#include "model/text.hpp"

namespace cemv::formats {

namespace {

using nlohmann::ordered_json;

// A float as its shortest round-trip text says it (90, not 90.0 or
// 90.0000000001), so that it reads back as the same single-precision value:
// an integer where the text is one, else the double the text denotes.
ordered_json number(float v) {
  const std::string text = model::float_text(v);
  if (text.find_first_not_of("-0123456789") == std::string::npos) {
    std::int64_t i = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), i);
    if (ec == std::errc() && end == text.data() + text.size()) return i;
  }
  char* end = nullptr;
  const double d = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(d))
    throw std::logic_error("scenario writer: no JSON number for " + text);
  return d;
}

bool same_tags(const std::vector<model::TagValue>& a, const std::vector<model::TagValue>& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].value != b[i].value || a[i].bad_quality != b[i].bad_quality) return false;
  return true;
}

ordered_json command_json(const model::InputTable& table, const model::Command& c) {
  using Op = model::CommandOp;
  ordered_json o;
  o["op"] = model::to_string(c.op);
  switch (c.op) {
    case Op::AckCause: o["cause"] = c.cause; break;
    case Op::ResetEffect:
    case Op::OverrideEffect:
    case Op::StopOverride: o["effect"] = c.effect; break;
    case Op::SoftBypassCause: o["cause"] = c.cause; o["on"] = c.on; break;
    case Op::SoftBypassTag: o["cause"] = c.cause; o["tag"] = c.tag; o["on"] = c.on; break;
    case Op::SoftBypassEffect: o["effect"] = c.effect; o["on"] = c.on; break;
    case Op::SimulateTag: {
      o["tag"] = c.tag_name;
      auto idx = table.find(c.tag_name);
      bool analog = idx && table.tags()[*idx].kind == model::TagKind::Analog;
      o["value"] = analog ? number(c.value) : ordered_json(c.value != 0.0f);
      break;
    }
    case Op::StopSimulation: if (!c.tag_name.empty()) o["tag"] = c.tag_name; break;
    case Op::ClearFirstOut: o["group"] = c.group; break;
    case Op::ClearAlarms:
      if (c.cause != 0) o["cause"] = c.cause;
      else o["effect"] = c.effect;
      break;
  }
  return o;
}

ordered_json value_json(const ExpectedValue& x) {
  switch (x.type) {
    case model::FieldType::Bool: return x.value != 0;
    case model::FieldType::Int: return x.value;
    case model::FieldType::Voting: return model::to_string(static_cast<model::Voting>(x.value));
  }
  return x.value;
}

// The inputs a step sets: those that differ from the step before (all of
// them when `all`), a value alone, or with its quality where the quality is
// bad or changes.
ordered_json inputs_json(const model::InputTable& table, const std::vector<model::TagValue>& before,
                         const std::vector<model::TagValue>& now, bool all, const std::set<std::size_t>& also) {
  ordered_json out = ordered_json::object();
  for (std::size_t i = 0; i < table.size(); ++i) {
    const bool value_changed = before[i].value != now[i].value;
    const bool quality_changed = before[i].bad_quality != now[i].bad_quality;
    if (!all && !also.count(i) && !value_changed && !quality_changed) continue;
    const auto& tag = table.tags()[i];
    ordered_json v = tag.kind == model::TagKind::Bool ? ordered_json(now[i].value != 0.0f) : number(now[i].value);
    if (now[i].bad_quality || quality_changed) {
      ordered_json o;
      o["value"] = v;
      o["quality"] = now[i].bad_quality ? "bad" : "good";
      v = o;
    }
    out[tag.name] = v;
  }
  return out;
}

}  // namespace

std::string scenario_text(const model::Matrix& m, const ScenarioRun& run) {
  const model::InputTable table(m);
  std::vector<model::TagValue> current = model::default_cycle_input(m).tags;
  ordered_json doc;
  doc["format"] = kScenarioFormat;
  if (!run.matrix.empty()) doc["matrix"] = run.matrix;
  if (run.description) doc["description"] = *run.description;
  ordered_json steps = ordered_json::array();
  const std::set<std::size_t> also(run.first_step_also_states.begin(), run.first_step_also_states.end()), none;
  std::size_t k = 0;
  for (const auto& s : run.steps) {
    if (s.cycles == 0 || k + s.cycles > run.cycles.size())
      throw std::logic_error("scenario writer: the steps do not cover the run's cycles");
    const model::CycleInput& in = run.cycles[k];
    for (std::size_t j = k + 1; j < k + s.cycles; ++j)
      if (!run.cycles[j].commands.empty() || !same_tags(run.cycles[j].tags, in.tags))
        throw std::logic_error("scenario writer: cycle " + std::to_string(j + 1) + " differs from its step's first");
    ordered_json step;
    if (s.description) step["description"] = *s.description;
    ordered_json changed =
        inputs_json(table, current, in.tags, k == 0 && run.first_step_states_every_input, k == 0 ? also : none);
    if (!changed.empty()) step["inputs"] = changed;
    if (!in.commands.empty()) {
      ordered_json cmds = ordered_json::array();
      for (const auto& c : in.commands) cmds.push_back(command_json(table, c));
      step["commands"] = cmds;
    }
    if (run.durations == Durations::Cycles) step["cycles"] = s.cycles;
    else step["ms"] = static_cast<std::uint64_t>(s.cycles) * m.cycle_ms;
    if (s.expect) {
      ordered_json e = ordered_json::object();
      for (const auto& x : *s.expect) e[x.key] = value_json(x);
      step["expect"] = e;
    }
    steps.push_back(step);
    current = in.tags;
    k += s.cycles;
  }
  if (k != run.cycles.size()) throw std::logic_error("scenario writer: the steps do not cover the run's cycles");
  doc["steps"] = steps;
  return doc.dump(1) + "\n";
}

std::vector<std::size_t> step_lengths(const std::vector<model::CycleInput>& cycles,
                                      const std::vector<std::size_t>& checkpoints) {
  const std::set<std::size_t> at(checkpoints.begin(), checkpoints.end());
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < cycles.size(); ++k) {
    const bool starts = k == 0 || at.count(k - 1) || !cycles[k].commands.empty() ||
                        !same_tags(cycles[k].tags, cycles[k - 1].tags);
    if (starts) out.push_back(0);
    ++out.back();
  }
  return out;
}

ScenarioRun checked_at_end(std::vector<model::CycleInput> cycles, std::string description,
                           std::vector<ExpectedValue> expect) {
  ScenarioRun run;
  run.description = std::move(description);
  for (std::size_t n : step_lengths(cycles, {})) run.steps.push_back({n, std::nullopt, std::nullopt});
  if (!run.steps.empty()) run.steps.back().expect = std::move(expect);
  run.cycles = std::move(cycles);
  return run;
}

std::string command_text(const model::Matrix& m, const model::Command& c) {
  return command_json(model::InputTable(m), c).dump();
}

}  // namespace cemv::formats
