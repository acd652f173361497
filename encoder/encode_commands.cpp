// Phase 2 of M.1: the operator commands (docs/semantics.md section O) as
// per-cycle inputs, in the encoding's fixed order (docs/encoding.md
// "Operator commands").
#include <set>

#include "encoder/builder.hpp"

namespace cemv::encoder::detail {

// ---- Phase 2: operator commands, in the encoding's fixed order ------------------

// Phase 2 of M.1: the operator commands as per-cycle inputs, processed as a set
// in the encoding's fixed order (docs/encoding.md "Operator commands"); the
// creation order of the command inputs is that order.
CommandStates CommandEncoder::encode() {
  collect_simulations();
  make_tag_soft_bypass_states();
  command_simulate_tag();
  command_stop_simulation();
  command_soft_bypass_cause();
  command_soft_bypass_tag();
  command_soft_bypass_effect();
  commands_without_interplay();
  return std::move(out_);
}

// The simulatable tags of the cone (O.8), in the model's order
// (model::CommandOrder::simulatable_tags), so that a slice processes its
// commands in the order of the whole matrix.
void CommandEncoder::collect_simulations() {
  std::set<std::string> read, written;  // tag keys
  for (const auto* cz : causes_)
    for (const auto& t : cz->tags) {
      if (model::parse_internal_ref(t.name)) continue;
      std::string key = model::tag_key(t.name);
      if (cz->mutually_locked_maintenance) readers_[key].push_back(cz);
      read.insert(key);
    }
  for (const auto* ef : effects_)
    for (const auto& t : ef->tags) {
      std::string key = model::tag_key(t.name);
      if (ef->mutually_locked_maintenance) writers_[key].push_back(ef);
      written.insert(key);
    }
  // O.8: a tag whose simulation some processed element forbids, in or out of
  // the cone, is never simulated.
  std::set<std::string> forbidden;
  for (const auto& cz : m_.causes)
    if (cz.function != model::CauseFunction::Comment)
      for (const auto& t : cz.tags)
        if (!t.simulation_allowed) forbidden.insert(model::tag_key(t.name));
  for (const auto& ef : m_.effects)
    if (ef.function != model::EffectFunction::Comment)
      for (const auto& t : ef.tags)
        if (!t.simulation_allowed) forbidden.insert(model::tag_key(t.name));
  for (const auto& name : enc_.order.simulatable_tags()) {
    std::string key = model::tag_key(name);
    bool input = read.count(key) > 0;
    if (!input && !written.count(key)) continue;
    auto idx = enc_.inputs.find(name);
    bool analog = input && idx && enc_.inputs.tags()[*idx].kind == model::TagKind::Analog;
    std::string sp = "sim[" + name + "]";
    z3::sort sort = analog ? fp32_ : c_.bool_sort();
    expr on = bool_state(sp + ".on", false);
    expr val = ts_.make_statevar(sp + ".value", sort);
    ts_.set_init(val, analog ? fconst(0.0f) : B(false));
    // M.2: group deactivation ends every simulation before the commands.
    out_.sims.emplace(key, Simulation{name, analog, !input, forbidden.count(key) == 0, on && !reads_.gd(), val, on, val});
    out_.sim_order.push_back(key);
  }
}

// Tag soft bypass states before the commands (M.2 ends them first).
void CommandEncoder::make_tag_soft_bypass_states() {
  for (const auto* cz : causes_) {
    for (std::size_t t = 0; t < cz->tags.size(); ++t) {
      expr v = bool_state(cause_prefix(cz->id) + ".tag[" + std::to_string(t + 1) + "].soft_bypass",
                          false);
      tag_sb_prev_[cz->id].push_back(v);
      tag_sb_[cz->id].push_back(v && !reads_.gd());
    }
  }
}

// 1. simulate_tag, in tag order.
void CommandEncoder::command_simulate_tag() {
  for (const auto& key : out_.sim_order) {
    Simulation& s = out_.sims.at(key);
    if (!s.allowed) continue;  // refused whatever its value: no command input (O.8)
    CommandInput ci = cmd_of(model::CommandOp::SimulateTag);
    ci.tag_name = s.name;
    std::string n = "cmd.simulate_tag[" + s.name + "]";
    expr value_in = ts_.make_inputvar(n + ".value", s.analog ? fp32_ : c_.bool_sort());
    if (s.analog) ts_.add_constraint(n + ".value.not_nan", not_nan(value_in));
    ci.value = value_in;
    expr accepted = command(ci, n);
    std::vector<expr> locks;
    for (const auto* cz : readers_[key]) locks.push_back(cause_locked_except(cz, key));
    for (const auto* ef : writers_[key]) {
      for (const auto& t : ef->tags)
        if (model::tag_key(t.name) != key) locks.push_back(sim_on(t.name));
    }
    accepted = accepted && !any(locks);
    s.value = z3::ite(accepted, value_in, s.value);
    s.on = s.on || accepted;
  }
}

// 2. stop_simulation per tag, then for every tag.
void CommandEncoder::command_stop_simulation() {
  for (const auto& key : out_.sim_order) {
    Simulation& s = out_.sims.at(key);
    CommandInput ci = cmd_of(model::CommandOp::StopSimulation);
    ci.tag_name = s.name;
    expr stop = command(ci, "cmd.stop_simulation[" + s.name + "]");
    s.on = s.on && !stop;
  }
  {
    CommandInput ci = cmd_of(model::CommandOp::StopSimulation);
    expr stop_all = command(ci, "cmd.stop_simulation");
    for (const auto& key : out_.sim_order) out_.sims.at(key).on = out_.sims.at(key).on && !stop_all;
  }
  for (const auto& key : out_.sim_order) {
    const Simulation& s = out_.sims.at(key);
    ts_.assign_next(s.on_prev, s.on);
    ts_.assign_next(s.value_prev, s.value);
  }
}

// 3. soft_bypass_cause (O.5): on, then off.
void CommandEncoder::command_soft_bypass_cause() {
  for (const auto* cz : causes_) {
    const std::string P = cause_prefix(cz->id);
    const std::string id = std::to_string(cz->id);
    expr prev = bool_state(P + ".soft_bypass", false);
    expr now = prev && !reads_.gd();
    expr start = B(false);
    if (cz->soft_bypass.allowed) {
      CommandInput on = cmd_of(model::CommandOp::SoftBypassCause);
      on.cause = cz->id;
      expr do_on = command(on, "cmd.soft_bypass_cause[" + id + "].on");
      CommandInput off = on;
      off.on = false;
      expr do_off = command(off, "cmd.soft_bypass_cause[" + id + "].off");
      start = do_on && !now && !do_off;
      now = (now || do_on) && !do_off;
    }
    out_.cause_cmds.emplace(cz->id, CommandStates::CauseCommands{now, start, prev, {}, B(false), B(false)});
  }
}

// 4. soft_bypass_tag (O.6): per cause, per position: on, then off.
void CommandEncoder::command_soft_bypass_tag() {
  for (const auto* cz : causes_) {
    auto& sb = tag_sb_[cz->id];
    for (std::size_t t = 0; t < cz->tags.size(); ++t) {
      const auto& tag = cz->tags[t];
      if (!tag.soft_bypass_allowed) continue;
      std::string n = "cmd.soft_bypass_tag[" + std::to_string(cz->id) + "][" +
                      std::to_string(t + 1) + "]";
      CommandInput on = cmd_of(model::CommandOp::SoftBypassTag);
      on.cause = cz->id;
      on.tag = static_cast<int>(t + 1);
      expr do_on = command(on, n + ".on");
      if (cz->mutually_locked_maintenance)
        do_on = do_on && !cause_locked_except(cz, model::tag_key(tag.name));
      sb[t] = sb[t] || do_on;
      CommandInput off = on;
      off.on = false;
      expr do_off = command(off, n + ".off");
      sb[t] = sb[t] && !do_off;
    }
    for (std::size_t t = 0; t < cz->tags.size(); ++t) ts_.assign_next(tag_sb_prev_[cz->id][t], sb[t]);
    out_.cause_cmds.at(cz->id).tag_sb = sb;
  }
}

// 5. soft_bypass_effect (O.7): on, then off.
void CommandEncoder::command_soft_bypass_effect() {
  for (const auto* ef : effects_) {
    const std::string E = std::to_string(ef->id);
    expr prev = bool_state(effect_prefix(ef->id) + ".soft_bypass", false);
    expr now = prev && !reads_.gd();
    if (ef->soft_bypass_allowed) {
      CommandInput on = cmd_of(model::CommandOp::SoftBypassEffect);
      on.effect = ef->id;
      expr do_on = command(on, "cmd.soft_bypass_effect[" + E + "].on");
      CommandInput off = on;
      off.on = false;
      expr do_off = command(off, "cmd.soft_bypass_effect[" + E + "].off");
      now = (now || do_on) && !do_off;
    }
    ts_.assign_next(prev, now);
    out_.effect_cmds.emplace(ef->id, CommandStates::EffectCommands{now, B(false), B(false), B(false)});
  }
}

// 6. Commands without interplay: clear_first_out, clear_alarms, ack_cause,
// reset_effect, override_effect / stop_override.
void CommandEncoder::commands_without_interplay() {
  std::set<int> groups;
  for (const auto* cz : causes_)
    if (cz->first_out_group >= 1 && cz->first_out_group <= model::kMaxFirstOutGroup)
      groups.insert(cz->first_out_group);
  for (int g : groups) {
    CommandInput ci = cmd_of(model::CommandOp::ClearFirstOut);
    ci.group = g;
    out_.clear_first_out.emplace(g, command(ci, "cmd.clear_first_out[" + std::to_string(g) + "]"));
  }
  for (const auto* cz : causes_) {
    CommandInput ci = cmd_of(model::CommandOp::ClearAlarms);
    ci.cause = cz->id;
    out_.cause_cmds.at(cz->id).clear_alarms =
        command(ci, "cmd.clear_alarms_cause[" + std::to_string(cz->id) + "]");
  }
  for (const auto* ef : effects_) {
    CommandInput ci = cmd_of(model::CommandOp::ClearAlarms);
    ci.effect = ef->id;
    out_.effect_cmds.at(ef->id).clear_alarms =
        command(ci, "cmd.clear_alarms_effect[" + std::to_string(ef->id) + "]");
  }
  for (const auto* cz : causes_) {
    bool has_latch = !cz->auto_ack && (cz->time.mode == model::TimeMode::None ||
                                       cz->time.mode == model::TimeMode::OnDelay);
    if (!has_latch) continue;  // O.1: refused
    CommandInput ci = cmd_of(model::CommandOp::AckCause);
    ci.cause = cz->id;
    out_.cause_cmds.at(cz->id).ack = command(ci, "cmd.ack_cause[" + std::to_string(cz->id) + "]");
  }
  for (const auto* ef : effects_) {
    if (ef->reset_tag) continue;  // O.2, O.3: refused with a reset tag
    bool has_sr = false, has_vr = false;
    for (const auto* is : m_.intersections_of_effect(ef->id)) {
      if (!model::is_processed(is->type)) continue;
      const auto* cz = m_.find_cause(is->cause);
      if (!cz || cz->function == model::CauseFunction::Comment) continue;
      if (is->type == model::IntersectionType::S || is->type == model::IntersectionType::R)
        has_sr = true;
      if (is->type == model::IntersectionType::V || is->type == model::IntersectionType::R)
        has_vr = true;
    }
    const std::string E = std::to_string(ef->id);
    if (has_sr) {
      CommandInput ci = cmd_of(model::CommandOp::ResetEffect);
      ci.effect = ef->id;
      out_.effect_cmds.at(ef->id).reset = command(ci, "cmd.reset_effect[" + E + "]");
    }
    if (has_vr) {
      CommandInput o = cmd_of(model::CommandOp::OverrideEffect);
      o.effect = ef->id;
      expr a = command(o, "cmd.override_effect[" + E + "]");
      CommandInput s = cmd_of(model::CommandOp::StopOverride);
      s.effect = ef->id;
      expr b = command(s, "cmd.stop_override[" + E + "]");
      out_.effect_cmds.at(ef->id).toggle = a || b;  // O.3: two count as one
    }
  }
}

// A tag's simulation state at this point of the command sequence (O.8).
expr CommandEncoder::sim_on(const std::string& name) {
  auto it = out_.sims.find(model::tag_key(name));
  return it == out_.sims.end() ? B(false) : it->second.on;
}

// O.6/O.8 mutual lock: another tag (different name) of a locked cause is
// simulated or soft-bypassed at this point of the command sequence.
expr CommandEncoder::cause_locked_except(const model::Cause* cz, const std::string& key) {
  std::vector<expr> busy;
  for (std::size_t u = 0; u < cz->tags.size(); ++u) {
    if (model::tag_key(cz->tags[u].name) == key) continue;
    busy.push_back(tag_sb_[cz->id][u]);
    if (!model::parse_internal_ref(cz->tags[u].name)) busy.push_back(sim_on(cz->tags[u].name));
  }
  return any(busy);
}

}  // namespace cemv::encoder::detail
