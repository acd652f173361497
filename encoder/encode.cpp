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

expr Reads::raw_value(std::size_t index) {
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

expr Reads::raw_bad(std::size_t index) {
  auto it = raw_bad_.find(index);
  if (it != raw_bad_.end()) return it->second;
  const auto& tag = enc_.inputs.tags()[index];
  expr v = ts_.make_inputvar("input." + tag.name + ".bad", c_.bool_sort());
  enc_.tag_bad[index] = v;
  return raw_bad_.emplace(index, v).first->second;
}

// T.4: a rising edge needs the previous value; none in cycle 1.
expr Reads::edge_of(const std::string& state_name, const expr& now) {
  expr prev = bool_state(state_name, false);
  ts_.assign_next(prev, now);
  return now && !prev && !first_;
}

expr Reads::ref_value(const model::InternalRef& r, const std::optional<Node>& reader) {
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

expr Reads::bool_read(const std::string& name, const std::optional<Node>& reader) {
  if (auto ref = model::parse_internal_ref(name)) return ref_value(*ref, reader);
  auto idx = enc_.inputs.find(name);
  if (!idx) throw std::logic_error("tag not in the input table: " + name);
  expr v = raw_value(*idx);
  if (v.is_fpa()) return !fp_eq(v, fconst(0.0f));  // I.1: non-zero is TRUE
  return v;
}

// ---- Phase 1: matrix level -----------------------------------------------------

void Reads::build_matrix_level() {
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

void Reads::finish_previous_refs() {
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
  Reads reads(c_, m_, enc_, guard_cells_);
  const auto& order = reads.graph().evaluation_order();
  std::set<Node> cone;
  if (roots.empty()) {
    cone.insert(order.begin(), order.end());
  } else {
    auto feeders = reads.graph().feeders_of(roots);
    cone.insert(feeders.begin(), feeders.end());
  }
  // References read from outside the cone still need their source's value:
  // feeders_of includes them (the graph has an edge per reference).
  std::vector<const model::Cause*> causes;
  std::vector<const model::Effect*> effects;
  for (const auto& cz : m_.causes)
    if (cz.function != model::CauseFunction::Comment && cone.count({Node::Kind::Cause, cz.id}))
      causes.push_back(&cz);
  for (const auto& ef : m_.effects)
    if (ef.function != model::EffectFunction::Comment && cone.count({Node::Kind::Effect, ef.id}))
      effects.push_back(&ef);

  reads.build_matrix_level();
  const CommandStates commands = CommandEncoder(c_, m_, enc_, guard_cells_, reads, causes, effects).encode();
  CauseEncoder cause_encoder(c_, m_, enc_, guard_cells_, reads, commands);
  EffectEncoder effect_encoder(c_, m_, enc_, guard_cells_, reads, commands);
  for (const Node& n : order) {
    if (!cone.count(n)) continue;
    enc_.nodes.push_back(n);
    if (n.kind == Node::Kind::Cause) cause_encoder.build_cause(*m_.find_cause(n.id));
    else effect_encoder.build_effect(*m_.find_effect(n.id));
  }
  cause_encoder.build_first_out();
  reads.finish_previous_refs();
  for (const auto& o : model::observables(m_))
    if (cone.count(Node{o.kind, o.id}) && enc_.ts.term(o.key)) enc_.observables.push_back(o);
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