// Each standard property restates one rule of docs/semantics.md over the
// status fields, so it is exactly true of a correct implementation of that
// rule; what it checks is the matrix's wiring (XooN, bypasses, references)
// and the encoder/runtime agreement, and its proof support shows which
// elements carry it.
#include "properties/standard.hpp"

#include <algorithm>

#include "model/graph.hpp"
#include "model/vocabulary.hpp"
#include "properties/build.hpp"

namespace cemv::properties {

namespace {

using model::IntersectionType;
using build::Builder;
using build::CauseField;
using build::EffectField;

bool processed(const model::Cause* x) { return x && x->function != model::CauseFunction::Comment; }
bool processed(const model::Effect* x) { return x && x->function != model::EffectFunction::Comment; }

class Writer {
 public:
  explicit Writer(const model::Matrix& m) : m_(m), graph_(m), inputs_(m), b_(m) {}

  PropertyFile run() {
    out_.file_name = "<standard>";
    for (const auto& i : m_.intersections) intersection(i);
    for (const auto& x : m_.effects)
      if (processed(&x)) output_delay(x);
    for (const auto& x : m_.effects)
      if (processed(&x)) reachable(x);
    for (const auto& x : m_.effects)
      if (processed(&x)) resettable(x);
    for (const auto& x : m_.causes)
      if (processed(&x)) failsafe(x);
    return std::move(out_);
  }

 private:
  // The cause's `active` as the effect reads it (I.4): the previous cycle's
  // value when the reference closes a cycle of the dependency graph.
  Expr active_as_read(int cause, int effect) const {
    bool previous = graph_.reads_previous({model::Node::Kind::Cause, cause}, {model::Node::Kind::Effect, effect});
    Expr active = b_.cause(cause, CauseField::Active);
    return previous ? Builder::prev(std::move(active)) : active;
  }

  // E.2/E.6: an active cause on an N, S, V or R intersection requests the
  // effect, which is then active unless bypassed, or (V and R only) overridden.
  // With an XooN assignment (E.2) at least X of its causes must be active.
  void intersection(const model::Intersection& i) {
    if (!model::is_processed(i.type) || !processed(m_.find_cause(i.cause)) || !processed(m_.find_effect(i.effect)))
      return;
    std::vector<Expr> cond{active_as_read(i.cause, i.effect)};
    std::string what = "cause " + std::to_string(i.cause) + " active";
    if (i.xoon) {
      std::vector<const model::Intersection*> group;
      for (const auto* j : m_.intersections_of_effect(i.effect))
        if (j->xoon && model::is_processed(j->type) && processed(m_.find_cause(j->cause))) group.push_back(j);
      int x = *i.xoon;
      for (const auto* j : group) x = std::min(x, *j->xoon);
      std::vector<Expr> members;
      for (const auto* j : group) members.push_back(active_as_read(j->cause, i.effect));
      cond.push_back(Builder::at_least(std::move(members), x));
      what += " with " + std::to_string(x) + "oo" + std::to_string(group.size()) + " of its XooN assignment";
    }
    // The type that counts is the assignment's (E.2): the type of its lowest cause.
    IntersectionType type = i.type;
    if (i.xoon)
      for (const auto* j : m_.intersections_of_effect(i.effect))
        if (j->xoon && model::is_processed(j->type)) {
          type = j->type;
          break;
        }
    cond.push_back(Builder::negate(b_.effect(i.effect, EffectField::Bypassed)));
    std::string unless = "not bypassed";
    if (type == IntersectionType::V || type == IntersectionType::R) {
      cond.push_back(Builder::negate(b_.effect(i.effect, EffectField::OverrideActive)));
      unless = "neither bypassed nor overridden";
    }
    add(Builder::invariant(
        "std.intersection.c" + std::to_string(i.cause) + ".e" + std::to_string(i.effect),
        what + ", effect " + std::to_string(i.effect) + " " + unless + ": effect " + std::to_string(i.effect) + " active",
        Builder::implies(Builder::all(std::move(cond)), b_.effect(i.effect, EffectField::Active))));
  }

  // E.7: once the effect has been active for the whole output delay, the delay
  // no longer holds the outputs back.
  void output_delay(const model::Effect& x) {
    if (x.output_delay_ms == 0) return;
    std::uint64_t cycles = (std::uint64_t{x.output_delay_ms} + m_.cycle_ms - 1) / m_.cycle_ms;  // T.2
    add(Builder::invariant(
        "std.output_delay.e" + std::to_string(x.id),
        "effect " + std::to_string(x.id) + " active for its output delay (" + std::to_string(x.output_delay_ms) +
            " ms): the outputs follow",
        Builder::implies(Builder::held(b_.effect(x.id, EffectField::Active), static_cast<int>(cycles)),
                         Builder::negate(b_.effect(x.id, EffectField::OutputDelayRunning)))));
  }

  void reachable(const model::Effect& x) {
    add(Builder::reachable("std.reachable.e" + std::to_string(x.id), "effect " + std::to_string(x.id) + " can be tripped",
                           b_.effect(x.id, EffectField::Active)));
  }

  // E.4/E.5: an effect that latches (S or R intersection) can leave the latched state.
  void resettable(const model::Effect& x) {
    bool latches = false;
    for (const auto* i : m_.intersections_of_effect(x.id))
      latches = latches || ((i->type == IntersectionType::S || i->type == IntersectionType::R) &&
                            processed(m_.find_cause(i->cause)));
    if (!latches) return;
    add(Builder::reachable("std.resettable.e" + std::to_string(x.id),
                           "latched effect " + std::to_string(x.id) + " can be reset",
                           Builder::all({Builder::prev(b_.effect(x.id, EffectField::Latched)),
                                         Builder::negate(b_.effect(x.id, EffectField::Latched))})));
  }

  // C.3/C.4: with every tag of a `trip` or `degrade` cause in bad quality the
  // trip is requested, unless every tag is soft-bypassed (voting `bypass`).
  // Simulation delivers good quality (C.2), so the property assumes none.
  void failsafe(const model::Cause& x) {
    if (x.bad_quality == model::BadQuality::Ignore || x.tags.empty()) return;
    std::vector<Expr> assumptions, cond;
    for (const auto& t : x.tags) {
      if (model::parse_internal_ref(t.name) || !inputs_.find(t.name)) return;  // no quality to lose
      cond.push_back(b_.bad(t.name));
      assumptions.push_back(Builder::negate(b_.simulate_issued(t.name)));
    }
    cond.push_back(Builder::voting_is_not(b_.cause(x.id, CauseField::Voting), model::Voting::Bypass));
    add(Builder::invariant("std.failsafe.c" + std::to_string(x.id),
                           "every tag of cause " + std::to_string(x.id) + " in bad quality (" +
                               model::to_string(x.bad_quality) + "): trip requested",
                           Builder::implies(Builder::all(std::move(cond)), b_.cause(x.id, CauseField::TripRequested)),
                           std::move(assumptions)));
  }

  void add(Property p) { out_.properties.push_back(std::move(p)); }

  const model::Matrix& m_;
  model::DependencyGraph graph_;
  model::InputTable inputs_;
  Builder b_;
  PropertyFile out_;
};

}  // namespace

PropertyFile standard_properties(const model::Matrix& m) { return Writer(m).run(); }

std::string standard_properties_text(const model::Matrix& m) {
  const model::InputTable inputs(m);
  std::string out;
  for (const auto& p : standard_properties(m).properties) out += build::block_text(p, inputs);
  return out;
}

}  // namespace cemv::properties
