// The encoding of docs/semantics.md as a transition system. Each block cites
// the semantics paragraph it implements (S-n) and the manual section; the
// choices of the encoding itself are in docs/encoding.md.
#include "encoder/encode.hpp"

#include "encoder/builder.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

namespace cemv::encoder {

using model::Node;
using z3::expr;
using detail::Builder;

model::Command CommandInput::command() const {
  model::Command c;
  c.op = op;
  c.cause = cause;
  c.effect = effect;
  c.tag = tag;
  c.group = group;
  c.on = on;
  c.tag_name = tag_name;
  return c;
}

const CommandInput* Encoding::find_command(const model::Command& c) const {
  for (const auto& ci : commands) {
    if (ci.op != c.op) continue;
    switch (c.op) {
      case model::CommandOp::AckCause:
        if (ci.cause == c.cause) return &ci;
        break;
      case model::CommandOp::ResetEffect:
      case model::CommandOp::OverrideEffect:
      case model::CommandOp::StopOverride:
        if (ci.effect == c.effect) return &ci;
        break;
      case model::CommandOp::SoftBypassCause:
        if (ci.cause == c.cause && ci.on == c.on) return &ci;
        break;
      case model::CommandOp::SoftBypassTag:
        if (ci.cause == c.cause && ci.tag == c.tag && ci.on == c.on) return &ci;
        break;
      case model::CommandOp::SoftBypassEffect:
        if (ci.effect == c.effect && ci.on == c.on) return &ci;
        break;
      case model::CommandOp::SimulateTag:
      case model::CommandOp::StopSimulation:
        if (model::tag_key(ci.tag_name) == model::tag_key(c.tag_name)) return &ci;
        break;
      case model::CommandOp::ClearFirstOut:
        if (ci.group == c.group) return &ci;
        break;
      case model::CommandOp::ClearAlarms:
        if ((c.cause != 0 && ci.cause == c.cause) || (c.effect != 0 && ci.effect == c.effect))
          return &ci;
        break;
    }
  }
  return nullptr;
}

std::vector<model::Command> Encoding::canonical_commands(
    const std::vector<model::Command>& cmds) const {
  std::vector<model::Command> out = order.canonical(cmds);
  std::erase_if(out, [&](const model::Command& c) { return find_command(c) == nullptr; });
  return out;
}

namespace detail {

// ---- Inputs and reads ---------------------------------------------------------

expr Builder::raw_value(std::size_t index) {
  auto it = raw_value_.find(index);
  if (it != raw_value_.end()) return it->second;
  const auto& tag = enc_.inputs.tags()[index];
  bool analog = tag.kind == model::TagKind::Analog;
  expr v = ts_.make_inputvar("input." + tag.name, analog ? fp32_ : c_.bool_sort());
  // Floating point: no NaN on the wire (docs/encoding.md).
  if (analog) ts_.add_constraint("input." + tag.name + ".not_nan", not_nan(v));
  enc_.tag_value[index] = v;
  return raw_value_.emplace(index, v).first->second;
}

expr Builder::raw_bad(std::size_t index) {
  auto it = raw_bad_.find(index);
  if (it != raw_bad_.end()) return it->second;
  const auto& tag = enc_.inputs.tags()[index];
  expr v = ts_.make_inputvar("input." + tag.name + ".bad", c_.bool_sort());
  enc_.tag_bad[index] = v;
  return raw_bad_.emplace(index, v).first->second;
}

// T.4: a rising edge needs the previous value; none in cycle 1.
expr Builder::edge_of(const std::string& state_name, const expr& now) {
  expr prev = bool_state(state_name, false);
  ts_.assign_next(prev, now);
  return now && !prev && !first_;
}

expr Builder::ref_value(const model::InternalRef& r, const std::optional<Node>& reader) {
  Node source{r.kind == model::InternalRef::Kind::Cause ? Node::Kind::Cause : Node::Kind::Effect,
              r.id};
  bool processed = false;
  if (source.kind == Node::Kind::Cause) {
    const auto* c = m_.find_cause(r.id);
    processed = c && c->function != model::CauseFunction::Comment;
  } else {
    const auto* e = m_.find_effect(r.id);
    processed = e && e->function != model::EffectFunction::Comment &&
                (r.kind != model::InternalRef::Kind::EffectTag ||
                 (r.tag >= 1 && r.tag <= static_cast<int>(e->tags.size())));
  }
  if (!processed) return B(false);  // I.3
  // I.4: not yet evaluated in this cycle -> the previous cycle's value.
  if (!reader || graph_.reads_previous(source, *reader)) {
    auto key = std::make_tuple(static_cast<int>(r.kind), r.id, r.tag);
    auto it = prev_refs_.find(key);
    if (it == prev_refs_.end()) {
      std::string name =
          "prev." + (r.kind == model::InternalRef::Kind::Cause    ? cause_prefix(r.id) + ".active"
                     : r.kind == model::InternalRef::Kind::Effect ? effect_prefix(r.id) + ".active"
                                                                  : effect_prefix(r.id) + ".tag[" +
                                                                        std::to_string(r.tag) + "]");
      it = prev_refs_.emplace(key, PrevRef{r, bool_state(name, false)}).first;
    }
    return it->second.var;
  }
  if (r.kind == model::InternalRef::Kind::Cause) {
    auto it = cause_active_.find(r.id);
    if (it == cause_active_.end()) throw std::logic_error("reference read before evaluation");
    return it->second;
  }
  if (r.kind == model::InternalRef::Kind::Effect) {
    auto it = effect_active_.find(r.id);
    if (it == effect_active_.end()) throw std::logic_error("reference read before evaluation");
    return it->second;
  }
  auto it = effect_tag_.find({r.id, r.tag});
  if (it == effect_tag_.end()) throw std::logic_error("reference read before evaluation");
  return it->second;
}

expr Builder::bool_read(const std::string& name, const std::optional<Node>& reader) {
  if (auto ref = model::parse_internal_ref(name)) return ref_value(*ref, reader);
  auto idx = enc_.inputs.find(name);
  if (!idx) throw std::logic_error("tag not in the input table: " + name);
  expr v = raw_value(*idx);
  if (v.is_fpa()) return !fp_eq(v, fconst(0.0f));  // I.1: non-zero is TRUE
  return v;
}

// ---- Phase 1: matrix level -----------------------------------------------------

void Builder::build_matrix_level() {
  first_ = bool_state("first_cycle", true);
  ts_.assign_next(first_, B(false));
  gd_ = B(false);
  if (m_.group_deactivation) {
    expr en = bool_read(m_.group_deactivation->enable_tag, std::nullopt);
    expr set = bool_read(m_.group_deactivation->set_tag, std::nullopt);
    gd_ = en && edge_of("prev.group_deactivation.set_tag", set);
  }
  cmd_ok_ = B(true);
  if (m_.secure_write && !m_.secure_write->enable_tag.empty())
    cmd_ok_ = bool_read(m_.secure_write->enable_tag, std::nullopt);
}

// ---- Phase 2: operator commands, in the encoding's fixed order ------------------

// Phase 2 of M.1: the operator commands as per-cycle inputs, processed as a set
// in the encoding's fixed order (docs/encoding.md "Operator commands"); the
// creation order of the command inputs is that order.
void Builder::build_commands() {
  collect_simulations();
  make_tag_soft_bypass_states();
  command_simulate_tag();
  command_stop_simulation();
  command_soft_bypass_cause();
  command_soft_bypass_tag();
  command_soft_bypass_effect();
  commands_without_interplay();
}

// The simulatable tags of the cone (O.8), in the model's order
// (model::CommandOrder::simulatable_tags), so that a slice processes its
// commands in the order of the whole matrix.
void Builder::collect_simulations() {
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
    sims_.emplace(key, Simulation{name, analog, !input, forbidden.count(key) == 0, on && !gd_, val, on, val});
    sim_order_.push_back(key);
  }
}

// Tag soft bypass states before the commands (M.2 ends them first).
void Builder::make_tag_soft_bypass_states() {
  for (const auto* cz : causes_) {
    for (std::size_t t = 0; t < cz->tags.size(); ++t) {
      expr v = bool_state(cause_prefix(cz->id) + ".tag[" + std::to_string(t + 1) + "].soft_bypass",
                          false);
      tag_sb_prev_[cz->id].push_back(v);
      tag_sb_[cz->id].push_back(v && !gd_);
    }
  }
}

// 1. simulate_tag, in tag order.
void Builder::command_simulate_tag() {
  for (const auto& key : sim_order_) {
    Simulation& s = sims_.at(key);
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
void Builder::command_stop_simulation() {
  for (const auto& key : sim_order_) {
    Simulation& s = sims_.at(key);
    CommandInput ci = cmd_of(model::CommandOp::StopSimulation);
    ci.tag_name = s.name;
    expr stop = command(ci, "cmd.stop_simulation[" + s.name + "]");
    s.on = s.on && !stop;
  }
  {
    CommandInput ci = cmd_of(model::CommandOp::StopSimulation);
    expr stop_all = command(ci, "cmd.stop_simulation");
    for (const auto& key : sim_order_) sims_.at(key).on = sims_.at(key).on && !stop_all;
  }
  for (const auto& key : sim_order_) {
    const Simulation& s = sims_.at(key);
    ts_.assign_next(s.on_prev, s.on);
    ts_.assign_next(s.value_prev, s.value);
  }
}

// 3. soft_bypass_cause (O.5): on, then off.
void Builder::command_soft_bypass_cause() {
  for (const auto* cz : causes_) {
    const std::string P = cause_prefix(cz->id);
    const std::string id = std::to_string(cz->id);
    expr prev = bool_state(P + ".soft_bypass", false);
    expr now = prev && !gd_;
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
    cause_cmds_.emplace(cz->id, CauseCommands{now, start, prev, {}, B(false), B(false)});
  }
}

// 4. soft_bypass_tag (O.6): per cause, per position: on, then off.
void Builder::command_soft_bypass_tag() {
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
    cause_cmds_.at(cz->id).tag_sb = sb;
  }
}

// 5. soft_bypass_effect (O.7): on, then off.
void Builder::command_soft_bypass_effect() {
  for (const auto* ef : effects_) {
    const std::string E = std::to_string(ef->id);
    expr prev = bool_state(effect_prefix(ef->id) + ".soft_bypass", false);
    expr now = prev && !gd_;
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
    effect_cmds_.emplace(ef->id, EffectCommands{now, B(false), B(false), B(false)});
  }
}

// 6. Commands without interplay: clear_first_out, clear_alarms, ack_cause,
// reset_effect, override_effect / stop_override.
void Builder::commands_without_interplay() {
  std::set<int> groups;
  for (const auto* cz : causes_)
    if (cz->first_out_group >= 1 && cz->first_out_group <= model::kMaxFirstOutGroup)
      groups.insert(cz->first_out_group);
  for (int g : groups) {
    CommandInput ci = cmd_of(model::CommandOp::ClearFirstOut);
    ci.group = g;
    clear_first_out_.emplace(g, command(ci, "cmd.clear_first_out[" + std::to_string(g) + "]"));
  }
  for (const auto* cz : causes_) {
    CommandInput ci = cmd_of(model::CommandOp::ClearAlarms);
    ci.cause = cz->id;
    cause_cmds_.at(cz->id).clear_alarms =
        command(ci, "cmd.clear_alarms_cause[" + std::to_string(cz->id) + "]");
  }
  for (const auto* ef : effects_) {
    CommandInput ci = cmd_of(model::CommandOp::ClearAlarms);
    ci.effect = ef->id;
    effect_cmds_.at(ef->id).clear_alarms =
        command(ci, "cmd.clear_alarms_effect[" + std::to_string(ef->id) + "]");
  }
  for (const auto* cz : causes_) {
    bool has_latch = !cz->auto_ack && (cz->time.mode == model::TimeMode::None ||
                                       cz->time.mode == model::TimeMode::OnDelay);
    if (!has_latch) continue;  // O.1: refused
    CommandInput ci = cmd_of(model::CommandOp::AckCause);
    ci.cause = cz->id;
    cause_cmds_.at(cz->id).ack = command(ci, "cmd.ack_cause[" + std::to_string(cz->id) + "]");
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
      effect_cmds_.at(ef->id).reset = command(ci, "cmd.reset_effect[" + E + "]");
    }
    if (has_vr) {
      CommandInput o = cmd_of(model::CommandOp::OverrideEffect);
      o.effect = ef->id;
      expr a = command(o, "cmd.override_effect[" + E + "]");
      CommandInput s = cmd_of(model::CommandOp::StopOverride);
      s.effect = ef->id;
      expr b = command(s, "cmd.stop_override[" + E + "]");
      effect_cmds_.at(ef->id).toggle = a || b;  // O.3: two count as one
    }
  }
}

// A tag's simulation state at this point of the command sequence (O.8).
expr Builder::sim_on(const std::string& name) {
  auto it = sims_.find(model::tag_key(name));
  return it == sims_.end() ? B(false) : it->second.on;
}

// O.6/O.8 mutual lock: another tag (different name) of a locked cause is
// simulated or soft-bypassed at this point of the command sequence.
expr Builder::cause_locked_except(const model::Cause* cz, const std::string& key) {
  std::vector<expr> busy;
  for (std::size_t u = 0; u < cz->tags.size(); ++u) {
    if (model::tag_key(cz->tags[u].name) == key) continue;
    busy.push_back(tag_sb_[cz->id][u]);
    if (!model::parse_internal_ref(cz->tags[u].name)) busy.push_back(sim_on(cz->tags[u].name));
  }
  return any(busy);
}

void Builder::finish_previous_refs() {
  for (auto& [key, pr] : prev_refs_) {
    const auto& r = pr.ref;
    expr now = B(false);
    if (r.kind == model::InternalRef::Kind::Cause) {
      if (auto it = cause_active_.find(r.id); it != cause_active_.end()) now = it->second;
    } else if (r.kind == model::InternalRef::Kind::Effect) {
      if (auto it = effect_active_.find(r.id); it != effect_active_.end()) now = it->second;
    } else if (auto it = effect_tag_.find({r.id, r.tag}); it != effect_tag_.end()) {
      now = it->second;
    }
    ts_.assign_next(pr.var, now);
  }
}

void Builder::build(const std::vector<Node>& roots) {
  enc_.inputs = model::InputTable(m_);
  enc_.order = model::CommandOrder(m_);
  enc_.tag_value.assign(enc_.inputs.size(), std::nullopt);
  enc_.tag_bad.assign(enc_.inputs.size(), std::nullopt);
  const auto& order = graph_.evaluation_order();
  if (roots.empty()) {
    cone_.insert(order.begin(), order.end());
  } else {
    auto feeders = graph_.feeders_of(roots);
    cone_.insert(feeders.begin(), feeders.end());
  }
  // References read from outside the cone still need their source's value:
  // feeders_of includes them (the graph has an edge per reference).
  for (const auto& cz : m_.causes)
    if (cz.function != model::CauseFunction::Comment && cone_.count({Node::Kind::Cause, cz.id}))
      causes_.push_back(&cz);
  for (const auto& ef : m_.effects)
    if (ef.function != model::EffectFunction::Comment && cone_.count({Node::Kind::Effect, ef.id}))
      effects_.push_back(&ef);

  build_matrix_level();
  build_commands();
  for (const Node& n : order) {
    if (!cone_.count(n)) continue;
    enc_.nodes.push_back(n);
    if (n.kind == Node::Kind::Cause) build_cause(*m_.find_cause(n.id));
    else build_effect(*m_.find_effect(n.id));
  }
  build_first_out();
  finish_previous_refs();
  for (const auto& o : model::observables(m_))
    if (cone_.count(Node{o.kind, o.id}) && ts_.term(o.key)) enc_.observables.push_back(o);
}

}  // namespace detail

std::unique_ptr<Encoding> encode(z3::context& ctx, const model::Matrix& m,
                                 const std::vector<Node>& roots, const EncodeOptions& options) {
  auto enc = std::make_unique<Encoding>(ctx);
  Builder b(ctx, m, *enc, options.guard_cells);
  b.build(roots);
  enc->ts.check_complete();
  return enc;
}

}  // namespace cemv::encoder