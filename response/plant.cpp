#include "response/plant.hpp"

#include <algorithm>

#include "model/vocabulary.hpp"

namespace cemv::response {

using model::Cause;

Holders holders_of(const model::Matrix& m, const Path& p) {
  Holders out;
  for (const auto& n : p.elements) {
    if (n.kind != model::Node::Kind::Cause) continue;
    const Cause& c = *m.find_cause(n.id);
    for (const auto* t : {&c.bypass_tag, &c.inhibit_tag}) {
      const auto ref = *t ? model::parse_internal_ref(**t) : std::nullopt;
      if (!ref) continue;
      if (ref->kind == model::InternalRef::Kind::Cause) out.causes.insert(ref->id);
      if (ref->kind == model::InternalRef::Kind::Effect) out.effects.insert(ref->id);
      if (ref->kind == model::InternalRef::Kind::EffectTag) {
        const model::Effect* x = m.find_effect(ref->id);
        if (x && ref->tag >= 1 && static_cast<std::size_t>(ref->tag) <= x->tags.size())
          (x->tags[ref->tag - 1].ett ? out.effects : out.inactive_effects).insert(x->id);
      }
    }
  }
  return out;
}

std::set<int> effects_on(const Path& p) {
  std::set<int> out;
  for (const auto& n : p.elements)
    if (n.kind == model::Node::Kind::Effect) out.insert(n.id);
  return out;
}

std::set<int> linked_causes(const model::Matrix& m, const Path& p) {
  const std::set<int> effects = effects_on(p);
  std::set<int> out;
  for (const auto& x : m.intersections)
    if (effects.count(x.effect)) out.insert(x.cause);
  return out;
}

bool held_by_logic(const Cause& c) {
  for (const auto* t : {&c.bypass_tag, &c.inhibit_tag})
    if (*t && model::parse_internal_ref(**t)) return true;
  return false;
}

const Cause* activator_of(const model::Matrix& m, int x, const std::set<int>& linked) {
  for (const auto* i : m.intersections_of_effect(x)) {
    const Cause* c = m.find_cause(i->cause);
    if (!c || i->xoon || !model::is_processed(i->type) || i->type == model::IntersectionType::X) continue;
    if (linked.count(c->id) || c->time.mode != model::TimeMode::None || external_tags(*c).size() != c->tags.size())
      continue;
    if (external_tags(*c).empty() || static_cast<int>(c->tags.size()) < votes_needed(*c) || held_by_logic(*c))
      continue;
    return c;
  }
  return nullptr;
}

std::vector<const Cause*> holds_released_by(const model::Matrix& m, const Path& p) {
  const std::set<int> linked = linked_causes(m, p);
  std::vector<const Cause*> out;
  for (int x : holders_of(m, p).inactive_effects)
    if (const Cause* c = activator_of(m, x, linked)) out.push_back(c);
  return out;
}

std::vector<const Cause*> rest_trips_released_by(const model::Matrix& m, const Path& p) {
  const std::set<int> linked = linked_causes(m, p);
  std::set<int> held_active;
  for (int id : linked) {
    if (std::count(p.causes.begin(), p.causes.end(), id)) continue;
    for (const auto& t : m.find_cause(id)->tags) {
      const auto ref = model::parse_internal_ref(t.name);
      if (!ref || (ref->kind != model::InternalRef::Kind::Effect && ref->kind != model::InternalRef::Kind::EffectTag))
        continue;
      const model::Effect* x = m.find_effect(ref->id);
      if (!x) continue;
      bool reads_when_inactive = false;  // the reference's value while x is not active
      if (ref->kind == model::InternalRef::Kind::EffectTag) {
        if (ref->tag < 1 || static_cast<std::size_t>(ref->tag) > x->tags.size()) continue;
        reads_when_inactive = !x->tags[ref->tag - 1].ett;
      }
      if (reads_when_inactive == t.ett) held_active.insert(x->id);  // the trip value (C.3: 1 ETT, 0 DTT)
    }
  }
  std::vector<const Cause*> out;
  for (int x : held_active)
    if (const Cause* c = activator_of(m, x, linked); c && std::find(out.begin(), out.end(), c) == out.end())
      out.push_back(c);
  return out;
}

std::set<std::size_t> hold_off_tags(const model::Matrix& m, const Path& p) {
  // Every tag a path element reads stays as demand_run sets it.
  std::set<std::string> own;
  std::set<int> effects, causes;
  for (const auto& n : p.elements) {
    if (n.kind == model::Node::Kind::Cause) {
      const Cause& c = *m.find_cause(n.id);
      causes.insert(c.id);
      for (const auto& t : c.tags) own.insert(t.name);
      for (const auto* t : {&c.bypass_tag, &c.inhibit_tag})
        if (*t) own.insert(**t);
    } else {
      const model::Effect& e = *m.find_effect(n.id);
      effects.insert(e.id);
      for (const auto* t : {&e.bypass_tag, &e.reset_tag})
        if (*t) own.insert(**t);
      if (e.process_data) {
        if (e.process_data->tag) own.insert(*e.process_data->tag);
        if (e.process_data->mask_tag) own.insert(*e.process_data->mask_tag);
      }
    }
  }
  // The causes of the elements whose activity holds a path cause off are
  // held off too (big_matrix's cause 83 is bypassed while effect 82 is
  // active, which cause 126 activates whenever the pulse of cause 123 ends).
  const Holders holders = holders_of(m, p);
  const model::InputTable table(m);
  std::set<std::size_t> hold_off;
  auto hold = [&](const Cause& c) {
    for (const auto* t : {&c.bypass_tag, &c.inhibit_tag})
      if (*t && !own.count(**t) && !model::parse_internal_ref(**t))
        if (auto index = table.find(**t)) hold_off.insert(*index);
  };
  for (const auto& x : m.intersections) {
    if ((!effects.count(x.effect) && !holders.effects.count(x.effect)) || causes.count(x.cause)) continue;
    if (const Cause* c = m.find_cause(x.cause)) hold(*c);
  }
  for (int id : holders.causes)
    if (const Cause* c = m.find_cause(id); c && !causes.count(id)) hold(*c);
  return hold_off;
}

}  // namespace cemv::response
