#include "model/vocabulary.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace cemv::model {

std::string tag_key(std::string_view name) {
  std::string key(name);
  for (auto& c : key) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return key;
}

namespace {
// Reads "[n]" at s[pos..]; advances pos. Accepts 1-3 decimal digits, no sign.
std::optional<int> bracketed_number(std::string_view s, std::size_t& pos) {
  if (pos >= s.size() || s[pos] != '[') return std::nullopt;
  std::size_t close = s.find(']', pos);
  if (close == std::string_view::npos) return std::nullopt;
  std::string_view digits = s.substr(pos + 1, close - pos - 1);
  if (digits.empty() || digits.size() > 3) return std::nullopt;
  for (char c : digits)
    if (c < '0' || c > '9') return std::nullopt;
  int v = 0;
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (ec != std::errc{} || end != digits.data() + digits.size()) return std::nullopt;
  pos = close + 1;
  return v;
}
}  // namespace

// 6.1.4: internal references are the exception to case-insensitivity, so the
// keywords must be spelt exactly "Cause" and "Effect".
std::optional<InternalRef> parse_internal_ref(std::string_view name) {
  InternalRef ref;
  std::size_t pos = 0;
  if (name.starts_with("Cause[")) {
    ref.kind = InternalRef::Kind::Cause;
    pos = 5;
  } else if (name.starts_with("Effect[")) {
    ref.kind = InternalRef::Kind::Effect;
    pos = 6;
  } else {
    return std::nullopt;
  }
  auto id = bracketed_number(name, pos);
  if (!id) return std::nullopt;
  ref.id = *id;
  if (pos == name.size()) return ref;
  if (ref.kind != InternalRef::Kind::Effect) return std::nullopt;
  auto tag = bracketed_number(name, pos);
  if (!tag || pos != name.size()) return std::nullopt;
  ref.kind = InternalRef::Kind::EffectTag;
  ref.tag = *tag;
  return ref;
}

InputTable::InputTable(const Matrix& m) {
  auto add = [&](const std::optional<std::string>& name, TagKind kind, TagRole role) {
    if (!name || name->empty() || parse_internal_ref(*name)) return;
    std::string key = tag_key(*name);
    auto it = std::find_if(by_key_.begin(), by_key_.end(),
                           [&](const auto& p) { return p.first == key; });
    if (it != by_key_.end()) {
      auto& roles = tags_[it->second].roles;
      if (std::find(roles.begin(), roles.end(), role) == roles.end()) roles.push_back(role);
      return;
    }
    by_key_.emplace_back(key, tags_.size());
    tags_.push_back(InputTag{*name, kind, {role}});
  };
  if (m.secure_write) add(m.secure_write->enable_tag, TagKind::Bool, TagRole::SecureWriteEnable);
  if (m.group_deactivation) {
    add(m.group_deactivation->enable_tag, TagKind::Bool, TagRole::GroupDeactivationEnable);
    add(m.group_deactivation->set_tag, TagKind::Bool, TagRole::GroupDeactivationSet);
  }
  for (const auto& c : m.causes) {
    if (c.function == CauseFunction::Comment) continue;
    for (const auto& t : c.tags)
      add(t.name, c.input == InputKind::Analog ? TagKind::Analog : TagKind::Bool,
          TagRole::CauseInput);
    add(c.bypass_tag, TagKind::Bool, TagRole::CauseBypass);
    add(c.inhibit_tag, TagKind::Bool, TagRole::CauseInhibit);
  }
  for (const auto& e : m.effects) {
    if (e.function == EffectFunction::Comment) continue;
    add(e.bypass_tag, TagKind::Bool, TagRole::EffectBypass);
    add(e.reset_tag, TagKind::Bool, TagRole::EffectReset);
    if (e.process_data) {
      add(e.process_data->tag, TagKind::Bool, TagRole::ProcessValue);
      add(e.process_data->mask_tag, TagKind::Bool, TagRole::Mask);
    }
  }
  std::sort(by_key_.begin(), by_key_.end());
}

std::optional<std::size_t> InputTable::find(std::string_view name) const {
  std::string key = tag_key(name);
  auto it = std::lower_bound(by_key_.begin(), by_key_.end(), key,
                             [](const auto& p, const std::string& k) { return p.first < k; });
  if (it == by_key_.end() || it->first != key) return std::nullopt;
  return it->second;
}

namespace {
constexpr std::pair<CommandOp, const char*> kOps[] = {
    {CommandOp::AckCause, "ack_cause"},
    {CommandOp::ResetEffect, "reset_effect"},
    {CommandOp::OverrideEffect, "override_effect"},
    {CommandOp::StopOverride, "stop_override"},
    {CommandOp::SoftBypassCause, "soft_bypass_cause"},
    {CommandOp::SoftBypassTag, "soft_bypass_tag"},
    {CommandOp::SoftBypassEffect, "soft_bypass_effect"},
    {CommandOp::SimulateTag, "simulate_tag"},
    {CommandOp::StopSimulation, "stop_simulation"},
    {CommandOp::ClearFirstOut, "clear_first_out"},
    {CommandOp::ClearAlarms, "clear_alarms"},
};
constexpr std::pair<Voting, const char*> kVotings[] = {
    {Voting::OneOoOne, "1oo1"},   {Voting::OneOoTwo, "1oo2"},   {Voting::TwoOoTwo, "2oo2"},
    {Voting::OneOoThree, "1oo3"}, {Voting::TwoOoThree, "2oo3"}, {Voting::ThreeOoThree, "3oo3"},
    {Voting::Bypass, "bypass"},
};
}  // namespace

const char* to_string(CommandOp op) {
  for (auto [o, n] : kOps)
    if (o == op) return n;
  return "?";
}

std::optional<CommandOp> command_op_from_string(std::string_view s) {
  for (auto [o, n] : kOps)
    if (s == n) return o;
  return std::nullopt;
}

const char* to_string(Voting v) {
  for (auto [o, n] : kVotings)
    if (o == v) return n;
  return "?";
}

std::optional<Voting> voting_from_string(std::string_view s) {
  for (auto [o, n] : kVotings)
    if (s == n) return o;
  return std::nullopt;
}

const std::vector<FieldInfo>& cause_fields() {
  static const std::vector<FieldInfo> fields = {
      {"active", FieldType::Bool},          {"trip_requested", FieldType::Bool},
      {"tripped_tags", FieldType::Int},     {"voting", FieldType::Voting},
      {"degraded", FieldType::Bool},        {"bypassed", FieldType::Bool},
      {"soft_bypassed", FieldType::Bool},   {"inhibited", FieldType::Bool},
      {"ack_required", FieldType::Bool},    {"first_out", FieldType::Bool},
      {"hysteresis_active", FieldType::Bool}, {"delta_alarm", FieldType::Bool},
      {"prewarning", FieldType::Bool},      {"timer_running", FieldType::Bool},
      {"bypass_timeout", FieldType::Bool},  {"bypass_prealarm", FieldType::Bool},
  };
  return fields;
}

const std::vector<FieldInfo>& effect_fields() {
  static const std::vector<FieldInfo> fields = {
      {"active", FieldType::Bool},
      {"latched", FieldType::Bool},
      {"ok_to_reset", FieldType::Bool},
      {"override_active", FieldType::Bool},
      {"override_failed_timeout", FieldType::Bool},
      {"override_failed_cause", FieldType::Bool},
      {"override_prealarm", FieldType::Bool},
      {"bypassed", FieldType::Bool},
      {"soft_bypassed", FieldType::Bool},
      {"masked", FieldType::Bool},
      {"pass_through_active", FieldType::Bool},
      {"output_delay_running", FieldType::Bool},
  };
  return fields;
}

std::string observable_key(const Node& n, std::string_view field, int tag) {
  std::string key = to_string(n) + "." + std::string(field);
  if (tag > 0) key += "[" + std::to_string(tag) + "]";
  return key;
}

std::vector<Observable> observables(const Matrix& m) {
  std::vector<Observable> out;
  for (const auto& c : m.causes) {
    if (c.function == CauseFunction::Comment) continue;
    const Node n{Node::Kind::Cause, c.id};
    for (const auto& f : cause_fields())
      out.push_back({observable_key(n, f.name), f.type, n.kind, c.id, f.name, 0});
  }
  for (const auto& e : m.effects) {
    if (e.function == EffectFunction::Comment) continue;
    const Node n{Node::Kind::Effect, e.id};
    for (const auto& f : effect_fields())
      out.push_back({observable_key(n, f.name), f.type, n.kind, e.id, f.name, 0});
    for (int k = 1; k <= static_cast<int>(e.tags.size()); ++k)
      out.push_back({observable_key(n, "tag", k), FieldType::Bool, n.kind, e.id, "tag", k});
  }
  return out;
}

// ---- The fixed command order ------------------------------------------------

CommandOrder::Key CommandOrder::key_of(const Command& c) {
  using Op = CommandOp;
  const int op = static_cast<int>(c.op);
  switch (c.op) {
    case Op::AckCause: return {op, c.cause, 0, 0, 0, true, ""};
    case Op::ResetEffect:
    case Op::OverrideEffect:
    case Op::StopOverride: return {op, 0, c.effect, 0, 0, true, ""};
    case Op::SoftBypassCause: return {op, c.cause, 0, 0, 0, c.on, ""};
    case Op::SoftBypassTag: return {op, c.cause, 0, c.tag, 0, c.on, ""};
    case Op::SoftBypassEffect: return {op, 0, c.effect, 0, 0, c.on, ""};
    case Op::SimulateTag:
    case Op::StopSimulation: return {op, 0, 0, 0, 0, true, tag_key(c.tag_name)};
    case Op::ClearFirstOut: return {op, 0, 0, 0, c.group, true, ""};
    case Op::ClearAlarms: return {op, c.cause, c.effect, 0, 0, true, ""};
  }
  return {op, c.cause, c.effect, c.tag, c.group, c.on, tag_key(c.tag_name)};
}

void CommandOrder::add(const Command& c) { rank_.emplace(key_of(c), rank_.size()); }

namespace {

Command command_of(CommandOp op) {
  Command c;
  c.op = op;
  return c;
}

}  // namespace

CommandOrder::CommandOrder(const Matrix& m) {
  std::vector<const Cause*> causes;
  std::vector<const Effect*> effects;
  for (const auto& c : m.causes)
    if (c.function != CauseFunction::Comment) causes.push_back(&c);
  for (const auto& e : m.effects)
    if (e.function != EffectFunction::Comment) effects.push_back(&e);
  add_simulation(m, effects);
  add_soft_bypasses(causes, effects);
  add_alarms_and_acks(causes, effects);
  add_resets_and_overrides(effects);
}

// O.8: cause input tags (InputTable order), then output tags; each simulated,
// then each simulation stopped, then every simulation stopped.
void CommandOrder::add_simulation(const Matrix& m, const std::vector<const Effect*>& effects) {
  std::vector<std::string> keys;
  auto simulatable = [&](const std::string& name) {
    std::string key = tag_key(name);
    if (std::find(keys.begin(), keys.end(), key) != keys.end()) return;
    keys.push_back(key);
    simulatable_.push_back(name);
  };
  const InputTable table(m);
  for (const auto& t : table.tags())
    if (std::find(t.roles.begin(), t.roles.end(), TagRole::CauseInput) != t.roles.end())
      simulatable(t.name);
  for (const auto* e : effects)
    for (const auto& t : e->tags) simulatable(t.name);
  for (CommandOp op : {CommandOp::SimulateTag, CommandOp::StopSimulation})
    for (const auto& name : simulatable_) {
      Command c = command_of(op);
      c.tag_name = name;
      add(c);
    }
  add(command_of(CommandOp::StopSimulation));
}

// O.7: causes, their tags, effects; on before off.
void CommandOrder::add_soft_bypasses(const std::vector<const Cause*>& causes, const std::vector<const Effect*>& effects) {
  for (const auto* cz : causes)
    for (bool on : {true, false}) {
      Command c = command_of(CommandOp::SoftBypassCause);
      c.cause = cz->id;
      c.on = on;
      add(c);
    }
  for (const auto* cz : causes)
    for (int t = 1; t <= static_cast<int>(cz->tags.size()); ++t)
      for (bool on : {true, false}) {
        Command c = command_of(CommandOp::SoftBypassTag);
        c.cause = cz->id;
        c.tag = t;
        c.on = on;
        add(c);
      }
  for (const auto* ef : effects)
    for (bool on : {true, false}) {
      Command c = command_of(CommandOp::SoftBypassEffect);
      c.effect = ef->id;
      c.on = on;
      add(c);
    }
}

// First-out groups cleared, alarms cleared (causes, then effects), causes acknowledged.
void CommandOrder::add_alarms_and_acks(const std::vector<const Cause*>& causes, const std::vector<const Effect*>& effects) {
  for (int g = 1; g <= kMaxFirstOutGroup; ++g) {
    Command c = command_of(CommandOp::ClearFirstOut);
    c.group = g;
    add(c);
  }
  for (const auto* cz : causes) {
    Command c = command_of(CommandOp::ClearAlarms);
    c.cause = cz->id;
    add(c);
  }
  for (const auto* ef : effects) {
    Command c = command_of(CommandOp::ClearAlarms);
    c.effect = ef->id;
    add(c);
  }
  for (const auto* cz : causes) {
    Command c = command_of(CommandOp::AckCause);
    c.cause = cz->id;
    add(c);
  }
}

// Per effect: reset, override, stop override.
void CommandOrder::add_resets_and_overrides(const std::vector<const Effect*>& effects) {
  for (const auto* ef : effects)
    for (CommandOp op : {CommandOp::ResetEffect, CommandOp::OverrideEffect, CommandOp::StopOverride}) {
      Command c = command_of(op);
      c.effect = ef->id;
      add(c);
    }
}

std::optional<std::size_t> CommandOrder::rank(const Command& c) const {
  auto it = rank_.find(key_of(c));
  if (it == rank_.end()) return std::nullopt;
  return it->second;
}

std::vector<Command> CommandOrder::canonical(const std::vector<Command>& cmds) const {
  // Sorted by (rank, key); a command naming nothing of the matrix ranks after all.
  std::vector<std::pair<std::pair<std::size_t, Key>, Command>> picked;
  auto pick = [&](const Command& c) {
    Key key = key_of(c);
    auto it = rank_.find(key);
    std::pair<std::size_t, Key> at{it == rank_.end() ? rank_.size() : it->second, std::move(key)};
    for (auto& p : picked)
      if (p.first == at) {
        p.second = c;  // a repeat: the last one wins
        return;
      }
    picked.emplace_back(std::move(at), c);
  };
  for (const auto& c : cmds) {
    if (c.op == CommandOp::ClearAlarms && c.cause != 0 && c.effect != 0) {
      Command a = c, b = c;  // O.10: both named, both cleared
      a.effect = 0;
      b.cause = 0;
      pick(a);
      pick(b);
    } else {
      pick(c);
    }
  }
  std::sort(picked.begin(), picked.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Command> out;
  out.reserve(picked.size());
  for (auto& p : picked) out.push_back(std::move(p.second));
  return out;
}

TagValue default_tag_value(const Matrix& m, const InputTag& tag) {
  TagValue v;
  if (std::find(tag.roles.begin(), tag.roles.end(), TagRole::CauseInput) == tag.roles.end())
    return v;  // Boolean control and process tags: FALSE
  std::string key = tag_key(tag.name);
  for (const auto& c : m.causes) {
    if (c.function == CauseFunction::Comment) continue;
    for (const auto& t : c.tags) {
      if (tag_key(t.name) != key) continue;
      if (c.input == InputKind::Analog && c.analog) {
        double limit = c.analog->limit, hyst = c.analog->hysteresis;
        double x = c.analog->limit_type == LimitType::High ? limit - hyst - 1.0 : limit + hyst + 1.0;
        v.value = static_cast<float>(x);
      } else {
        // 6.3.4: DTT trips on FALSE, so its healthy value is TRUE; ETT the opposite.
        v.value = t.ett ? 0.0f : 1.0f;
      }
      return v;
    }
  }
  return v;
}

CycleInput default_cycle_input(const Matrix& m) {
  InputTable table(m);
  CycleInput in;
  for (const auto& t : table.tags()) in.tags.push_back(default_tag_value(m, t));
  return in;
}

}  // namespace cemv::model
