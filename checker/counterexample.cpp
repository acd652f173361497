#include "checker/counterexample.hpp"

#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "formats/scenario.hpp"
#include "model/text.hpp"

namespace cemv::checker {

namespace {

using nlohmann::ordered_json;

// A float written through its shortest round-trip text, so the scenario says
// 90 and not 90.0000000001, and reads back as the same single-precision value.
ordered_json number(float v) { return ordered_json::parse(model::float_text(v)); }

ordered_json tag_json(const model::InputTag& tag, const model::TagValue& v, bool quality_changed) {
  ordered_json value = tag.kind == model::TagKind::Bool ? ordered_json(v.value != 0.0f) : number(v.value);
  if (!v.bad_quality && !quality_changed) return value;
  ordered_json o;
  o["value"] = value;
  o["quality"] = v.bad_quality ? "bad" : "good";
  return o;
}

// The inputs that differ from `before`, in InputTable order.
ordered_json changed_inputs(const model::InputTable& table, const std::vector<model::TagValue>& before,
                            const std::vector<model::TagValue>& now) {
  ordered_json out = ordered_json::object();
  for (std::size_t i = 0; i < table.size(); ++i) {
    bool value_changed = before[i].value != now[i].value;
    bool quality_changed = before[i].bad_quality != now[i].bad_quality;
    if (value_changed || quality_changed) out[table.tags()[i].name] = tag_json(table.tags()[i], now[i], quality_changed);
  }
  return out;
}

ordered_json command_json(const model::Matrix& m, const model::Command& c) {
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
      model::InputTable table(m);
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

bool same_tags(const std::vector<model::TagValue>& a, const std::vector<model::TagValue>& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].value != b[i].value || a[i].bad_quality != b[i].bad_quality) return false;
  return true;
}

}  // namespace

std::string scenario_json(const model::Matrix& m, const std::vector<model::CycleInput>& inputs,
                          const std::string& description,
                          const std::vector<ScenarioExpectation>& expect) {
  model::InputTable table(m);
  std::vector<model::TagValue> current = model::default_cycle_input(m).tags;
  ordered_json doc;
  doc["format"] = formats::kScenarioFormat;
  doc["description"] = description;
  ordered_json steps = ordered_json::array();
  // A new step starts where inputs change or commands are issued (a step's
  // commands go to its first cycle only); the last step carries the
  // expectations, checked after the last cycle.
  for (std::size_t k = 0; k < inputs.size();) {
    const model::CycleInput& in = inputs[k];
    ordered_json step;
    ordered_json changed = changed_inputs(table, current, in.tags);
    if (!changed.empty()) step["inputs"] = changed;
    if (!in.commands.empty()) {
      ordered_json cmds = ordered_json::array();
      for (const auto& c : in.commands) cmds.push_back(command_json(m, c));
      step["commands"] = cmds;
    }
    current = in.tags;
    std::size_t n = 1;
    while (k + n < inputs.size() && inputs[k + n].commands.empty() &&
           same_tags(inputs[k + n].tags, current))
      ++n;
    step["cycles"] = n;
    k += n;
    if (k == inputs.size()) {
      ordered_json e = ordered_json::object();
      for (const auto& x : expect) {
        switch (x.type) {
          case model::FieldType::Bool: e[x.key] = x.value != 0; break;
          case model::FieldType::Int: e[x.key] = x.value; break;
          case model::FieldType::Voting: e[x.key] = model::to_string(static_cast<model::Voting>(x.value)); break;
        }
      }
      step["expect"] = e;
    }
    steps.push_back(step);
  }
  doc["steps"] = steps;
  return doc.dump(1) + "\n";
}

std::string command_text(const model::Matrix& m, const model::Command& c) { return command_json(m, c).dump(); }

void write_text_atomically(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      throw std::runtime_error(path.string() + ": cannot write the file");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw std::runtime_error(path.string() + ": cannot write the file: " + ec.message());
}

}  // namespace cemv::checker
