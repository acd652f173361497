// The observable groups of checker/equivalence.hpp and the verdict's text:
// plain functions of the two matrices, kept apart from decide_equivalence so
// that a test double of the decision (tests/cli/change_double) replaces only
// the decision and links these as they are.
#include <functional>
#include <map>
#include <set>

#include "checker/equivalence.hpp"

namespace cemv::checker {

namespace {

using model::Node;

void add_keys(std::vector<std::string>& keys, std::set<std::string>& seen, const std::vector<model::Observable>& obs,
              const std::function<bool(const model::Observable&)>& take) {
  for (const auto& o : obs)
    if (take(o) && seen.insert(o.key).second) keys.push_back(o.key);
}

}  // namespace

const char* to_string(EquivalenceVerdict v) {
  switch (v) {
    case EquivalenceVerdict::Equivalent: return "equivalent";
    case EquivalenceVerdict::Differs: return "differs";
    case EquivalenceVerdict::Unknown: return "unknown";
  }
  return "unknown";
}

// An effect's keys are the union of both matrices' (an output tag added or
// removed is a key only one has: the group then differs by interface).
std::vector<ObservableGroup> effect_groups(const model::Matrix& a, const model::Matrix& b) {
  std::set<int> ids;
  for (const auto* m : {&a, &b})
    for (const auto& e : m->effects) ids.insert(e.id);
  const auto oa = model::observables(a), ob = model::observables(b);
  std::vector<ObservableGroup> out;
  for (int id : ids) {
    ObservableGroup g;
    g.name = model::to_string(Node{Node::Kind::Effect, id});
    g.roots = {Node{Node::Kind::Effect, id}};
    std::set<std::string> seen;
    auto mine = [id](const model::Observable& o) { return o.kind == Node::Kind::Effect && o.id == id; };
    add_keys(g.keys, seen, oa, mine);
    add_keys(g.keys, seen, ob, mine);
    out.push_back(std::move(g));
  }
  return out;
}

std::vector<ObservableGroup> output_groups(const model::Matrix& a, const model::Matrix& b) {
  std::map<std::pair<int, int>, std::string> tags;  // (effect, k) -> key
  for (const auto* m : {&a, &b})
    for (const auto& o : model::observables(*m))
      if (o.kind == Node::Kind::Effect && o.field == "tag") tags.emplace(std::make_pair(o.id, o.tag), o.key);
  std::vector<ObservableGroup> out;
  for (const auto& [where, key] : tags)
    out.push_back(ObservableGroup{key, {key}, {Node{Node::Kind::Effect, where.first}}});
  return out;
}

ObservableGroup whole_matrix(const model::Matrix& a, const model::Matrix& b) {
  ObservableGroup g;
  g.name = "matrix";
  std::set<std::string> seen;
  auto all = [](const model::Observable&) { return true; };
  add_keys(g.keys, seen, model::observables(a), all);
  add_keys(g.keys, seen, model::observables(b), all);
  return g;
}

}  // namespace cemv::checker
