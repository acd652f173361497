#include "testgen/phrases.hpp"

#include <cstdio>

#include "model/text.hpp"

namespace cemv::testgen::detail {

namespace {

std::string cause_label(const model::Matrix& m, int id) {
  const model::Cause* c = m.find_cause(id);
  return "cause " + std::to_string(id) + (c ? " " + c->name : "");
}
std::string effect_label(const model::Matrix& m, int id) {
  const model::Effect* e = m.find_effect(id);
  return "effect " + std::to_string(id) + (e ? " " + e->name : "");
}

// The first cause reading `tag` as an analog input: its limit gives the
// engineer a reference ("limit 90, high").
const model::Cause* analog_reader(const model::Matrix& m, const std::string& tag) {
  for (const auto& c : m.causes)
    if (c.input == model::InputKind::Analog && c.analog)
      for (const auto& t : c.tags)
        if (model::tag_key(t.name) == model::tag_key(tag)) return &c;
  return nullptr;
}

std::string role_text(const model::Matrix& m, const model::InputTag& tag) {
  if (tag.roles.empty()) return "";
  switch (tag.roles.front()) {
    case model::TagRole::CauseBypass: return " (bypass switch)";
    case model::TagRole::CauseInhibit: return " (inhibit switch)";
    case model::TagRole::EffectBypass: return " (effect bypass switch)";
    case model::TagRole::EffectReset: return " (reset / override button)";
    case model::TagRole::ProcessValue: return " (BPCS process value)";
    case model::TagRole::Mask: return " (mask switch)";
    case model::TagRole::SecureWriteEnable: return " (secure write enable)";
    case model::TagRole::GroupDeactivationEnable: return " (group deactivation enable)";
    case model::TagRole::GroupDeactivationSet: return " (group deactivation set)";
    case model::TagRole::CauseInput: break;
  }
  for (const auto& c : m.causes)
    for (const auto& t : c.tags)
      if (model::tag_key(t.name) == model::tag_key(tag.name))
        return std::string(" (input of ") + cause_label(m, c.id) + ", " + (t.ett ? "ETT" : "DTT") + ")";
  return "";
}

}  // namespace

std::string phrase_input(const model::Matrix& m, const model::InputTag& tag, const model::TagValue& before,
                         const model::TagValue& now) {
  std::string s;
  if (now.value != before.value) {
    if (tag.kind == model::TagKind::Bool) {
      s = "Set " + tag.name + " to " + (now.value != 0.0f ? "1" : "0") + role_text(m, tag);
    } else {
      const model::Cause* c = analog_reader(m, tag.name);
      std::string unit = c && !c->analog->unit.empty() ? " " + c->analog->unit : "";
      s = "Set " + tag.name + " to " + model::float_text(now.value) + unit;
      if (c)
        s += std::string(" (limit ") + model::float_text(c->analog->limit) + ", " +
             (c->analog->limit_type == model::LimitType::High ? "high" : "low") + ")";
    }
  }
  if (now.bad_quality != before.bad_quality) {
    std::string q = now.bad_quality ? "make the signal of " + tag.name + " bad quality (channel fault)"
                                    : "restore good quality of " + tag.name;
    s = s.empty() ? std::string(1, static_cast<char>(std::toupper(static_cast<unsigned char>(q[0])))) + q.substr(1)
                  : s + ", and " + q;
  } else if (now.bad_quality && now.value != before.value) {
    s += " (still bad quality)";
  }
  return s;
}

std::string phrase_command(const model::Matrix& m, const model::Command& c) {
  using Op = model::CommandOp;
  const std::string onoff = c.on ? "on" : "off";
  switch (c.op) {
    case Op::AckCause: return "Acknowledge " + cause_label(m, c.cause);
    case Op::ResetEffect: return "Press reset for " + effect_label(m, c.effect);
    case Op::OverrideEffect: return "Press override for " + effect_label(m, c.effect);
    case Op::StopOverride: return "Stop the override of " + effect_label(m, c.effect);
    case Op::SoftBypassCause: return "Switch the soft bypass of " + cause_label(m, c.cause) + " " + onoff;
    case Op::SoftBypassTag: {
      const model::Cause* cs = m.find_cause(c.cause);
      std::string name = cs && c.tag >= 1 && c.tag <= static_cast<int>(cs->tags.size())
                             ? " (" + cs->tags[static_cast<std::size_t>(c.tag - 1)].name + ")" : "";
      return "Switch the soft bypass of tag " + std::to_string(c.tag) + name + " of " + cause_label(m, c.cause) + " " + onoff;
    }
    case Op::SoftBypassEffect: return "Switch the soft bypass of " + effect_label(m, c.effect) + " " + onoff;
    case Op::SimulateTag: return "Simulate " + c.tag_name + " = " + model::float_text(c.value);
    case Op::StopSimulation: return c.tag_name.empty() ? "Stop every simulation" : "Stop the simulation of " + c.tag_name;
    case Op::ClearFirstOut: return "Clear the first-out display of group " + std::to_string(c.group);
    case Op::ClearAlarms:
      return "Clear the alarms of " + (c.cause ? cause_label(m, c.cause) : effect_label(m, c.effect));
  }
  return "";
}

std::string phrase_duration(std::uint64_t ms) {
  char buf[64];
  if (ms < 1000) std::snprintf(buf, sizeof buf, "Wait %llu ms", static_cast<unsigned long long>(ms));
  else if (ms < 120000) std::snprintf(buf, sizeof buf, "Wait %.1f s", static_cast<double>(ms) / 1000.0);
  else if (ms < 7200000) std::snprintf(buf, sizeof buf, "Wait %.1f min", static_cast<double>(ms) / 60000.0);
  else std::snprintf(buf, sizeof buf, "Wait %.2f h", static_cast<double>(ms) / 3600000.0);
  return buf;
}

std::string phrase_observation(const model::Matrix& m, const model::Observable& o, int value) {
  if (o.field == "tag") {
    const model::Effect* e = m.find_effect(o.id);
    std::string name = e ? e->tags[static_cast<std::size_t>(o.tag - 1)].name : o.key;
    return name + " = " + std::to_string(value);
  }
  std::string who = o.kind == model::Node::Kind::Cause ? cause_label(m, o.id) : effect_label(m, o.id);
  std::string field = o.field;
  for (auto& ch : field)
    if (ch == '_') ch = ' ';
  std::string v = o.type == model::FieldType::Bool    ? (value ? "yes" : "no")
                  : o.type == model::FieldType::Voting ? model::to_string(static_cast<model::Voting>(value))
                                                       : std::to_string(value);
  return who + " " + field + ": " + v;
}

}  // namespace cemv::testgen::detail
