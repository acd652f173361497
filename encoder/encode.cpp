// The encoding of docs/semantics.md as a transition system. Each block cites
// the semantics paragraph it implements (S-n) and the manual section; the
// choices of the encoding itself are in docs/encoding.md.
#include "encoder/encode.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

namespace cemv::encoder {

using model::Node;
using z3::expr;

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

namespace {

// Term names start with the element as observable keys spell it
// (model::observable_key), so each observable is the term named by its key.
std::string cause_prefix(int id) { return model::to_string(Node{Node::Kind::Cause, id}); }
std::string effect_prefix(int id) { return model::to_string(Node{Node::Kind::Effect, id}); }

// T.2: whole cycles of a duration, rounded up, 64-bit.
int cycles_of(std::uint64_t ms, std::uint32_t cycle_ms) {
  if (ms == 0 || cycle_ms == 0) return 0;
  return static_cast<int>((ms + cycle_ms - 1) / cycle_ms);
}

// A simulatable tag (O.8): its simulation state after this cycle's commands.
struct Simulation {
  std::string name;
  bool analog = false;
  bool output = false;
  expr on;
  expr value;
  expr on_prev;    // state variable
  expr value_prev; // state variable
};

class Builder {
 public:
  Builder(z3::context& ctx, const model::Matrix& m, Encoding& enc)
      : c_(ctx), m_(m), enc_(enc), ts_(enc.ts), graph_(m), first_(ctx), cmd_ok_(ctx), gd_(ctx),
        fp32_(ctx.fpa_sort(8, 24)) {}

  void build(const std::vector<Node>& roots);

 private:
  expr B(bool b) { return c_.bool_val(b); }
  expr I(int v) { return c_.int_val(v); }
  expr count(const std::vector<expr>& bs) {
    if (bs.empty()) return I(0);
    expr sum = z3::ite(bs[0], I(1), I(0));
    for (std::size_t i = 1; i < bs.size(); ++i) sum = sum + z3::ite(bs[i], I(1), I(0));
    return sum;
  }
  expr any(const std::vector<expr>& bs) {
    if (bs.empty()) return B(false);  // a nullary (or) prints as a bare symbol
    if (bs.size() == 1) return bs[0];
    z3::expr_vector v(c_);
    for (const auto& b : bs) v.push_back(b);
    return z3::mk_or(v);
  }
  expr bool_state(const std::string& name, bool init) {
    expr v = ts_.make_statevar(name, c_.bool_sort());
    ts_.set_init(v, B(init));
    return v;
  }
  // An elapsed-cycles counter (T.2) saturating at d, with its range lemma.
  expr counter(const std::string& name, int d) {
    expr v = ts_.make_statevar(name, c_.int_sort());
    ts_.set_init(v, I(0));
    ts_.add_lemma(name + ".range", v >= 0 && v <= d);
    return v;
  }
  expr sat_inc(const expr& e, int d) { return z3::ite(e >= d, I(d), e + 1); }
  expr fconst(float v) { return ts_.float_const(v); }
  expr fge(const expr& a, const expr& b) { return expr(c_, Z3_mk_fpa_geq(c_, a, b)); }
  expr fle(const expr& a, const expr& b) { return expr(c_, Z3_mk_fpa_leq(c_, a, b)); }
  expr flt(const expr& a, const expr& b) { return expr(c_, Z3_mk_fpa_lt(c_, a, b)); }
  expr fabs_diff(const expr& a, const expr& b) {
    expr d(c_, Z3_mk_fpa_sub(c_, ts_.rne(), a, b));
    return expr(c_, Z3_mk_fpa_abs(c_, d));
  }
  expr not_nan(const expr& v) { return !expr(c_, Z3_mk_fpa_is_nan(c_, v)); }

  // A per-cycle command input, gated by secure write (M.3). Creation order is
  // the processing order (Encoding::canonical_commands).
  expr command(CommandInput ci, const std::string& name) {
    ci.var = ts_.make_inputvar(name, c_.bool_sort());
    enc_.commands.push_back(ci);
    return ci.var && cmd_ok_;
  }
  CommandInput cmd_of(model::CommandOp op) {
    return CommandInput{op, 0, 0, 0, 0, true, "", B(false), std::nullopt};
  }

  // The raw input of a tag (I.1); created on first use.
  expr raw_value(std::size_t index);
  expr raw_bad(std::size_t index);
  // A Boolean read of a tag slot by `reader` (E.1, C.8, M.2): an internal
  // reference (I.3, I.4) or the raw input value; nullopt reader = matrix level.
  expr bool_read(const std::string& name, const std::optional<Node>& reader);
  expr ref_value(const model::InternalRef& r, const std::optional<Node>& reader);
  expr edge_of(const std::string& state_name, const expr& now);

  void build_matrix_level();
  void build_commands();
  // The steps of build_commands, in the order the encoding processes them.
  void collect_simulations();
  void make_tag_soft_bypass_states();
  void command_simulate_tag();        // O.8
  void command_stop_simulation();     // O.8
  void command_soft_bypass_cause();   // O.5
  void command_soft_bypass_tag();     // O.6
  void command_soft_bypass_effect();  // O.7
  void commands_without_interplay();  // O.9, O.10, O.1, O.2, O.3
  expr sim_on(const std::string& name);
  expr cause_locked_except(const model::Cause* cz, const std::string& key);
  void build_cause(const model::Cause& cz);
  void build_first_out();
  void build_effect(const model::Effect& ef);
  void finish_previous_refs();

  z3::context& c_;
  const model::Matrix& m_;
  Encoding& enc_;
  TransitionSystem& ts_;
  model::DependencyGraph graph_;
  expr first_;   // cycle 1 (T.3)
  expr cmd_ok_;  // M.3: commands accepted in this cycle
  expr gd_;      // M.2: group deactivation in this cycle
  z3::sort fp32_;
  std::set<Node> cone_;
  std::vector<const model::Cause*> causes_;    // processed causes in the cone, by id
  std::vector<const model::Effect*> effects_;  // processed effects in the cone, by id

  std::map<std::size_t, expr> raw_value_, raw_bad_;
  std::map<std::string, Simulation> sims_;     // by tag_key
  std::vector<std::string> sim_order_;         // tag keys in processing order
  std::map<std::string, std::vector<const model::Cause*>> readers_;   // tag key -> locked causes (O.6, O.8)
  std::map<std::string, std::vector<const model::Effect*>> writers_;  // tag key -> locked effects (O.8)
  std::map<int, std::vector<expr>> tag_sb_prev_;  // tag soft bypass (O.6): previous cycle, by cause
  std::map<int, std::vector<expr>> tag_sb_;       // ... and at this point of the command sequence

  // After phase 2 (commands).
  struct CauseCommands {
    expr sb_on;        // soft bypass after commands (before the C.1 expiry check)
    expr sb_start;     // switched on in this cycle (timer starts)
    expr sb_prev;      // state variable
    std::vector<expr> tag_sb;  // tag soft bypass after commands
    expr clear_alarms;
    expr ack;
  };
  struct EffectCommands {
    expr sb_on;
    expr clear_alarms;
    expr reset;   // reset_effect accepted
    expr toggle;  // override_effect / stop_override accepted
  };
  std::map<int, CauseCommands> cause_cmds_;
  std::map<int, EffectCommands> effect_cmds_;
  std::map<int, expr> clear_first_out_;

  std::map<int, expr> cause_active_;
  std::map<int, expr> effect_active_;
  std::map<std::pair<int, int>, expr> effect_tag_;
  struct PrevRef {
    model::InternalRef ref;
    expr var;
  };
  std::map<std::tuple<int, int, int>, PrevRef> prev_refs_;
  std::map<int, std::vector<std::pair<int, expr>>> first_out_groups_;
};

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
    sims_.emplace(key, Simulation{name, analog, !input, on && !gd_, val, on, val});
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

// ---- Phase 3: causes -------------------------------------------------------------

void Builder::build_cause(const model::Cause& cz) {
  const Node self{Node::Kind::Cause, cz.id};
  const std::string P = cause_prefix(cz.id);
  const int n = static_cast<int>(cz.tags.size());
  const bool analog = cz.input == model::InputKind::Analog && cz.analog.has_value();
  const model::AnalogParams ap = analog ? *cz.analog : model::AnalogParams{};
  const bool high = ap.limit_type == model::LimitType::High;
  CauseCommands& cmds = cause_cmds_.at(cz.id);

  // C.1: timed soft bypass, expiry checked at the start of the evaluation.
  expr sb = cmds.sb_on;
  expr bypass_timeout = B(false);
  expr bypass_prealarm = B(false);
  {
    expr alarm = bool_state(P + ".bypass_timeout", false);
    expr kept = alarm && !cmds.clear_alarms;
    if (cz.soft_bypass.allowed && cz.soft_bypass.max_s > 0) {
      const int d = cycles_of(std::uint64_t{cz.soft_bypass.max_s} * 1000, m_.cycle_ms);
      expr cntv = counter(P + ".soft_bypass.elapsed", d);
      expr elapsed = z3::ite(cmds.sb_start, I(0), cntv);
      expr expired = sb && elapsed >= d;
      sb = sb && !expired;
      if (cz.soft_bypass.prealarm_s > 0) {
        const int pre = cycles_of(std::uint64_t{cz.soft_bypass.prealarm_s} * 1000, m_.cycle_ms);
        bypass_prealarm = sb && elapsed >= pre;
      }
      ts_.assign_next(cntv, z3::ite(sb, sat_inc(elapsed, d), I(0)));
      bypass_timeout = kept || expired;
    } else {
      bypass_timeout = kept;
    }
    ts_.assign_next(alarm, bypass_timeout);
  }
  ts_.assign_next(cmds.sb_prev, sb);

  // C.2: tag values and qualities.
  std::vector<expr> values, bads;
  for (int t = 0; t < n; ++t) {
    const auto& tag = cz.tags[static_cast<std::size_t>(t)];
    if (auto ref = model::parse_internal_ref(tag.name)) {
      values.push_back(ref_value(*ref, self));
      bads.push_back(B(false));
      continue;
    }
    std::size_t idx = *enc_.inputs.find(tag.name);
    expr raw = raw_value(idx);
    expr bad = raw_bad(idx);
    const Simulation& s = sims_.at(model::tag_key(tag.name));
    values.push_back(z3::ite(s.on, s.value, raw));
    bads.push_back(bad && !s.on);
  }

  // C.3: trip, taken out. C.4: voting with hysteresis.
  expr hyst_mode = bool_state(P + ".trip_requested_prev", false);
  const float relaxed = high ? ap.limit - ap.hysteresis : ap.limit + ap.hysteresis;
  std::vector<expr> tripped, tripped_strict, out_bad, out;
  for (int t = 0; t < n; ++t) {
    const auto& tag = cz.tags[static_cast<std::size_t>(t)];
    expr by_value = B(false), by_value_strict = B(false);
    if (!analog) {
      by_value = tag.ett ? values[t] : !values[t];
      by_value_strict = by_value;
    } else {
      by_value_strict = high ? fge(values[t], fconst(ap.limit)) : fle(values[t], fconst(ap.limit));
      expr relax = high ? fge(values[t], fconst(relaxed)) : fle(values[t], fconst(relaxed));
      by_value = z3::ite(hyst_mode, relax, by_value_strict);
    }
    expr tsb = cmds.tag_sb[static_cast<std::size_t>(t)];
    expr ob = cz.bad_quality == model::BadQuality::Degrade ? (bads[t] && !tsb) : B(false);
    bool trip_bad = cz.bad_quality == model::BadQuality::Trip;
    tripped.push_back(trip_bad ? (bads[t] || by_value) : by_value);
    tripped_strict.push_back(trip_bad ? (bads[t] || by_value_strict) : by_value_strict);
    out_bad.push_back(ob);
    out.push_back(tsb || ob);
  }
  std::vector<expr> counted, counted_strict;
  for (int t = 0; t < n; ++t) {
    counted.push_back(tripped[t] && !out[t]);
    counted_strict.push_back(tripped_strict[t] && !out[t]);
  }
  expr k = count(out);
  expr cnt = count(counted);
  expr cnt_strict = count(counted_strict);
  expr any_bad_out = any(out_bad);
  int X = 1;
  if (cz.function == model::CauseFunction::And) X = n;
  if (cz.function == model::CauseFunction::TwoOoThree) X = 2;
  auto voting_code = [](int x, int of) -> int {
    using V = model::Voting;
    if (of == 1) return static_cast<int>(V::OneOoOne);
    if (of == 2) return static_cast<int>(x == 1 ? V::OneOoTwo : V::TwoOoTwo);
    return static_cast<int>(x == 1 ? V::OneOoThree : x == 2 ? V::TwoOoThree : V::ThreeOoThree);
  };
  expr tr = any_bad_out;  // m = 0
  expr tr_strict = any_bad_out;
  expr voting = z3::ite(any_bad_out, I(static_cast<int>(model::Voting::OneOoOne)),
                        I(static_cast<int>(model::Voting::Bypass)));
  for (int k0 = n - 1; k0 >= 0; --k0) {
    int xk = std::max(1, X - k0);
    tr = z3::ite(k == k0, cnt >= xk, tr);
    tr_strict = z3::ite(k == k0, cnt_strict >= xk, tr_strict);
    voting = z3::ite(k == k0, I(voting_code(xk, n - k0)), voting);
  }
  ts_.assign_next(hyst_mode, tr);

  // C.5: delta alarm and prewarning (status only).
  expr delta_alarm = B(false);
  expr prewarning = B(false);
  if (analog && ap.delta > 0.0f && n >= 2) {
    std::vector<expr> pairs;
    const float clear_below = ap.delta - ap.hysteresis;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        expr st = bool_state(
            P + ".delta[" + std::to_string(i + 1) + "][" + std::to_string(j + 1) + "]", false);
        expr diff = fabs_diff(values[i], values[j]);
        expr now = z3::ite(fge(diff, fconst(ap.delta)), B(true),
                           z3::ite(flt(diff, fconst(clear_below)), B(false), st));
        ts_.assign_next(st, now);
        pairs.push_back(now);
      }
    delta_alarm = any(pairs);
  }
  if (analog && ap.prewarning &&
      (high ? *ap.prewarning < ap.limit : *ap.prewarning > ap.limit)) {
    std::vector<expr> pw;
    for (int t = 0; t < n; ++t)
      pw.push_back(high ? fge(values[t], fconst(*ap.prewarning))
                        : fle(values[t], fconst(*ap.prewarning)));
    prewarning = any(pw);
  }

  // C.6: time function.
  const int d = cycles_of(cz.time.ms, m_.cycle_ms);
  expr tm = tr;
  expr timer_running = B(false);
  switch (cz.time.mode) {
    case model::TimeMode::None:
      break;
    case model::TimeMode::OnDelay: {
      // Counter = cycles TR has held before this cycle (saturating at D).
      expr held = counter(P + ".on_delay.elapsed", d);
      tm = tr && held >= d;
      timer_running = tr && !tm;
      ts_.assign_next(held, z3::ite(tr, sat_inc(held, d), I(0)));
      break;
    }
    case model::TimeMode::OffDelay: {
      expr tm_prev = bool_state(P + ".off_delay.tm_prev", false);
      expr since = counter(P + ".off_delay.elapsed", d);
      tm = tr || (tm_prev && since < d);
      timer_running = !tr && tm;
      ts_.assign_next(tm_prev, tm);
      ts_.assign_next(since, z3::ite(tr, I(0), sat_inc(since, d)));
      break;
    }
    case model::TimeMode::Timed: {
      expr tr_prev = bool_state(P + ".timed.tr_prev", false);
      expr running = bool_state(P + ".timed.running", false);
      expr cntv = counter(P + ".timed.elapsed", d);
      expr cont = running && cntv < d;
      expr start = tr && !tr_prev && !cont;
      tm = cont || (start && B(d > 0));
      expr elapsed = z3::ite(start, I(0), cntv);
      timer_running = tm;
      ts_.assign_next(tr_prev, tr);
      ts_.assign_next(running, tm);
      ts_.assign_next(cntv, z3::ite(tm, sat_inc(elapsed, d), I(0)));
      ts_.add_lemma(P + ".timed.running_bound", z3::implies(running, cntv <= d));
      break;
    }
  }

  // C.8 reads, C.7 latch, C.8 active.
  expr hard = cz.bypass_tag ? bool_read(*cz.bypass_tag, self) : B(false);
  expr inhibited = cz.inhibit_tag ? bool_read(*cz.inhibit_tag, self) : B(false);
  expr bypassed = hard || sb;
  expr latch_now = B(false);
  bool has_latch = !cz.auto_ack && (cz.time.mode == model::TimeMode::None ||
                                    cz.time.mode == model::TimeMode::OnDelay);
  if (has_latch) {
    expr latch = bool_state(P + ".ack_latch", false);
    expr cleared = latch && !(cmds.ack && !tr);
    latch_now = cleared || (tm && !bypassed && !inhibited);
    ts_.assign_next(latch, latch_now);
  }
  expr active = (tm || latch_now) && !bypassed && !inhibited;
  cause_active_.emplace(cz.id, active);

  ts_.name_term(P + ".active", active);
  ts_.name_term(P + ".trip_requested", tr);
  ts_.name_term(P + ".tripped_tags", cnt);
  ts_.name_term(P + ".voting", voting);
  ts_.name_term(P + ".degraded", k > 0);
  ts_.name_term(P + ".bypassed", bypassed);
  ts_.name_term(P + ".soft_bypassed", sb);
  ts_.name_term(P + ".inhibited", inhibited);
  ts_.name_term(P + ".ack_required", latch_now);
  ts_.name_term(P + ".hysteresis_active",
                analog ? expr(hyst_mode && tr && !tr_strict) : B(false));
  ts_.name_term(P + ".delta_alarm", delta_alarm);
  ts_.name_term(P + ".prewarning", prewarning);
  ts_.name_term(P + ".timer_running", timer_running);
  ts_.name_term(P + ".bypass_timeout", bypass_timeout);
  ts_.name_term(P + ".bypass_prealarm", bypass_prealarm);
  if (cz.first_out_group >= 1 && cz.first_out_group <= model::kMaxFirstOutGroup)
    first_out_groups_[cz.first_out_group].emplace_back(cz.id, active);
  else
    ts_.name_term(P + ".first_out", B(false));
}

// ---- Phase 4: first out (C.11) -------------------------------------------------

void Builder::build_first_out() {
  for (auto& [group, members] : first_out_groups_) {
    std::sort(members.begin(), members.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    expr clear = clear_first_out_.at(group);
    std::vector<expr> held, became, vars;
    for (auto& [id, active] : members) {
      std::string P = cause_prefix(id);
      vars.push_back(bool_state(P + ".first_out", false));
      held.push_back(vars.back() && !clear);
      expr was = bool_state(P + ".active_prev", false);
      ts_.assign_next(was, active);
      became.push_back(active && !was);
    }
    expr holds = any(held);
    expr earlier = B(false);
    for (std::size_t i = 0; i < members.size(); ++i) {
      expr now = held[i] || (!holds && became[i] && !earlier);
      earlier = earlier || became[i];
      ts_.assign_next(vars[i], now);
      ts_.name_term(cause_prefix(members[i].first) + ".first_out", now);
    }
  }
}

// ---- Phase 3: effects -------------------------------------------------------------

void Builder::build_effect(const model::Effect& ef) {
  const Node self{Node::Kind::Effect, ef.id};
  const std::string P = effect_prefix(ef.id);
  EffectCommands& cmds = effect_cmds_.at(ef.id);

  // E.2: requests per intersection type.
  std::map<model::IntersectionType, std::vector<expr>> direct;
  std::vector<expr> xoon_members;
  std::optional<model::IntersectionType> xoon_type;
  int xoon_x = 0;
  std::vector<std::pair<int, expr>> linked;
  for (const auto* is : m_.intersections_of_effect(ef.id)) {
    if (!model::is_processed(is->type)) continue;
    const model::Cause* cz = m_.find_cause(is->cause);
    if (!cz || cz->function == model::CauseFunction::Comment) continue;
    auto it = cause_active_.find(is->cause);
    if (it == cause_active_.end()) throw std::logic_error("cause read before evaluation");
    linked.emplace_back(is->cause, it->second);
    if (is->xoon) {
      xoon_members.push_back(it->second);
      xoon_type = is->type;
      xoon_x = xoon_x == 0 ? *is->xoon : std::min(xoon_x, *is->xoon);
    } else {
      direct[is->type].push_back(it->second);
    }
  }
  auto req = [&](model::IntersectionType t) {
    std::vector<expr> parts = direct[t];
    if (xoon_type && *xoon_type == t) parts.push_back(count(xoon_members) >= xoon_x);
    return any(parts);
  };
  expr reqN = req(model::IntersectionType::N);
  expr reqS = req(model::IntersectionType::S);
  expr reqV = req(model::IntersectionType::V);
  expr reqR = req(model::IntersectionType::R);

  // E.1: reads.
  expr hard = ef.bypass_tag ? bool_read(*ef.bypass_tag, self) : B(false);
  expr bypassed = hard || cmds.sb_on;
  expr toggle = cmds.toggle;
  if (ef.reset_tag) toggle = edge_of("prev." + P + ".reset_tag", bool_read(*ef.reset_tag, self));
  expr od_prev = bool_state(P + ".output_delay_running_prev", false);

  // E.3: override.
  expr ov_now = B(false), fail_t = B(false), fail_c = B(false), prealarm = B(false);
  expr was_running = B(false);
  expr reset = cmds.reset;
  if (ef.override_time) {
    const int d = cycles_of(std::uint64_t{ef.override_time->max_s} * 1000, m_.cycle_ms);
    expr ov = bool_state(P + ".override", false);
    was_running = ov;
    expr cntv = counter(P + ".override.elapsed", d);
    expr alarm_t = bool_state(P + ".override_failed_timeout", false);
    expr alarm_c = bool_state(P + ".override_failed_cause", false);
    expr running = ov && !gd_;  // M.2
    std::vector<expr> newcomers;
    std::vector<std::pair<expr, expr>> snaps;  // (state, active)
    for (auto& [cid, a] : linked) {
      expr snap = bool_state(P + ".override.started_with[" + std::to_string(cid) + "]", false);
      snaps.emplace_back(snap, a);
      newcomers.push_back(a && !snap);
    }
    // Step 1: end conditions.
    expr timeout = running && cntv >= d;
    expr by_cause = running && any(newcomers);
    expr gone = running && !(reqV || reqR);
    running = running && !timeout && !by_cause && !gone;
    // Step 2: toggle.
    expr stop = toggle && running;
    expr start = toggle && !running && (reqV || reqR) && !bypassed && !od_prev;
    reset = reset || (toggle && !running && !start);
    running = (running && !stop) || start;
    ov_now = running;
    expr elapsed = z3::ite(start, I(0), cntv);
    fail_t = !start && ((alarm_t && !cmds.clear_alarms) || timeout);
    fail_c = !start && ((alarm_c && !cmds.clear_alarms) || by_cause);
    if (ef.override_time->prealarm_s > 0) {
      const int pre = cycles_of(std::uint64_t{ef.override_time->prealarm_s} * 1000, m_.cycle_ms);
      prealarm = running && elapsed >= pre;
    }
    for (auto& [snap, a] : snaps) ts_.assign_next(snap, z3::ite(start, a, snap));
    ts_.assign_next(ov, running);
    ts_.assign_next(cntv, z3::ite(running, sat_inc(elapsed, d), I(0)));
    ts_.assign_next(alarm_t, fail_t);
    ts_.assign_next(alarm_c, fail_c);
  } else {
    reset = reset || toggle;
  }

  // E.4 reset, E.5 latches.
  expr s_latch = bool_state(P + ".s_latch", false);
  expr r_latch = bool_state(P + ".r_latch", false);
  expr req_r_prev = bool_state(P + ".req_r_prev", false);
  expr s_now = (s_latch && !(reset && !reqS && !od_prev)) || reqS;
  expr r_now = ((r_latch && !(reset && !reqR && !od_prev)) || reqR) &&
               !(req_r_prev && !reqR && was_running);
  ts_.assign_next(s_latch, s_now);
  ts_.assign_next(r_latch, r_now);
  ts_.assign_next(req_r_prev, reqR);
  expr latched = s_now || r_now;

  // E.6 active.
  expr active = (reqN || s_now || ((reqV || r_now) && !ov_now)) && !bypassed;
  effect_active_.emplace(ef.id, active);

  // E.7 output delay.
  expr os = active;
  const int od = cycles_of(ef.output_delay_ms, m_.cycle_ms);
  if (od > 0) {
    expr os_prev = bool_state(P + ".output_state_prev", false);
    expr held = counter(P + ".output_delay.elapsed", od);  // cycles active before this one
    os = active && (os_prev || first_ || held >= od);
    ts_.assign_next(os_prev, os);
    ts_.assign_next(held, z3::ite(active, sat_inc(held, od), I(0)));
  }
  expr od_running = active && !os;
  ts_.assign_next(od_prev, od_running);

  // E.8 pass-through and mask, E.9 outputs, E.10 output simulation.
  bool pass = false, has_mask = false;
  expr process = B(false), mask = B(false);
  if (ef.process_data && ef.process_data->tag) {
    process = bool_read(*ef.process_data->tag, self);
    pass = ef.process_data->pass_through;
    if (ef.process_data->mask_tag) {
      has_mask = true;
      mask = bool_read(*ef.process_data->mask_tag, self);
    }
  }
  for (std::size_t j = 0; j < ef.tags.size(); ++j) {
    const auto& tag = ef.tags[j];
    expr safe = B(tag.ett);
    expr logic = tag.ett ? os : !os;
    expr pv = tag.ett ? !process : process;
    expr out = logic;
    if (pass && has_mask) out = z3::ite(os, z3::ite(mask, pv, safe), pv);
    else if (pass) out = z3::ite(os, safe, pv);
    else if (has_mask) out = z3::ite(mask, pv, logic);
    const Simulation& s = sims_.at(model::tag_key(tag.name));
    out = z3::ite(s.on, s.value, out);
    effect_tag_.emplace(std::make_pair(ef.id, static_cast<int>(j + 1)), out);
    ts_.name_term(P + ".tag[" + std::to_string(j + 1) + "]", out);
  }

  ts_.name_term(P + ".active", active);
  ts_.name_term(P + ".latched", latched);
  ts_.name_term(P + ".ok_to_reset", latched && !reqS && !reqR && !od_running);
  ts_.name_term(P + ".override_active", ov_now);
  ts_.name_term(P + ".override_failed_timeout", fail_t);
  ts_.name_term(P + ".override_failed_cause", fail_c);
  ts_.name_term(P + ".override_prealarm", prealarm);
  ts_.name_term(P + ".bypassed", bypassed);
  ts_.name_term(P + ".soft_bypassed", cmds.sb_on);
  ts_.name_term(P + ".masked", has_mask ? mask : B(false));
  ts_.name_term(P + ".pass_through_active", pass ? expr(!os) : B(false));
  ts_.name_term(P + ".output_delay_running", od_running);
}

// I.4: previous-cycle copies of references that close a cycle.
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

}  // namespace

std::unique_ptr<Encoding> encode(z3::context& ctx, const model::Matrix& m,
                                 const std::vector<Node>& roots) {
  auto enc = std::make_unique<Encoding>(ctx);
  Builder b(ctx, m, *enc);
  b.build(roots);
  enc->ts.check_complete();
  return enc;
}

}  // namespace cemv::encoder
