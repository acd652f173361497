// cemv-scenario/1 commands (docs/scenario.md "Commands (10.7)"), each argument
// checked against the matrix.
#include "formats/scenario_reader.hpp"

#include <string>

#include "model/text.hpp"

namespace cemv::formats::scenario_detail {

using namespace cemv::model;

namespace {

// The "op" of a command: a known command name.
std::optional<CommandOp> read_op(ScenarioContext& cx, const json& j, const std::string& path) {
  if (!j.contains("op") || !j["op"].is_string()) {
    cx.error(join(path, "op"), "missing or not a string; a command names its \"op\"");
    return std::nullopt;
  }
  std::string name = j["op"].get<std::string>();
  auto op = command_op_from_string(name);
  if (!op) {
    std::vector<std::string> ops;
    for (int i = 0; i <= static_cast<int>(CommandOp::ClearAlarms); ++i)
      ops.push_back(to_string(static_cast<CommandOp>(i)));
    cx.error(join(path, "op"), "unknown command " + in_quotes(name) + did_you_mean(name, ops));
  }
  return op;
}

// The arguments of one command, each read into `cmd` with its own checks.
struct CommandArgs {
  ScenarioContext& p;
  const json& j;
  const std::string& path;
  const std::string& name;
  Command& cmd;

  const json* need(const char* key) {
    if (!j.contains(key)) {
      p.error(path, "command " + in_quotes(name) + " needs \"" + key + "\"");
      return nullptr;
    }
    return &j[key];
  }
  const Cause* cause() {
    const json* v = need("cause");
    if (!v) return nullptr;
    const Cause* c = p.cause_ref(*v, join(path, "cause"));
    if (c) cmd.cause = c->id;
    return c;
  }
  void effect() {
    const json* v = need("effect");
    if (!v) return;
    if (const Effect* e = p.effect_ref(*v, join(path, "effect"))) cmd.effect = e->id;
  }
  void on() {
    const json* v = need("on");
    if (!v) return;
    if (auto b = p.bool_field(*v, join(path, "on"))) cmd.on = *b;
  }
  // soft_bypass_tag (O.6): the position of an input tag of cause `c`, 1-3.
  void tag_index(const Cause* c) {
    const json* t = need("tag");
    if (!t) return;
    auto k = p.int_field(*t, join(path, "tag"));
    if (!k || !c) return;
    if (*k < 1 || *k > static_cast<std::int64_t>(c->tags.size()))
      p.error(join(path, "tag"), "cause " + std::to_string(c->id) + " has " + std::to_string(c->tags.size()) +
                                     " input tag(s); the tag index is 1-" + std::to_string(c->tags.size()));
    else
      cmd.tag = static_cast<int>(*k);
  }
  // simulate_tag (O.8): the tag, and a value of its kind.
  void simulated_tag_and_value() {
    const json* t = need("tag");
    const json* v = need("value");
    if (!t) return;
    std::string tag = p.string_field(*t, join(path, "tag"));
    if (tag.empty()) return;
    auto sim = p.simulatable_tag(tag, join(path, "tag"));
    if (!sim) return;
    cmd.tag_name = sim->name;
    if (v)
      if (auto x = p.tag_value(*v, sim->kind, sim->name, join(path, "value"))) cmd.value = *x;
  }
  // stop_simulation (O.8): one tag, or (without "tag") every simulation.
  void stopped_tag() {
    if (!j.contains("tag")) return;
    std::string tag = p.string_field(j["tag"], join(path, "tag"));
    if (!j["tag"].is_string()) return;
    if (auto sim = p.simulatable_tag(tag, join(path, "tag"))) cmd.tag_name = sim->name;
  }
  // clear_first_out (O.9): a first-out group.
  void group() {
    const json* g = need("group");
    if (!g) return;
    auto v = p.int_field(*g, join(path, "group"));
    if (v && (*v < 1 || *v > kMaxFirstOutGroup))
      p.error(join(path, "group"), "first-out groups are 1-" + std::to_string(kMaxFirstOutGroup));
    else if (v)
      cmd.group = static_cast<int>(*v);
  }
  // clear_alarms (O.10): exactly one of a cause and an effect.
  void cause_or_effect() {
    if (j.contains("cause") == j.contains("effect")) {
      p.error(path, "command 'clear_alarms' needs exactly one of \"cause\" and \"effect\"");
    } else if (j.contains("cause")) {
      if (const Cause* c = p.cause_ref(j["cause"], join(path, "cause"))) cmd.cause = c->id;
    } else {
      if (const Effect* e = p.effect_ref(j["effect"], join(path, "effect"))) cmd.effect = e->id;
    }
  }
};

}  // namespace

std::optional<Command> read_command(ScenarioContext& cx, const json& j, const std::string& path) {
  if (!j.is_object()) {
    cx.error(path, "a command is an object, not " + json_type_name(j));
    return std::nullopt;
  }
  auto op = read_op(cx, j, path);
  if (!op) return std::nullopt;
  const std::string name = j["op"].get<std::string>();
  Command cmd;
  cmd.op = *op;
  std::size_t before = cx.issues.size();
  CommandArgs args{cx, j, path, name, cmd};
  switch (*op) {
    case CommandOp::AckCause:
      cx.check_keys(j, path, {"op", "cause"});
      args.cause();
      break;
    case CommandOp::ResetEffect:
    case CommandOp::OverrideEffect:
    case CommandOp::StopOverride:
      cx.check_keys(j, path, {"op", "effect"});
      args.effect();
      break;
    case CommandOp::SoftBypassCause:
      cx.check_keys(j, path, {"op", "cause", "on"});
      args.cause();
      args.on();
      break;
    case CommandOp::SoftBypassTag:
      cx.check_keys(j, path, {"op", "cause", "tag", "on"});
      args.tag_index(args.cause());
      args.on();
      break;
    case CommandOp::SoftBypassEffect:
      cx.check_keys(j, path, {"op", "effect", "on"});
      args.effect();
      args.on();
      break;
    case CommandOp::SimulateTag:
      cx.check_keys(j, path, {"op", "tag", "value"});
      args.simulated_tag_and_value();
      break;
    case CommandOp::StopSimulation:
      cx.check_keys(j, path, {"op", "tag"});
      args.stopped_tag();
      break;
    case CommandOp::ClearFirstOut:
      cx.check_keys(j, path, {"op", "group"});
      args.group();
      break;
    case CommandOp::ClearAlarms:
      cx.check_keys(j, path, {"op", "cause", "effect"});
      args.cause_or_effect();
      break;
  }
  if (cx.issues.size() != before) return std::nullopt;
  return cmd;
}

}  // namespace cemv::formats::scenario_detail
