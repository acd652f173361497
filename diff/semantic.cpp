#include "diff/semantic.hpp"

#include <algorithm>
#include <map>
#include <optional>

#include "checker/work_queue.hpp"
#include "checker/prover.hpp"
#include "checker/replay.hpp"
#include "model/graph.hpp"
#include "runtime/runtime.hpp"

namespace cemv::diff {

namespace {

using checker::EquivalenceVerdict;
using model::Node;

// The cones of one version's effects, on one dependency graph (built once:
// a 128 x 128 matrix has 128 effects to ask about).
class Cones {
 public:
  explicit Cones(const model::Matrix& m) : m_(m), g_(m) {}
  std::set<int> causes(int effect) const { return of(effect, Node::Kind::Cause); }
  std::set<int> effects(int effect) const {
    std::set<int> out = of(effect, Node::Kind::Effect);
    out.insert(effect);
    return out;
  }

 private:
  std::set<int> of(int effect, Node::Kind kind) const {
    std::set<int> out;
    const model::Effect* e = m_.find_effect(effect);
    if (!e || e->function == model::EffectFunction::Comment) return out;
    for (const auto& n : g_.feeders_of(Node{Node::Kind::Effect, effect}))
      if (n.kind == kind) out.insert(n.id);
    return out;
  }
  const model::Matrix& m_;
  model::DependencyGraph g_;
};

// Whether a structural change (only a critical one with `critical_only`)
// touches the effect (OLD id `o`, NEW id `n`) or an element of its cone in
// either version.
bool touched(const StructuralDiff& d, const Cones& old_c, const Cones& new_c, int o, int n, bool critical_only) {
  std::set<int> oc = o ? old_c.causes(o) : std::set<int>{}, nc = n ? new_c.causes(n) : std::set<int>{};
  std::set<int> oe = o ? old_c.effects(o) : std::set<int>{}, ne = n ? new_c.effects(n) : std::set<int>{};
  for (const auto& c : d.changes) {
    using E = ElementChange::Element;
    if (critical_only && !c.critical()) continue;
    switch (c.element) {
      case E::Matrix:
        if (c.critical()) return true;  // cycle time, secure write, group deactivation: every effect
        break;
      case E::Cause:
        if ((c.old_id && oc.count(c.old_id)) || (c.new_id && nc.count(c.new_id))) return true;
        break;
      case E::Effect:
        if ((c.old_id && oe.count(c.old_id)) || (c.new_id && ne.count(c.new_id))) return true;
        break;
      case E::Intersection:
        if ((c.old_effect && oe.count(c.old_effect)) || (c.new_effect && ne.count(c.new_effect))) return true;
        break;
    }
  }
  return false;
}

// The relabelled run as NEW's own inputs: tags by name, commands' ids back.
std::vector<model::CycleInput> to_new(const std::vector<model::CycleInput>& in, const model::Matrix& rel,
                                      const model::Matrix& new_m, const Relabelling& r) {
  std::map<int, int> cause_back, effect_back;
  for (const auto& [n, x] : r.cause_ids) cause_back[x] = n;
  for (const auto& [n, x] : r.effect_ids) effect_back[x] = n;
  const model::InputTable tr(rel), tn(new_m);
  const model::CycleInput defaults = model::default_cycle_input(new_m);
  std::vector<model::CycleInput> out;
  for (const auto& c : in) {
    model::CycleInput x;
    x.tags = defaults.tags;
    for (std::size_t i = 0; i < tr.size(); ++i)
      if (auto j = tn.find(tr.tags()[i].name)) x.tags[*j] = c.tags[i];
    for (auto cmd : c.commands) {
      if (cmd.cause) cmd.cause = cause_back.at(cmd.cause);
      if (cmd.effect) cmd.effect = effect_back.at(cmd.effect);
      x.commands.push_back(cmd);
    }
    out.push_back(std::move(x));
  }
  return out;
}

// A relabelled distinguishing run must be a run of NEW itself: NEW, given the
// same inputs under its own numbers, shows what the relabelled matrix showed.
void confirm_on_new(const checker::Distinction& d, const model::Matrix& rel, const model::Matrix& new_m,
                    const Relabelling& r, const std::string& group) {
  std::map<int, int> effect_back;
  for (const auto& [n, x] : r.effect_ids) effect_back[x] = n;
  const auto inputs = to_new(d.run_b.inputs, rel, new_m, r);
  const checker::ConcreteTrace t = checker::run_on_runtime(new_m, inputs);
  const auto rel_obs = model::observables(rel), new_obs = model::observables(new_m);
  std::map<std::string, std::size_t> new_index;
  for (std::size_t i = 0; i < new_obs.size(); ++i) new_index[new_obs[i].key] = i;
  for (std::size_t i = 0; i < rel_obs.size(); ++i) {
    const auto& o = rel_obs[i];
    if (o.kind != Node::Kind::Effect) continue;
    std::string key = model::observable_key(Node{Node::Kind::Effect, effect_back.at(o.id)}, o.field, o.tag);
    auto it = new_index.find(key);
    if (it == new_index.end()) continue;
    for (std::size_t k = 0; k < t.observables.size(); ++k)
      if (t.observables[k][it->second] != d.run_b.observables[k][i])
        throw checker::InternalError("diff of " + group + ": NEW renumbered into OLD's numbers behaves differently "
                                     "from NEW on the distinguishing run (" + key + ", cycle " +
                                     std::to_string(k + 1) + ")");
  }
}

std::optional<std::size_t> key_index(const std::vector<model::Observable>& obs, const std::string& key) {
  for (std::size_t i = 0; i < obs.size(); ++i)
    if (obs[i].key == key) return i;
  return std::nullopt;
}

// An output tag's verdict "differs", with the run that shows it.
// It rests on what the effect's verdict rests on, and says which run.
checker::GroupEquivalence tag_differs(const checker::ObservableGroup& tag, const checker::GroupEquivalence& effect,
                                      const std::string& which_run, checker::Distinction shown) {
  checker::GroupEquivalence out;
  out.group = tag.name;
  out.verdict = EquivalenceVerdict::Differs;
  out.basis = effect.basis;
  out.method = effect.method + which_run;
  out.distinction = std::move(shown);
  return out;
}

// An output tag's verdict from its effect's distinguishing run, when the tag
// itself differs in that run's last cycle: the run was replayed on both
// runtimes, and no shorter run can separate the tag, since it would separate
// the effect (whose observables include the tag) earlier too. Otherwise the
// tag is decided on its own.
std::optional<checker::GroupEquivalence> from_effect_run(const checker::GroupEquivalence& effect,
                                                         const checker::ObservableGroup& tag,
                                                         const model::Matrix& a, const model::Matrix& b) {
  if (!effect.distinction || tag.keys.size() != 1) return std::nullopt;
  const checker::Distinction& d = *effect.distinction;
  const auto oa = model::observables(a), ob = model::observables(b);
  const auto ia = key_index(oa, tag.keys.front()), ib = key_index(ob, tag.keys.front());
  if (!ia || !ib || d.run_a.observables.empty() || d.run_b.observables.empty()) return std::nullopt;
  const int va = d.run_a.observables.back()[*ia], vb = d.run_b.observables.back()[*ib];
  if (va == vb) return std::nullopt;
  checker::Distinction t = d;
  t.key = tag.keys.front();
  t.type = oa[*ia].type;
  t.value_a = va;
  t.value_b = vb;
  return tag_differs(tag, effect, ", the effect's run", std::move(t));
}

// An output tag that does not differ in its effect's distinguishing run
// mostly differs once the run goes on the way a field test does: the trip
// held until the output delay has run (E.7), then the plant back at rest
// (defaults, no commands). A latch added (N -> S), a reset or a mask changed
// shows there, a few cycles after the effect's own difference, where a
// search over the product from start-up must unroll the whole run (the
// 128 x 128 benchmark: 60 s per tag, undecided). Both runtimes run the
// continued inputs, so the answer is replayed by construction; it is not
// proved shortest (docs/change-acceptance.md). nullopt when no continuation
// tried shows the tag differing: the tag is then decided on its own.
std::optional<checker::GroupEquivalence> from_continued_effect_run(const checker::GroupEquivalence& effect,
                                                                   const checker::ObservableGroup& tag,
                                                                   const model::Matrix& a, const model::Matrix& b) {
  if (!effect.distinction || tag.keys.size() != 1) return std::nullopt;
  const checker::Distinction& d = *effect.distinction;
  if (d.run_a.inputs.empty() || d.run_b.inputs.empty()) return std::nullopt;
  const auto oa = model::observables(a), ob = model::observables(b);
  const auto ia = key_index(oa, tag.keys.front()), ib = key_index(ob, tag.keys.front());
  if (!ia || !ib) return std::nullopt;
  const model::Effect* ea = a.find_effect(tag.roots.front().id);
  const model::Effect* eb = b.find_effect(tag.roots.front().id);
  if (!ea || !eb) return std::nullopt;
  auto delay_cycles = [](const model::Matrix& m, const model::Effect& e) {
    return static_cast<std::size_t>((e.output_delay_ms + m.cycle_ms - 1) / m.cycle_ms);
  };
  const std::size_t delay = std::max(delay_cycles(a, *ea), delay_cycles(b, *eb));
  constexpr std::size_t kRelease = 8;  // cycles at rest after the hold
  // At rest: the scenario defaults, and, for an effect that passes process
  // data through (E.9), the same with the process value at 1, so that the
  // released output does not rest at the value it acts with.
  std::vector<std::pair<model::CycleInput, model::CycleInput>> rests;
  {
    const runtime::Runtime ra(a), rb(b);
    rests.push_back({ra.default_input(), rb.default_input()});
    const auto& pd = ea->process_data ? ea->process_data : eb->process_data;
    if (pd && pd->tag) {
      auto raised = rests.front();
      const auto ja = ra.inputs().find(*pd->tag), jb = rb.inputs().find(*pd->tag);
      if (ja) raised.first.tags[*ja].value = 1.0f;
      if (jb) raised.second.tags[*jb].value = 1.0f;
      if (ja || jb) rests.push_back(std::move(raised));
    }
  }
  auto continued = [&](const std::vector<model::CycleInput>& run, const model::CycleInput& rest, std::size_t hold) {
    std::vector<model::CycleInput> in = run;
    model::CycleInput held = run.back();
    held.commands.clear();
    for (std::size_t k = 0; k < hold; ++k) in.push_back(held);
    for (std::size_t k = 0; k < kRelease; ++k) in.push_back(rest);
    return in;
  };
  for (const auto& [rest_a, rest_b] : rests)
  for (std::size_t hold : {std::size_t{0}, delay + 1, delay + 8}) {
    const auto ta = checker::run_on_runtime(a, continued(d.run_a.inputs, rest_a, hold));
    const auto tb = checker::run_on_runtime(b, continued(d.run_b.inputs, rest_b, hold));
    const std::size_t n = std::min(ta.observables.size(), tb.observables.size());
    for (std::size_t k = 0; k < n; ++k) {
      const int va = ta.observables[k][*ia], vb = tb.observables[k][*ib];
      if (va == vb) continue;
      checker::Distinction t;
      t.key = tag.keys.front();
      t.type = oa[*ia].type;
      t.cycle = static_cast<int>(k);
      t.value_a = va;
      t.value_b = vb;
      t.run_a.inputs.assign(ta.inputs.begin(), ta.inputs.begin() + static_cast<std::ptrdiff_t>(k + 1));
      t.run_a.observables.assign(ta.observables.begin(), ta.observables.begin() + static_cast<std::ptrdiff_t>(k + 1));
      t.run_b.inputs.assign(tb.inputs.begin(), tb.inputs.begin() + static_cast<std::ptrdiff_t>(k + 1));
      t.run_b.observables.assign(tb.observables.begin(), tb.observables.begin() + static_cast<std::ptrdiff_t>(k + 1));
      return tag_differs(tag, effect, ", the effect's run continued", std::move(t));
    }
  }
  return std::nullopt;
}

}  // namespace

bool SemanticDiff::any_changed() const {
  return std::any_of(effects.begin(), effects.end(),
                     [](const EffectBehaviour& e) { return e.result.verdict == EquivalenceVerdict::Differs; });
}
RetestScope retest_scope(const SemanticDiff& d) {
  RetestScope s;
  for (const auto& e : d.effects)
    if (e.result.verdict == EquivalenceVerdict::Unknown) {
      s.reason = "effect[" + std::to_string(e.new_id ? e.new_id : e.old_id) + "] " + e.name +
                 " is undecided: the semantic comparison is incomplete, so retest the whole matrix";
      return s;
    }
  for (const auto& e : d.effects)
    if (e.behaviour_changed() && !e.critically_changed) {
      s.reason = "the comparisons disagree: effect[" + std::to_string(e.new_id ? e.new_id : e.old_id) + "] " +
                 e.name + " behaves differently but no critical change is listed in its cone, so retest the "
                 "whole matrix";
      return s;
    }
  s.partial = true;
  s.reason = d.any_changed()
                 ? "the comparisons agree (every effect whose behaviour changed has a critical change in its cone, "
                   "every other effect is proved equivalent): a partial retest of the impact set is justified"
                 : "the comparisons agree: no effect's behaviour changed (every effect proved equivalent), so no "
                   "functional retest is needed";
  return s;
}

bool SemanticDiff::any_unknown() const {
  return std::any_of(effects.begin(), effects.end(),
                     [](const EffectBehaviour& e) { return e.result.verdict == EquivalenceVerdict::Unknown; });
}

namespace {

// Compares OLD and NEW effect by effect: each effect's group decided on
// OLD and NEW relabelled into OLD's numbering, its distinctions carried to
// NEW's numbering and confirmed there, then the impact set.
class BehaviourComparer {
 public:
  BehaviourComparer(const model::Matrix& old_m, const model::Matrix& new_m, const StructuralDiff& d,
                    const SemanticOptions& options)
      : old_m_(old_m), new_m_(new_m), d_(d), options_(options), r_(relabel(new_m, d, old_m)), rel_(r_.matrix),
        old_cones_(old_m), new_cones_(new_m), cancel_(options.cancel ? *options.cancel : own_) {
    for (const auto& [n, x] : r_.cause_ids) out_.relabelled |= n != x;
    for (const auto& [n, x] : r_.effect_ids) out_.relabelled |= n != x;
    for (const auto& [n, x] : r_.effect_ids) rel_to_new_[x] = n;
    eo_.work = options.work;
    eo_.timeout_s = options.timeout_s;
    eo_.cancel = &cancel_;
    // One group per effect of OLD or NEW, in OLD's numbering, each in its
    // own slot: the result does not depend on the number of workers.
    groups_ = checker::effect_groups(old_m, rel_);
  }

  SemanticDiff compare() {
    // Each effect undecided ("time limit") until its task decides it: the
    // cancel token (--total-timeout) may end the run first.
    for (std::size_t gi = 0; gi < groups_.size(); ++gi) out_.effects.push_back(undecided(gi));
    checker::WorkQueue(options_.jobs, cancel_).run(groups_.size(), [&](std::size_t gi) { out_.effects[gi] = decide(gi); });
    for (const auto& e : out_.effects)
      if (e.behaviour_changed()) add_to_impact(e);
    return std::move(out_);
  }

 private:
  EffectBehaviour undecided(std::size_t gi) const {
    const checker::ObservableGroup& g = groups_[gi];
    const int id = g.roots.front().id;
    EffectBehaviour e;
    e.old_id = old_m_.find_effect(id) ? id : 0;
    e.new_id = rel_to_new_.count(id) ? rel_to_new_.at(id) : 0;
    e.name = e.new_id ? new_m_.find_effect(e.new_id)->name : old_m_.find_effect(id)->name;
    e.structurally_changed = touched(d_, old_cones_, new_cones_, e.old_id, e.new_id, false);
    e.critically_changed = touched(d_, old_cones_, new_cones_, e.old_id, e.new_id, true);
    e.result.group = g.name;
    e.result.unknown = checker::UnknownReason::TimeLimit;
    e.result.reason = checker::to_string(e.result.unknown);
    return e;
  }

  EffectBehaviour decide(std::size_t gi) const {
    const checker::ObservableGroup& g = groups_[gi];
    const int id = g.roots.front().id;
    EffectBehaviour e = undecided(gi);
    e.result = checker::decide_equivalence(old_m_, rel_, g, eo_);
    if (e.result.distinction && e.new_id) {
      const auto& dist = *e.result.distinction;
      e.new_inputs = to_new(dist.run_b.inputs, rel_, new_m_, r_);
      // The group is one effect: its keys start with "effect[OLD id]".
      const std::string prefix = "effect[" + std::to_string(id) + "]";
      e.new_key = dist.key.rfind(prefix, 0) == 0
                      ? "effect[" + std::to_string(e.new_id) + "]" + dist.key.substr(prefix.size())
                      : dist.key;
      if (out_.relabelled) confirm_on_new(dist, rel_, new_m_, r_, g.name);
    }
    if (e.result.verdict == EquivalenceVerdict::Differs && e.old_id && e.new_id) decide_outputs(e, id);
    return e;
  }

  // A differing effect's output tags: from its distinguishing run when it
  // shows them, else decided on their own.
  void decide_outputs(EffectBehaviour& e, int id) const {
    for (const auto& og : checker::output_groups(old_m_, rel_)) {
      if (og.roots.front().id != id) continue;
      if (auto same = from_effect_run(e.result, og, old_m_, rel_)) {
        e.outputs.push_back(std::move(*same));
        continue;
      }
      if (auto later = from_continued_effect_run(e.result, og, old_m_, rel_)) {
        e.outputs.push_back(std::move(*later));
        if (out_.relabelled) confirm_on_new(*e.outputs.back().distinction, rel_, new_m_, r_, og.name);
        continue;
      }
      e.outputs.push_back(checker::decide_equivalence(old_m_, rel_, og, eo_));
      if (e.outputs.back().distinction && out_.relabelled)
        confirm_on_new(*e.outputs.back().distinction, rel_, new_m_, r_, og.name);
    }
  }

  // The impact set: changed effects, their cones' causes, tags and SIF groups.
  void add_to_impact(const EffectBehaviour& e) {
    out_.impact.effects.push_back(e.new_id ? e.new_id : e.old_id);
    if (e.old_id) add_cone(old_m_, e.old_id, false);
    if (e.new_id) add_cone(new_m_, e.new_id, true);
  }
  void add_cone(const model::Matrix& m, int id, bool is_new) {
    const Cones& cones = is_new ? new_cones_ : old_cones_;
    const model::Effect* ef = m.find_effect(id);
    if (!ef) return;
    Impact& impact = out_.impact;
    for (const auto& t : ef->tags) impact.tags.insert(t.name);
    for (int s : ef->sif) impact.sif_groups.insert(s);
    for (int c : cones.causes(id)) {
      const model::Cause* cz = m.find_cause(c);
      if (is_new) impact.causes.insert(c);
      else if (d_.cause_map.count(c)) impact.causes.insert(d_.cause_map.at(c));
      for (const auto& t : cz->tags)
        if (!model::parse_internal_ref(t.name)) impact.tags.insert(t.name);
      for (int s : cz->sif) impact.sif_groups.insert(s);
    }
  }

  const model::Matrix& old_m_;
  const model::Matrix& new_m_;
  const StructuralDiff& d_;
  const SemanticOptions& options_;
  const Relabelling r_;
  const model::Matrix& rel_;
  const Cones old_cones_, new_cones_;
  checker::CancelToken own_;
  checker::CancelToken& cancel_;
  checker::EquivalenceOptions eo_;
  std::vector<checker::ObservableGroup> groups_;
  std::map<int, int> rel_to_new_;
  SemanticDiff out_;
};

}  // namespace

SemanticDiff compare_behaviour(const model::Matrix& old_m, const model::Matrix& new_m, const StructuralDiff& d,
                               const SemanticOptions& options) {
  return BehaviourComparer(old_m, new_m, d, options).compare();
}

}  // namespace cemv::diff
