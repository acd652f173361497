#include "response/paths.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "model/vocabulary.hpp"

namespace cemv::response {

using model::Cause;
using model::Effect;
using model::Node;

namespace {

// One way from trigger causes to an element.
struct Route {
  std::vector<int> causes;
  int needed = 1;
  std::set<Node> elements;
  long long estimate = 0;
  std::set<int> groups;  // SIF groups of the causes on the route (triggers and relays)
};

class Walker {
 public:
  explicit Walker(const model::Matrix& m) : m_(m), graph_(m) {}

  // The routes into effect e (its own output delay not included).
  std::vector<Route> into_effect(int id) {
    std::vector<Route> out;
    const Effect* e = m_.find_effect(id);
    if (!e || e->function == model::EffectFunction::Comment || on_stack(Node{Node::Kind::Effect, id})) return out;
    stack_.push_back({Node::Kind::Effect, id});
    std::vector<const model::Intersection*> xoon;
    for (const auto* x : m_.intersections_of_effect(id)) {
      if (!model::is_processed(x->type) || x->type == model::IntersectionType::X) continue;
      if (x->xoon) {
        xoon.push_back(x);
        continue;
      }
      for (Route r : into_cause(x->cause)) {
        r.elements.insert({Node::Kind::Effect, id});
        out.push_back(std::move(r));
      }
    }
    // An XooN assignment is one path, triggered by X of its causes; its
    // causes must be triggers themselves (a relay in an XooN is not followed).
    if (!xoon.empty()) {
      Route r;
      r.needed = *xoon.front()->xoon;
      bool all_start = true;
      for (const auto* x : xoon) {
        r.needed = std::min(r.needed, *x->xoon);
        const Cause* c = m_.find_cause(x->cause);
        if (!c || !is_start(*c)) {
          all_start = false;
          break;
        }
        r.causes.push_back(c->id);
        r.elements.insert({Node::Kind::Cause, c->id});
        r.groups.insert(c->sif.begin(), c->sif.end());
        r.estimate = std::max(r.estimate, own_delay(*c));
      }
      if (all_start) {
        r.elements.insert({Node::Kind::Effect, id});
        out.push_back(std::move(r));
      }
    }
    stack_.pop_back();
    return out;
  }

 private:
  const model::Matrix& m_;
  model::DependencyGraph graph_;
  std::vector<Node> stack_;

  bool on_stack(const Node& n) const { return std::find(stack_.begin(), stack_.end(), n) != stack_.end(); }

  // A trigger: enough external input tags for the voting.
  static bool is_start(const Cause& c) {
    return c.function != model::CauseFunction::Comment &&
           static_cast<int>(external_tags(c).size()) >= votes_needed(c);
  }
  // Whether the reference tag trips its cause when the referenced element is
  // active, so that a demand upstream travels on (I.3, C.3). `Cause[x]` and
  // `Effect[x]` read 1 when active: only an energize-to-trip tag trips on
  // that. `Effect[x][y]` reads output tag y, which is at its safe value when
  // the effect responds (E.9): the tag trips on it when both have the same
  // `ett`. Otherwise the upstream demand *releases* the cause (a permissive
  // read the other way round): no route of a demand.
  bool trips_when_active(const model::CauseTag& t, const model::InternalRef& ref) const {
    if (ref.kind != model::InternalRef::Kind::EffectTag) return t.ett;
    const Effect* e = m_.find_effect(ref.id);
    if (!e || ref.tag < 1 || static_cast<std::size_t>(ref.tag) > e->tags.size()) return false;
    return e->tags[static_cast<std::size_t>(ref.tag) - 1].ett == t.ett;
  }
  long long own_delay(const Cause& c) const {
    return c.time.mode == model::TimeMode::OnDelay ? cycles_of(c.time.ms, m_.cycle_ms) : 0;
  }

  std::vector<Route> into_cause(int id) {
    std::vector<Route> out;
    const Cause* c = m_.find_cause(id);
    const Node self{Node::Kind::Cause, id};
    if (!c || c->function == model::CauseFunction::Comment || on_stack(self)) return out;
    if (is_start(*c)) {
      Route r;
      r.causes = {id};
      r.elements = {self};
      r.estimate = own_delay(*c);
      r.groups.insert(c->sif.begin(), c->sif.end());
      out.push_back(std::move(r));
    }
    // A voting over other causes only (and of Cause[x], 2oo3 of Cause[x]):
    // one path whose trigger is X of those causes, as an XooN assignment.
    if (votes_needed(*c) > 1) {
      Route r;
      r.needed = votes_needed(*c);
      for (const auto& t : c->tags) {
        auto ref = model::parse_internal_ref(t.name);
        const Cause* up = ref && ref->kind == model::InternalRef::Kind::Cause && t.ett ? m_.find_cause(ref->id) : nullptr;
        if (!up || !is_start(*up) || !votes_needed(*up)) return out;
        r.causes.push_back(up->id);
        r.elements.insert({Node::Kind::Cause, up->id});
        r.groups.insert(up->sif.begin(), up->sif.end());
        r.estimate = std::max(r.estimate, own_delay(*up) + (graph_.reads_previous({Node::Kind::Cause, up->id}, self) ? 1 : 0));
      }
      std::sort(r.causes.begin(), r.causes.end());
      r.elements.insert(self);
      r.estimate += own_delay(*c);
      r.groups.insert(c->sif.begin(), c->sif.end());
      out.push_back(std::move(r));
      return out;
    }
    // A relay: one referenced element is enough to trip it (voting 1ooN).
    stack_.push_back(self);
    for (const auto& t : c->tags) {
      auto ref = model::parse_internal_ref(t.name);
      if (!ref || !trips_when_active(t, *ref)) continue;
      std::vector<Route> upstream;
      Node source{ref->kind == model::InternalRef::Kind::Cause ? Node::Kind::Cause : Node::Kind::Effect, ref->id};
      long long extra = graph_.reads_previous(source, self) ? 1 : 0;
      if (ref->kind == model::InternalRef::Kind::Cause) {
        upstream = into_cause(ref->id);
      } else {
        upstream = into_effect(ref->id);
        const Effect* e = m_.find_effect(ref->id);
        if (e && ref->kind == model::InternalRef::Kind::EffectTag) extra += cycles_of(e->output_delay_ms, m_.cycle_ms);
      }
      for (Route r : upstream) {
        r.elements.insert(self);
        r.estimate += extra + own_delay(*c);
        r.groups.insert(c->sif.begin(), c->sif.end());
        out.push_back(std::move(r));
      }
    }
    stack_.pop_back();
    return out;
  }
};

}  // namespace

std::string Path::key() const {
  std::string s = "c";
  // '_' between ids: the key is part of a property name, which the property
  // language reads as an identifier (docs/properties.md).
  for (std::size_t i = 0; i < causes.size(); ++i) s += (i ? "_" : "") + std::to_string(causes[i]);
  return s + ".e" + std::to_string(effect);
}

int votes_needed(const Cause& c) {
  switch (c.function) {
    case model::CauseFunction::Normal: return 1;
    case model::CauseFunction::Or: return 1;
    case model::CauseFunction::And: return static_cast<int>(c.tags.size());
    case model::CauseFunction::TwoOoThree: return 2;
    case model::CauseFunction::Comment: return 0;
  }
  return 1;
}

long long cycles_of(std::uint64_t ms, std::uint32_t cycle_ms) {
  return static_cast<long long>((ms + cycle_ms - 1) / cycle_ms);
}

std::vector<Path> response_paths(const model::Matrix& m, const std::vector<int>& sifs) {
  std::vector<int> groups = sifs;
  if (groups.empty())
    for (const auto& [g, name] : m.sif_groups) groups.push_back(g);
  std::vector<Path> out;
  Walker walker(m);
  for (int g : groups) {
    for (const auto& e : m.effects) {
      if (e.function == model::EffectFunction::Comment || std::find(e.sif.begin(), e.sif.end(), g) == e.sif.end())
        continue;
      // Routes with the same trigger into the same effect are one path: the
      // property quantifies over the whole logic, whichever route answers.
      std::map<std::pair<std::vector<int>, int>, Path> merged;
      for (const Route& r : walker.into_effect(e.id)) {
        if (!r.groups.count(g)) continue;
        Path& p = merged[{r.causes, r.needed}];
        p.sif = g;
        p.causes = r.causes;
        p.needed = r.needed;
        p.effect = e.id;
        for (const auto& n : r.elements)
          if (std::find(p.elements.begin(), p.elements.end(), n) == p.elements.end()) p.elements.push_back(n);
        p.estimate = std::max(p.estimate, r.estimate + cycles_of(e.output_delay_ms, m.cycle_ms));
      }
      for (auto& [key, p] : merged) {
        std::sort(p.elements.begin(), p.elements.end());
        for (int id : p.causes) {
          const Cause* c = m.find_cause(id);
          const std::size_t external = external_tags(*c).size();
          if (external >= 2 && external == c->tags.size()) p.voted.push_back(id);
        }
        out.push_back(std::move(p));
      }
    }
  }
  return out;
}

std::vector<const model::CauseTag*> external_tags(const model::Cause& c) {
  std::vector<const model::CauseTag*> out;
  for (const auto& t : c.tags)
    if (!model::parse_internal_ref(t.name)) out.push_back(&t);
  return out;
}

}  // namespace cemv::response
