// TEST DOUBLE of checker/equivalence.hpp (see README.md): every function the
// real header declares, defined here so that the linker never takes the real
// equivalence.o from cemv_checker. The verdict is chosen by a word in a name.
#include <algorithm>
#include <cctype>
#include <set>
#include <string>

#include "checker/equivalence.hpp"
#include "checker/prover.hpp"
#include "cli/commands.hpp"

namespace cemv::checker {

namespace {

bool has(std::string s, const char* word) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s.find(word) != std::string::npos;
}

std::vector<std::string> keys_of(const model::Matrix& m, const model::Node& n) {
  std::vector<std::string> out;
  for (const auto& o : model::observables(m))
    if (o.kind == n.kind && o.id == n.id) out.push_back(o.key);
  return out;
}

}  // namespace

const char* to_string(EquivalenceVerdict v) {
  switch (v) {
    case EquivalenceVerdict::Equivalent: return "equivalent";
    case EquivalenceVerdict::Differs: return "differs";
    case EquivalenceVerdict::Unknown: return "unknown";
  }
  return "?";
}

std::vector<ObservableGroup> effect_groups(const model::Matrix& a, const model::Matrix& b) {
  std::set<int> ids;
  for (const auto* m : {&a, &b})
    for (const auto& e : m->effects) ids.insert(e.id);
  std::vector<ObservableGroup> out;
  for (int id : ids) {
    const model::Node n{model::Node::Kind::Effect, id};
    ObservableGroup g{"effect[" + std::to_string(id) + "]", keys_of(a.find_effect(id) ? a : b, n), {n}};
    out.push_back(std::move(g));
  }
  return out;
}

std::vector<ObservableGroup> output_groups(const model::Matrix&, const model::Matrix&) { return {}; }

ObservableGroup whole_matrix(const model::Matrix& a, const model::Matrix&) {
  ObservableGroup g;
  g.name = "matrix";
  for (const auto& o : model::observables(a)) g.keys.push_back(o.key);
  return g;
}

GroupEquivalence decide_equivalence(const model::Matrix& a, const model::Matrix& b, const ObservableGroup& group,
                                    const EquivalenceOptions&) {
  std::string name = a.name;
  if (!group.roots.empty()) {
    const int id = group.roots.front().id;
    const model::Effect* e = b.find_effect(id) ? b.find_effect(id) : a.find_effect(id);
    name = e ? e->name : "";
  }
  if (has(name, "internal"))
    throw InternalError("equivalence of " + group.name + ": the runtimes do not reproduce the distinguishing run "
                        "(test double)");
  GroupEquivalence r;
  r.group = group.name;
  if (has(name, "undecided")) {
    r.verdict = EquivalenceVerdict::Unknown;
    r.method = "test double";
    r.reason = "time limit";
    return r;
  }
  r.verdict = EquivalenceVerdict::Equivalent;
  r.method = "test double";
  return r;
}

}  // namespace cemv::checker

// The commands main.cpp registers beside diff and mutate under
// CEMV_WITH_VERIFICATION, absent from this double.
namespace cemv::cli {
void add_response_commands(CLI::App&, Context&) {}
void add_evidence_commands(CLI::App&, Context&) {}
}  // namespace cemv::cli
