#include "checker/localize.hpp"

#include <memory>
#include <string_view>
#include <unordered_set>

#include "checker/check/recheck.hpp"
#include "checker/reduce.hpp"
#include "checker/reduce_terms.hpp"

namespace cemv::checker {

namespace {

// What the localized problem owns: the original (whose context the terms live
// in) and the new transition system.
struct Localized {
  std::shared_ptr<void> original;
  encoder::TransitionSystem ts;
};

}  // namespace

KeepState keep_elements(const std::vector<model::Node>& elements) {
  std::unordered_set<std::string> keys;
  for (const auto& n : elements) keys.insert(model::to_string(n));
  return [keys = std::move(keys)](const std::string& state_name) {
    std::string_view name = state_name;
    if (name.starts_with("prev.")) name.remove_prefix(5);
    if (!name.starts_with("cause[") && !name.starts_with("effect[")) return true;
    const auto close = name.find(']');
    return close == std::string_view::npos || keys.count(std::string(name.substr(0, close + 1))) > 0;
  };
}

std::optional<OwnedProblem> localize(const OwnedProblem& original, const KeepState& keep, Localization* what) {
  const auto& ts = *original.problem.ts;
  z3::context& c = ts.ctx();
  std::vector<const encoder::TransitionSystem::StateVar*> kept, freed;
  for (const auto& s : ts.statevars()) (keep(s.name) ? kept : freed).push_back(&s);
  if (freed.empty()) return std::nullopt;
  auto owner = std::make_shared<Localized>(Localized{original.owner, encoder::TransitionSystem(c)});
  encoder::TransitionSystem& l = owner->ts;
  // A variable is a Z3 constant of its name and sort, so re-declaring it in
  // the new system gives the very term the original's formulas use: nothing
  // needs rewriting.
  for (const auto& in : ts.inputvars()) l.make_inputvar(in.name, in.var.get_sort());
  for (const auto* s : freed) l.make_inputvar(s->name, s->var.get_sort());
  for (const auto* s : kept) {
    z3::expr v = l.make_statevar(s->name, s->var.get_sort());
    l.set_init(v, s->init);
    l.assign_next(v, s->next);
  }
  // Constraints restrict a cycle's values; over freed variables they only
  // restrict the new inputs, which every original run meets.
  for (const auto& k : ts.constraints()) l.add_constraint(k.name, k.term);
  for (const auto& t : ts.named_terms()) l.name_term(t.name, t.term);
  // A lemma about a freed variable no longer holds of an input.
  for (const auto& lemma : ts.lemmas()) {
    const std::unordered_set<unsigned> vars = reduce_terms::variables_of(lemma.term);
    bool inside = true;
    for (const auto* s : freed) inside = inside && !vars.count(s->var.id());
    if (inside) l.add_lemma(lemma.name, lemma.term);
  }
  l.check_complete();
  OwnedProblem localized{owner, SafetyProblem{&owner->ts, original.problem.good, original.problem.assumption}};
  Reduction r;
  OwnedProblem out = reduce(localized, &r);
  if (what) {
    what->state_vars_before = ts.statevars().size();
    what->freed = freed.size();
    what->state_vars_after = r.state_vars_after;
  }
  return out;
}

std::optional<Trace> concretize(const SafetyProblem& original, const Trace& localized) {
  // The inputs by name (one the localized cone dropped keeps its value at
  // rest), the freed variables computed by their own next-state functions:
  // the same lifting as a reduced trace's.
  Trace out = lift_trace(original, localized);
  try {
    check::replay_counterexample(original, out);
  } catch (const InternalError&) {
    return std::nullopt;  // spurious: the freed variables were needed
  }
  return out;
}

}  // namespace cemv::checker
