#include "defeats/actions.hpp"

#include <algorithm>
#include <set>
#include <tuple>

#include "model/graph.hpp"
#include "model/vocabulary.hpp"

namespace cemv::defeats {

namespace {

std::string quoted(const std::string& tag) {
  std::string s = "\"";
  for (char c : tag) {
    if (c == '"' || c == '\\') s += '\\';
    s += c;
  }
  return s + "\"";
}

bool external(const std::optional<std::string>& tag) { return tag && !model::parse_internal_ref(*tag); }

bool has_override_cell(const model::Matrix& m, int effect) {
  for (const auto& x : m.intersections)
    if (x.effect == effect && (x.type == model::IntersectionType::V || x.type == model::IntersectionType::R)) {
      const model::Cause* c = m.find_cause(x.cause);
      if (c && c->function != model::CauseFunction::Comment) return true;
    }
  return false;
}

std::string effect_word(int id) { return "effect[" + std::to_string(id) + "]"; }

}  // namespace

const char* to_string(ActionKind k) {
  switch (k) {
    case ActionKind::SoftBypassCause: return "soft_bypass_cause";
    case ActionKind::SoftBypassTag: return "soft_bypass_tag";
    case ActionKind::SoftBypassEffect: return "soft_bypass_effect";
    case ActionKind::CauseBypassTag: return "cause_bypass_tag";
    case ActionKind::CauseInhibitTag: return "cause_inhibit_tag";
    case ActionKind::EffectBypassTag: return "effect_bypass_tag";
    case ActionKind::Override: return "override";
    case ActionKind::MaskTag: return "mask_tag";
    case ActionKind::SimulateInput: return "simulate_input";
    case ActionKind::SimulateOutput: return "simulate_output";
    case ActionKind::BadQuality: return "bad_quality";
  }
  return "?";
}

std::string Action::key() const {
  std::string k = to_string(kind);
  switch (kind) {
    case ActionKind::SoftBypassCause: return k + "[" + std::to_string(cause) + "]";
    case ActionKind::SoftBypassTag: return k + "[" + std::to_string(cause) + "," + std::to_string(tag_index) + "]";
    case ActionKind::SoftBypassEffect:
    case ActionKind::Override: return k + "[" + std::to_string(effect) + "]";
    default: return k + "[" + tag + "]";
  }
}

std::string Action::excluded_term() const {
  switch (kind) {
    case ActionKind::SoftBypassCause: return "issued(soft_bypass_cause, cause = " + std::to_string(cause) + ")";
    case ActionKind::SoftBypassTag:
      return "issued(soft_bypass_tag, cause = " + std::to_string(cause) + ", tag = " + std::to_string(tag_index) + ")";
    case ActionKind::SoftBypassEffect: return "issued(soft_bypass_effect, effect = " + std::to_string(effect) + ")";
    // A state, not a command: the override is toggled by the command or by
    // the reset tag's rising edge (E.3), and the reset stays free.
    case ActionKind::Override: return effect_word(effect) + ".override_active";
    case ActionKind::CauseBypassTag:
    case ActionKind::CauseInhibitTag:
    case ActionKind::EffectBypassTag:
    case ActionKind::MaskTag: return quoted(tag);
    case ActionKind::SimulateInput:
    case ActionKind::SimulateOutput: return "issued(simulate_tag, tag = " + quoted(tag) + ")";
    case ActionKind::BadQuality: return "bad(" + quoted(tag) + ")";
  }
  return "false";
}

std::string Action::description(const model::Matrix& m) const {
  auto cause_name = [&](int id) {
    const model::Cause* c = m.find_cause(id);
    return "cause " + std::to_string(id) + (c && !c->name.empty() ? " " + c->name : "");
  };
  auto effect_name = [&](int id) {
    const model::Effect* e = m.find_effect(id);
    return "effect " + std::to_string(id) + (e && !e->name.empty() ? " " + e->name : "");
  };
  switch (kind) {
    case ActionKind::SoftBypassCause: return "soft bypass of " + cause_name(cause);
    case ActionKind::SoftBypassTag:
      return "soft bypass of tag " + std::to_string(tag_index) + " (" + tag + ") of " + cause_name(cause);
    case ActionKind::SoftBypassEffect: return "soft bypass of " + effect_name(effect);
    case ActionKind::CauseBypassTag: return "bypass tag " + tag + " of " + cause_name(cause);
    case ActionKind::CauseInhibitTag: return "inhibit tag " + tag + " of " + cause_name(cause);
    case ActionKind::EffectBypassTag: return "bypass tag " + tag + " of " + effect_name(effect);
    case ActionKind::Override: return "override of " + effect_name(effect);
    case ActionKind::MaskTag: return "mask tag " + tag + " of " + effect_name(effect);
    case ActionKind::SimulateInput: return "simulation of input tag " + tag;
    case ActionKind::SimulateOutput: return "simulation of output tag " + tag;
    case ActionKind::BadQuality: return "bad quality of input tag " + tag;
  }
  return "";
}

std::vector<Action> actions_of(const model::Matrix& m, const response::Path& p) {
  const model::DependencyGraph g(m);
  std::vector<Action> out;
  std::set<std::pair<ActionKind, std::string>> tags_seen;  // one action per tag (case-insensitive)
  auto add_tag_action = [&](Action a) {
    if (tags_seen.insert({a.kind, model::tag_key(a.tag)}).second) out.push_back(std::move(a));
  };
  for (const model::Node& n : g.feeders_of(model::Node{model::Node::Kind::Effect, p.effect})) {
    if (n.kind == model::Node::Kind::Cause) {
      const model::Cause& c = *m.find_cause(n.id);
      if (c.soft_bypass.allowed) out.push_back({ActionKind::SoftBypassCause, c.id, 0, 0, ""});
      if (external(c.bypass_tag)) add_tag_action({ActionKind::CauseBypassTag, c.id, 0, 0, *c.bypass_tag});
      if (external(c.inhibit_tag)) add_tag_action({ActionKind::CauseInhibitTag, c.id, 0, 0, *c.inhibit_tag});
      for (std::size_t k = 0; k < c.tags.size(); ++k) {
        const model::CauseTag& t = c.tags[k];
        if (model::parse_internal_ref(t.name)) continue;
        if (t.soft_bypass_allowed)
          out.push_back({ActionKind::SoftBypassTag, c.id, 0, static_cast<int>(k + 1), t.name});
        if (t.simulation_allowed) add_tag_action({ActionKind::SimulateInput, c.id, 0, 0, t.name});
        add_tag_action({ActionKind::BadQuality, c.id, 0, 0, t.name});
      }
    } else {
      const model::Effect& e = *m.find_effect(n.id);
      if (e.soft_bypass_allowed) out.push_back({ActionKind::SoftBypassEffect, 0, e.id, 0, ""});
      if (external(e.bypass_tag)) add_tag_action({ActionKind::EffectBypassTag, 0, e.id, 0, *e.bypass_tag});
      if (e.override_time && has_override_cell(m, e.id)) out.push_back({ActionKind::Override, 0, e.id, 0, ""});
      if (e.process_data && e.process_data->tag && e.process_data->mask_tag && external(e.process_data->mask_tag))
        add_tag_action({ActionKind::MaskTag, 0, e.id, 0, *e.process_data->mask_tag});
      for (const auto& t : e.tags)
        if (t.simulation_allowed) add_tag_action({ActionKind::SimulateOutput, 0, e.id, 0, t.name});
    }
  }
  return out;
}

bool declared_for(const model::Matrix& m, const response::Path& p, const Action& a) {
  // The path's own elements: its trigger causes and its effect. A relay or
  // an intermediate effect of a chain is another element (I.3): an
  // operation on it acts through an internal reference.
  const auto own_cause = [&](int id) { return std::count(p.causes.begin(), p.causes.end(), id) > 0; };
  const auto own_cause_reads = [&](bool bypass) {
    // A shared tag: declared when it takes some own cause out.
    for (int id : p.causes) {
      const model::Cause& c = *m.find_cause(id);
      const auto& t = bypass ? c.bypass_tag : c.inhibit_tag;
      if (t && model::tag_key(*t) == model::tag_key(a.tag)) return true;
    }
    return false;
  };
  switch (a.kind) {
    case ActionKind::SoftBypassCause:
    case ActionKind::SoftBypassTag: return own_cause(a.cause);
    case ActionKind::CauseBypassTag: return own_cause_reads(true);
    case ActionKind::CauseInhibitTag: return own_cause_reads(false);
    case ActionKind::SoftBypassEffect:
    case ActionKind::Override:
    case ActionKind::EffectBypassTag:
    case ActionKind::MaskTag: return a.effect == p.effect;
    // A simulation of an own cause's input or of the effect's output is an
    // operation on that element (it stops it seeing or driving the plant).
    case ActionKind::SimulateInput:
      for (int id : p.causes)
        for (const auto& t : m.find_cause(id)->tags)
          if (model::tag_key(t.name) == model::tag_key(a.tag)) return true;
      return false;
    case ActionKind::SimulateOutput:
      for (const auto& t : m.find_effect(p.effect)->tags)
        if (model::tag_key(t.name) == model::tag_key(a.tag)) return true;
      return false;
    case ActionKind::BadQuality: return false;  // a fault
  }
  return false;
}

}  // namespace cemv::defeats
