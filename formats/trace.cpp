#include "formats/trace.hpp"


#include "model/text.hpp"

namespace cemv::formats {

namespace {

using nlohmann::json;

json observable_json(const model::Observable& o, int v) {
  switch (o.type) {
    case model::FieldType::Bool: return json(v != 0);
    case model::FieldType::Int: return json(v);
    case model::FieldType::Voting: return json(model::to_string(static_cast<model::Voting>(v)));
  }
  return json(v);
}

// Through the shortest float text, so the trace shows 0.1 and not 0.100000001.
double shortest_double(float v) { return std::stod(model::float_text(v)); }

json input_json(const model::InputTag& t, const model::TagValue& v) {
  if (t.kind == model::TagKind::Bool) return json(v.value != 0.0f);
  return json(shortest_double(v.value));
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
      j["value"] = shortest_double(c.value);
      break;
    case model::CommandOp::StopSimulation:
      if (!c.tag_name.empty()) j["tag"] = c.tag_name;
      break;
    default: break;
  }
  return j;
}

}  // namespace

TraceWriter::TraceWriter(const model::Matrix& m, const model::InputTable& inputs,
                         const std::vector<model::Observable>& observables, std::vector<std::string> outputs,
                         const std::string& signature, Sink sink, Options options)
    : m_(m), inputs_(inputs), observables_(observables), outputs_(std::move(outputs)), sink_(std::move(sink)),
      options_(options) {
  json trace;
  if (options_.changes_only) trace["changes_only"] = true;
  trace["format"] = kTraceFormat;
  trace["matrix"] = m_.name;
  trace["signature"] = signature;
  trace["cycle_ms"] = m_.cycle_ms;
  json in_names = json::array(), obs_keys = json::array();
  for (const auto& t : inputs_.tags()) in_names.push_back(t.name);
  for (const auto& o : observables_) obs_keys.push_back(o.key);
  trace["inputs"] = in_names;
  trace["observables"] = obs_keys;
  trace["outputs"] = outputs_;
  // One line per cycle keeps long traces readable and diffable; the header
  // fields come first in key order.
  std::string header = "{\n";
  for (const auto& [k, v] : trace.items()) header += " " + json(k).dump() + ": " + v.dump() + ",\n";
  header += " \"cycles\": [\n";
  sink_(header);
}

void TraceWriter::emit(const json& cycle) {
  sink_((written_ > 0 ? ",\n  " : "  ") + cycle.dump());
  ++written_;
}

void TraceWriter::add_cycle(std::size_t cycle, std::size_t step, const model::CycleInput& in,
                            int commands_refused, const std::vector<int>& snapshot,
                            const std::vector<std::optional<bool>>& outputs) {
  json row;
  json iv = json::array(), bad = json::array(), ov = json::array(), outv = json::array();
  for (std::size_t i = 0; i < inputs_.size(); ++i) {
    iv.push_back(input_json(inputs_.tags()[i], in.tags[i]));
    if (in.tags[i].bad_quality) bad.push_back(inputs_.tags()[i].name);
  }
  for (std::size_t i = 0; i < observables_.size(); ++i) ov.push_back(observable_json(observables_[i], snapshot[i]));
  for (const auto& v : outputs) outv.push_back(v ? json(*v) : json(nullptr));
  json cmds = json::array();
  for (const auto& cmd : in.commands) cmds.push_back(command_json(cmd));
  row["inputs"] = iv;
  row["bad_quality"] = bad;
  row["commands"] = cmds;
  row["commands_refused"] = commands_refused;
  row["observables"] = ov;
  row["outputs"] = outv;
  json cy = row;
  cy["cycle"] = static_cast<std::uint64_t>(cycle + 1);
  cy["t_ms"] = static_cast<std::uint64_t>(cycle) * m_.cycle_ms;
  cy["step"] = step;
  if (!options_.changes_only) {
    emit(cy);
    return;
  }
  if (written_ == 0 || row != previous_row_ || !cmds.empty()) {
    emit(cy);
    held_.reset();
  } else {
    held_ = std::move(cy);
  }
  previous_row_ = std::move(row);
}

void TraceWriter::finish() {
  if (finished_) return;
  finished_ = true;
  if (held_) emit(*held_);
  held_.reset();
  sink_(written_ > 0 ? "\n ]\n}\n" : " ]\n}\n");
}

}  // namespace cemv::formats
