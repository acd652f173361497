// The commands a property's `issued(...)` pattern can mean, as inputs of the
// encoding (properties/monitor_commands.hpp).
#include "properties/monitor_commands.hpp"

#include "model/vocabulary.hpp"

namespace cemv::properties::monitor_commands {

// Whether a command input of the encoding matches a pattern (ast.hpp
// CommandPattern: empty fields match anything, `on` only for soft bypass).
bool matches(const encoder::CommandInput& ci, const CommandPattern& p) {
  if (ci.op != p.op) return false;
  if (p.cause && ci.cause != *p.cause) return false;
  if (p.effect && ci.effect != *p.effect) return false;
  if (p.tag && ci.tag != *p.tag) return false;
  if (p.group && ci.group != *p.group) return false;
  bool soft_bypass = p.op == model::CommandOp::SoftBypassCause ||
                     p.op == model::CommandOp::SoftBypassTag ||
                     p.op == model::CommandOp::SoftBypassEffect;
  if (soft_bypass && p.on && ci.on != *p.on) return false;
  if (p.tag_name && model::tag_key(ci.tag_name) != model::tag_key(*p.tag_name)) return false;
  return true;
}

// The concrete commands a pattern can match that name a target of the cone
// (or the target the pattern fixes): open fields range over the cone's
// causes / effects, tag positions 1-3, groups 1-15, both `on` variants and the
// input tags the cone reads.
std::vector<model::Command> candidate_commands(const encoder::Encoding& enc, const CommandPattern& p) {
  using Op = model::CommandOp;
  std::vector<int> causes, effects;
  for (const auto& n : enc.nodes) (n.kind == model::Node::Kind::Cause ? causes : effects).push_back(n.id);
  if (p.cause) causes = {*p.cause};
  if (p.effect) effects = {*p.effect};
  std::vector<bool> ons = p.on ? std::vector<bool>{*p.on} : std::vector<bool>{true, false};
  std::vector<model::Command> out;
  auto cmd = [&](int cause, int effect) {
    model::Command c;
    c.op = p.op;
    c.cause = cause;
    c.effect = effect;
    return c;
  };
  switch (p.op) {
    case Op::AckCause:
      for (int i : causes) out.push_back(cmd(i, 0));
      break;
    case Op::ResetEffect:
    case Op::OverrideEffect:
    case Op::StopOverride:
      for (int j : effects) out.push_back(cmd(0, j));
      break;
    case Op::SoftBypassCause:
    case Op::SoftBypassEffect:
      for (int id : p.op == Op::SoftBypassCause ? causes : effects)
        for (bool on : ons) {
          model::Command c = p.op == Op::SoftBypassCause ? cmd(id, 0) : cmd(0, id);
          c.on = on;
          out.push_back(c);
        }
      break;
    case Op::SoftBypassTag:
      for (int i : causes)
        for (int t = 1; t <= model::kMaxCauseTags; ++t)
          if (!p.tag || *p.tag == t)
            for (bool on : ons) {
              model::Command c = cmd(i, 0);
              c.tag = t;
              c.on = on;
              out.push_back(c);
            }
      break;
    case Op::ClearFirstOut:
      for (int g = 1; g <= model::kMaxFirstOutGroup; ++g)
        if (!p.group || *p.group == g) {
          model::Command c = cmd(0, 0);
          c.group = g;
          out.push_back(c);
        }
      break;
    case Op::ClearAlarms:
      // O.10: naming both clears both; the encoding has one input per target.
      if (!p.effect || p.cause)
        for (int i : causes) out.push_back(cmd(i, 0));
      if (!p.cause || p.effect)
        for (int j : effects) out.push_back(cmd(0, j));
      break;
    case Op::SimulateTag:
    case Op::StopSimulation:
      if (p.tag_name) {
        model::Command c = cmd(0, 0);
        c.tag_name = *p.tag_name;
        out.push_back(c);
      } else {
        // The tags the cone reads: a simulation of any other tag cannot act
        // on the cone, and a judged open pattern has every reader in it.
        for (std::size_t t = 0; t < enc.inputs.size(); ++t)
          if (t < enc.tag_value.size() && enc.tag_value[t]) {
            model::Command c = cmd(0, 0);
            c.tag_name = enc.inputs.tags()[t].name;
            out.push_back(c);
          }
      }
      break;
  }
  return out;
}

// A command the encoding has no input for changes nothing in the cone: the
// configuration always refuses it (semantics O.1-O.10), or it acts outside
// the cone. So it is issued exactly when a fresh, unconstrained input says so;
// the input joins Encoding::commands under the encoder's naming scheme, so the
// Evaluator and a counterexample's replay treat it like any other command.
void add_free_command(encoder::Encoding& enc, const model::Command& c) {
  encoder::TransitionSystem& ts = enc.ts;
  std::string name = std::string("cmd.") + model::to_string(c.op);
  if (c.op == model::CommandOp::ClearAlarms) name += c.cause ? "_cause" : "_effect";
  if (c.cause) name += "[" + std::to_string(c.cause) + "]";
  if (c.effect) name += "[" + std::to_string(c.effect) + "]";
  if (c.tag) name += "[" + std::to_string(c.tag) + "]";
  if (c.group) name += "[" + std::to_string(c.group) + "]";
  if (!c.tag_name.empty()) name += "[" + c.tag_name + "]";
  if (c.op == model::CommandOp::SoftBypassCause || c.op == model::CommandOp::SoftBypassTag ||
      c.op == model::CommandOp::SoftBypassEffect)
    name += c.on ? ".on" : ".off";
  if (ts.inputvar(name)) throw std::logic_error("monitor: command input " + name + " exists but does not match");
  encoder::CommandInput ci{c.op, c.cause, c.effect, c.tag, c.group, c.on, c.tag_name,
                           ts.make_inputvar(name, ts.ctx().bool_sort()), std::nullopt};
  // The value of a simulation that cannot act on the cone is irrelevant: a
  // Bool keeps the query free of needless floating point.
  if (c.op == model::CommandOp::SimulateTag) ci.value = ts.make_inputvar(name + ".value", ts.ctx().bool_sort());
  enc.commands.push_back(ci);
}

}  // namespace cemv::properties::monitor_commands
