// The operator commands a matrix accepts that can change an output tag, as
// slots of the map (docs/plc.md "Map and relations", docs/semantics.md O.1-O.8).
#include <algorithm>
#include <cctype>

#include "plc_check/map.hpp"
#include "model/simulation.hpp"

namespace cemv::plc_check {

namespace {

bool processed(const model::Matrix& m, const model::Intersection& x) {
  const auto* c = m.find_cause(x.cause);
  const auto* e = m.find_effect(x.effect);
  return model::is_processed(x.type) && c && e && c->function != model::CauseFunction::Comment &&
         e->function != model::EffectFunction::Comment;
}

bool has_type(const model::Matrix& m, int effect, std::initializer_list<model::IntersectionType> types) {
  for (const auto* x : m.intersections_of_effect(effect))
    if (processed(m, *x) && std::find(types.begin(), types.end(), x->type) != types.end()) return true;
  return false;
}

std::string upper(std::string s) {
  for (auto& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return s;
}

CommandSlot slot(model::CommandOp op, std::string target, std::string default_name) {
  CommandSlot s;
  s.command.op = op;
  s.label = std::string(model::to_string(op)) + " " + target;
  s.default_name = upper(std::move(default_name));
  return s;
}

void cause_slots(const model::Cause& c, std::vector<CommandSlot>& out) {
  const std::string target = "cause " + std::to_string(c.id) + " " + c.name;
  const bool latch = !c.auto_ack && (c.time.mode == model::TimeMode::None || c.time.mode == model::TimeMode::OnDelay);
  if (latch) {
    out.push_back(slot(model::CommandOp::AckCause, target, c.name + "_ACK"));
    out.back().command.cause = c.id;
  }
  if (c.soft_bypass.allowed)
    for (bool on : {true, false}) {
      out.push_back(slot(model::CommandOp::SoftBypassCause, target + (on ? " on" : " off"),
                         c.name + (on ? "_SOFT_BYPASS_ON" : "_SOFT_BYPASS_OFF")));
      out.back().command.cause = c.id;
      out.back().command.on = on;
    }
  for (std::size_t t = 0; t < c.tags.size(); ++t) {
    if (!c.tags[t].soft_bypass_allowed || model::parse_internal_ref(c.tags[t].name)) continue;
    for (bool on : {true, false}) {
      out.push_back(slot(model::CommandOp::SoftBypassTag,
                         target + " tag " + std::to_string(t + 1) + " " + c.tags[t].name + (on ? " on" : " off"),
                         c.name + "_TAG" + std::to_string(t + 1) + (on ? "_SOFT_BYPASS_ON" : "_SOFT_BYPASS_OFF")));
      out.back().command.cause = c.id;
      out.back().command.tag = static_cast<int>(t + 1);
      out.back().command.on = on;
    }
  }
}

void effect_slots(const model::Matrix& m, const model::Effect& e, std::vector<CommandSlot>& out) {
  using T = model::IntersectionType;
  const std::string target = "effect " + std::to_string(e.id) + " " + e.name;
  auto add = [&](model::CommandOp op, const std::string& suffix, std::optional<bool> on = std::nullopt) {
    out.push_back(slot(op, target + (on ? (*on ? " on" : " off") : ""), e.name + suffix));
    out.back().command.effect = e.id;
    if (on) out.back().command.on = *on;
  };
  if (!e.reset_tag && has_type(m, e.id, {T::S, T::R})) add(model::CommandOp::ResetEffect, "_RESET");
  if (!e.reset_tag && has_type(m, e.id, {T::V, T::R})) {
    add(model::CommandOp::OverrideEffect, "_OVERRIDE");
    add(model::CommandOp::StopOverride, "_STOP_OVERRIDE");
  }
  if (e.soft_bypass_allowed) {
    add(model::CommandOp::SoftBypassEffect, "_SOFT_BYPASS_ON", true);
    add(model::CommandOp::SoftBypassEffect, "_SOFT_BYPASS_OFF", false);
  }
}

}  // namespace

std::vector<CommandSlot> command_slots(const model::Matrix& m) {
  std::vector<CommandSlot> out;
  for (const auto& c : m.causes)
    if (c.function != model::CauseFunction::Comment) cause_slots(c, out);
  for (const auto& e : m.effects)
    if (e.function != model::EffectFunction::Comment) effect_slots(m, e, out);
  // Simulation: every simulatable tag the operator is permitted to simulate (O.8).
  const model::CommandOrder order(m);
  for (const auto& tag : order.simulatable_tags()) {
    if (!model::simulation_permitted(m, tag)) continue;
    out.push_back(slot(model::CommandOp::SimulateTag, "tag " + tag, tag + "_SIMULATE"));
    out.back().command.tag_name = tag;
  }
  return out;
}

}  // namespace cemv::plc_check
