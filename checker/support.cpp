#include "checker/support.hpp"

#include <algorithm>
#include <string>

#include "model/validate.hpp"

namespace cemv::checker {

namespace {

std::string cause_key(int id) { return "cause[" + std::to_string(id) + "]"; }
std::string effect_key(int id) { return "effect[" + std::to_string(id) + "]"; }

bool in_cone(const std::vector<model::Node>& cone, model::Node::Kind kind, int id) {
  return std::any_of(cone.begin(), cone.end(), [&](const model::Node& n) { return n.kind == kind && n.id == id; });
}

model::Cause* cause_of(model::Matrix& m, int id) {
  for (auto& c : m.causes) if (c.id == id) return &c;
  return nullptr;
}
model::Effect* effect_of(model::Matrix& m, int id) {
  for (auto& e : m.effects) if (e.id == id) return &e;
  return nullptr;
}

void add_cause_options(const model::Cause& c, std::vector<Deletion>& out) {
  const int id = c.id;
  auto option = [&](const std::string& field, const std::string& what, std::function<void(model::Cause&)> edit) {
    out.push_back({{cause_key(id) + "." + field, what},
                   [id, edit](model::Matrix& m) { if (auto* x = cause_of(m, id)) edit(*x); }});
  };
  if (c.bypass_tag) option("bypass_tag", "bypass tag " + *c.bypass_tag, [](model::Cause& x) { x.bypass_tag.reset(); });
  if (c.inhibit_tag) option("inhibit_tag", "inhibit tag " + *c.inhibit_tag, [](model::Cause& x) { x.inhibit_tag.reset(); });
  if (c.time.mode != model::TimeMode::None)
    option("time", "time function", [](model::Cause& x) { x.time = model::TimeFunction{}; });
  if (!c.auto_ack) option("auto_ack", "manual acknowledgement", [](model::Cause& x) { x.auto_ack = true; });
}

void add_effect_options(const model::Effect& e, std::vector<Deletion>& out) {
  const int id = e.id;
  auto option = [&](const std::string& field, const std::string& what, std::function<void(model::Effect&)> edit) {
    out.push_back({{effect_key(id) + "." + field, what},
                   [id, edit](model::Matrix& m) { if (auto* x = effect_of(m, id)) edit(*x); }});
  };
  if (e.bypass_tag) option("bypass_tag", "bypass tag " + *e.bypass_tag, [](model::Effect& x) { x.bypass_tag.reset(); });
  if (e.reset_tag) option("reset_tag", "reset tag " + *e.reset_tag, [](model::Effect& x) { x.reset_tag.reset(); });
  if (e.output_delay_ms != 0)
    option("output_delay_ms", "output delay", [](model::Effect& x) { x.output_delay_ms = 0; });
  if (e.override_time) option("override", "override time", [](model::Effect& x) { x.override_time.reset(); });
  if (e.process_data) option("process_data", "pass-through / mask", [](model::Effect& x) { x.process_data.reset(); });
}

}  // namespace

std::vector<Deletion> candidate_deletions(const model::Matrix& m, const std::vector<model::Node>& cone) {
  std::vector<Deletion> out;
  for (const auto& x : m.intersections) {
    if (!in_cone(cone, model::Node::Kind::Effect, x.effect)) continue;
    const int c = x.cause, e = x.effect;
    out.push_back({{"intersection[" + std::to_string(c) + "," + std::to_string(e) + "]",
                    std::string("intersection ") + model::to_string(x.type) + " of " + cause_key(c) + " and " + effect_key(e)},
                   [c, e](model::Matrix& mm) {
                     std::erase_if(mm.intersections, [&](const model::Intersection& y) { return y.cause == c && y.effect == e; });
                   }});
  }
  for (const auto& c : m.causes)
    if (in_cone(cone, model::Node::Kind::Cause, c.id)) add_cause_options(c, out);
  for (const auto& e : m.effects)
    if (in_cone(cone, model::Node::Kind::Effect, e.id)) add_effect_options(e, out);
  return out;
}

std::vector<SupportElement> minimal_support(const model::Matrix& m, const std::vector<Deletion>& candidates,
                                            const std::function<ReproveOutcome(const model::Matrix&)>& reprove,
                                            bool& minimal, model::Matrix* reduced) {
  minimal = true;
  model::Matrix current = m;
  std::vector<SupportElement> kept;
  for (const auto& d : candidates) {
    model::Matrix trial = current;
    d.apply(trial);
    // A deletion that leaves an invalid matrix (e.g. an XooN group losing a
    // member) is no matrix a user could have: the element stays.
    if (model::has_errors(model::validate(trial))) {
      kept.push_back(d.element);
      continue;
    }
    ReproveOutcome r = reprove(trial);
    if (r == ReproveOutcome::Proved) {
      current = std::move(trial);
      continue;
    }
    if (r == ReproveOutcome::Undecided) minimal = false;
    kept.push_back(d.element);
  }
  if (reduced) *reduced = std::move(current);
  return kept;
}

}  // namespace cemv::checker
