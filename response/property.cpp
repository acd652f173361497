#include "response/property.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include "model/text.hpp"
#include "model/vocabulary.hpp"
#include "properties/build.hpp"
#include "properties/print.hpp"
#include "response/plant.hpp"

namespace cemv::response {

namespace {

using model::Cause;
using properties::Expr;
using properties::build::Builder;
using properties::build::CauseField;
using properties::build::EffectField;

// Several alternatives: one is itself, more are one `or`.
Expr any_of(std::vector<Expr> terms) {
  if (terms.size() == 1) return std::move(terms.front());
  return Builder::any(std::move(terms));
}

// count(terms) >= n; true when nothing is needed.
Expr at_least(std::vector<Expr> terms, int n) {
  if (n <= 0) return Expr::boolean(true);
  return Builder::at_least(std::move(terms), n);
}

class Writer {
 public:
  // `bad_counts`: an input in bad quality counts toward the demand (the
  // stated form of cemv defeats, docs/defeats.md): the process behind a
  // failed transmitter is unobserved, and in the worst case beyond the limit.
  Writer(const model::Matrix& m, bool bad_counts = false) : m_(m), b_(m), bad_counts_(bad_counts) {}

  // One input beyond its limit with good quality (C.3, with the strict
  // limit: a hysteresis band only makes a trip last longer); in the stated
  // form, or in bad quality.
  Expr beyond(const Cause& c, const model::CauseTag& t, bool bad_counts) const {
    Expr value = c.input == model::InputKind::Analog && c.analog
                     ? Builder::compare(c.analog->limit_type == model::LimitType::High ? properties::CompareOp::Ge
                                                                                       : properties::CompareOp::Le,
                                        b_.tag(t.name), Expr::real(c.analog->limit))
                     : t.ett ? b_.tag(t.name) : Builder::negate(b_.tag(t.name));
    Expr good = Builder::all({b_.good(t.name), std::move(value)});
    if (bad_counts) return Builder::any({b_.bad(t.name), std::move(good)});
    return good;
  }

  Expr normal_trigger(const Cause& c, bool bad_counts) const {
    std::vector<Expr> terms;
    for (const auto* t : external_tags(c)) terms.push_back(beyond(c, *t, bad_counts));
    return at_least(std::move(terms), votes_needed(c));
  }
  Expr normal_trigger(const Cause& c) const { return normal_trigger(c, bad_counts_); }

  // One input in bad quality, and as many of the others beyond their limits
  // as the voting then needs (C.3, C.4): "trip" counts the bad input as
  // tripped, "degrade" votes X' = max(1, X - 1) of the rest, "ignore" takes
  // the bad input's value as not tripping, so X of the rest (at most all).
  Expr degraded_trigger(const Cause& c) const {
    const auto tags = external_tags(c);
    const int x = votes_needed(c);
    const int others = static_cast<int>(tags.size()) - 1;
    int need = 0;
    switch (c.bad_quality) {
      case model::BadQuality::Trip: need = std::max(0, x - 1); break;
      case model::BadQuality::Degrade: need = std::max(1, x - 1); break;
      case model::BadQuality::Ignore: need = std::min(x, others); break;
    }
    need = std::min(need, others);
    std::vector<Expr> alternatives;
    for (std::size_t i = 0; i < tags.size(); ++i) {
      std::vector<Expr> rest;
      for (std::size_t j = 0; j < tags.size(); ++j)
        if (j != i) rest.push_back(beyond(c, *tags[j], false));
      alternatives.push_back(need > 0 ? Builder::all({b_.bad(tags[i]->name), at_least(std::move(rest), need)})
                                      : b_.bad(tags[i]->name));
    }
    return any_of(std::move(alternatives));
  }

  Expr trip_requested(int id) const { return b_.cause(id, CauseField::TripRequested); }

  // "`condition` has held, since a fresh rise (cause `id` had not requested
  // its trip in the cycle before), for the last `cycles` cycles".
  Expr held_since_fresh_rise(const Expr& condition, int id, long long cycles) const {
    return Builder::held(
        Builder::since(condition,
                       Builder::all({Builder::rose(condition), Builder::negate(Builder::prev(trip_requested(id)))})),
        static_cast<int>(cycles));
  }

  // Cause `c`'s normal or degraded condition held since a fresh rise for
  // `cycles` cycles: the one tree of that term for an XooN bound and for its
  // member lemmas, so that the bound's monitor and the lemmas it assumes
  // read one `held` counter (member_lemmas).
  Expr member_held(const Cause& c, bool degraded, long long cycles, bool bad_counts = false) const {
    return held_since_fresh_rise(degraded ? degraded_trigger(c) : normal_trigger(c, bad_counts), c.id, cycles);
  }

  // Its first cycle: the demand of the set that holds it has lasted exactly
  // `cycles` cycles after its rise.
  static Expr first_cycle(const Expr& held) { return Builder::all({held, Builder::negate(Builder::prev(held))}); }

  // The violation of an XooN path's bound (docs/response-time.md, "XooN"):
  // a fixed set of X trigger causes, each of which rose freshly and has held
  // since, the set complete for `cycles` cycles after its last member rose,
  // and no response in those cycles. A set whose members take turns is no
  // demand: each member's own timers restart with it, so a rotating set
  // would hold any XooN with delays off for ever without X conditions ever
  // holding together.
  Expr xoon_violation(const Path& p, Mode mode, long long cycles, const Expr& response) const {
    std::vector<Expr> held;
    for (int id : p.causes) held.push_back(member_held(*m_.find_cause(id), false, cycles, bad_counts_));
    Expr set;
    if (mode == Mode::Normal) {
      std::vector<Expr> first;
      for (const auto& h : held) first.push_back(first_cycle(h));
      set = Builder::all({at_least(held, p.needed), any_of(std::move(first))});
    } else {
      // The degraded cause v is one of the set, with X - 1 of the rest.
      std::vector<Expr> terms;
      for (int v : p.voted) {
        const Expr degraded = member_held(*m_.find_cause(v), true, cycles);
        std::vector<Expr> rest, first{first_cycle(degraded)};
        for (std::size_t i = 0; i < p.causes.size(); ++i)
          if (p.causes[i] != v) {
            rest.push_back(held[i]);
            if (p.needed > 1) first.push_back(first_cycle(held[i]));
          }
        terms.push_back(Builder::all({degraded, at_least(std::move(rest), p.needed - 1), any_of(std::move(first))}));
      }
      set = any_of(std::move(terms));
    }
    return Builder::all({std::move(set), Builder::negate(Builder::within(response, static_cast<int>(cycles)))});
  }

  // No maintenance operation: simulation and soft bypasses are never commanded.
  static std::vector<properties::Assumption> no_maintenance() {
    std::vector<properties::Assumption> out;
    for (auto op : {model::CommandOp::SimulateTag, model::CommandOp::SoftBypassCause, model::CommandOp::SoftBypassTag,
                    model::CommandOp::SoftBypassEffect})
      out.push_back(Builder::assumption(Builder::negate(Builder::issued(op))));
    return out;
  }

  Expr cause_assumption(int id) const {
    return Builder::all({Builder::negate(b_.cause(id, CauseField::Bypassed)),
                         Builder::negate(b_.cause(id, CauseField::Inhibited))});
  }

  // The bound's property; `stated`: the maintenance assumptions left to the
  // caller's `assumed` terms, and a bad input counted toward the demand.
  properties::Property bound(const Path& p, Mode mode, long long cycles, const std::string& name,
                             const std::vector<Expr>& assumed, bool stated) const {
    // The response: every output tag of the effect at its safe value (E.9).
    const model::Effect& e = *m_.find_effect(p.effect);
    std::vector<Expr> outputs;
    for (std::size_t k = 0; k < e.tags.size(); ++k) {
      Expr tag = b_.effect_tag(e.id, static_cast<int>(k + 1));
      outputs.push_back(e.tags[k].ett ? tag : Builder::negate(tag));
    }
    const Expr response = outputs.size() == 1 ? outputs.front() : Builder::all(outputs);
    std::vector<Expr> assumptions;
    for (const auto& n : stated ? std::vector<model::Node>{} : p.elements) {
      if (n.kind == model::Node::Kind::Cause) {
        assumptions.push_back(cause_assumption(n.id));
        continue;
      }
      assumptions.push_back(Builder::all({Builder::negate(b_.effect(n.id, EffectField::Bypassed)),
                                          Builder::negate(b_.effect(n.id, EffectField::OverrideActive))}));
      // A mask switched by an operator is maintenance (the manual's messages
      // class "Mask active" as preventive maintenance); a mask the logic
      // drives (an internal reference) is not, and may hold the outputs off.
      const model::Effect& x = *m_.find_effect(n.id);
      if (x.process_data && x.process_data->tag && x.process_data->mask_tag &&
          !model::parse_internal_ref(*x.process_data->mask_tag))
        assumptions.push_back(Builder::negate(b_.tag(*x.process_data->mask_tag)));
    }
    // An override of an effect whose state holds a path cause off is an
    // operation on the path too: it lifts a hold of the logic for at most its
    // maximum time, and a figure that counts it measures that time, not the
    // logic (docs/response-time.md, "Assumptions").
    const Holders holders = holders_of(m_, p);
    const std::set<int> on_path = effects_on(p);  // assumed not overridden above
    std::set<int> held_by(holders.effects);
    held_by.insert(holders.inactive_effects.begin(), holders.inactive_effects.end());
    for (int id : stated ? std::set<int>{} : held_by)
      if (!on_path.count(id) && m_.find_effect(id)->override_time)
        assumptions.push_back(Builder::negate(b_.effect(id, EffectField::OverrideActive)));
    for (const auto& t : assumed) assumptions.push_back(Builder::negate(t));
    if (p.causes.size() > 1)
      return Builder::never(name, "", xoon_violation(p, mode, cycles, response), std::move(assumptions));
    // A fresh demand: the cause had not requested its trip in the cycle before.
    const int first = p.causes.front();
    const Expr trigger =
        mode == Mode::Normal ? normal_trigger(*m_.find_cause(first)) : degraded_trigger(*m_.find_cause(first));
    return Builder::response(name, "",
                             Builder::all({Builder::rose(trigger), Builder::negate(Builder::prev(trip_requested(first)))}),
                             Builder::any({response, Builder::fell(trigger)}), static_cast<int>(cycles),
                             std::move(assumptions));
  }

  const model::InputTable& inputs() const { return b_.inputs(); }

 private:
  const model::Matrix& m_;
  Builder b_;
  bool bad_counts_ = false;
};

properties::PropertyFile one(const std::string& name, std::vector<properties::Assumption> assumptions,
                             properties::Property p) {
  properties::PropertyFile f;
  f.file_name = "cemv-response:" + name;
  f.assumptions = std::move(assumptions);
  f.properties.push_back(std::move(p));
  return f;
}

}  // namespace

properties::PropertyFile response_property(const model::Matrix& m, const Path& p, Mode mode, long long cycles,
                                           const std::string& name, const std::vector<Expr>& assumed) {
  const Writer w(m);
  return one(name, Writer::no_maintenance(), w.bound(p, mode, cycles, name, assumed, false));
}

properties::PropertyFile requirement_property(const model::Matrix& m, const Path& p, long long cycles,
                                              const std::string& name, const std::vector<Expr>& excluded) {
  const Writer w(m, true);
  properties::PropertyFile f = one(name, {}, w.bound(p, Mode::Normal, cycles, name, excluded, true));
  f.file_name = "cemv-defeats:" + name;
  return f;
}

std::string requirement_property_text(const model::Matrix& m, const Path& p, long long cycles,
                                      const std::string& name, const std::vector<std::string>& excluded) {
  const Writer w(m, true);
  const properties::Property bound = w.bound(p, Mode::Normal, cycles, name, {}, true);
  std::string s = "# Generated by cemv defeats (docs/defeats.md).\nproperty " + name + " {\n";
  for (const auto& t : excluded) s += "  assume not " + t + "\n";
  return s + "  " + properties::statement_text(bound, w.inputs()) + "\n}\n";
}

std::optional<MemberLemmas> member_lemmas(const model::Matrix& m, const Path& p, Mode mode, long long cycles,
                                          const std::string& name) {
  if (p.causes.size() < 2) return std::nullopt;
  const Writer w(m);
  const properties::build::Builder b(m);
  MemberLemmas out;
  out.file.file_name = "cemv-response:" + name;
  out.file.assumptions = Writer::no_maintenance();
  for (int id : p.causes) {
    const Cause& c = *m.find_cause(id);
    // A timed cause is active for its pulse only, however long its
    // condition holds: no lemma (the bound's proof goes without it).
    if (c.time.mode == model::TimeMode::Timed) continue;
    const long long delay = c.time.mode == model::TimeMode::OnDelay ? cycles_of(c.time.ms, m.cycle_ms) : 0;
    if (delay > cycles) continue;
    // Each condition as xoon_violation builds it (member_held); one property
    // each, since a lemma may fail for one condition only (an `and` whose
    // bad input is ignored never trips in degraded mode).
    std::vector<std::pair<std::string, Expr>> conditions{{".c" + std::to_string(id), w.member_held(c, false, cycles)}};
    if (mode == Mode::Degraded && std::count(p.voted.begin(), p.voted.end(), id))
      conditions.push_back({".c" + std::to_string(id) + ".degraded", w.member_held(c, true, cycles)});
    for (const auto& [suffix, held] : conditions) {
      Expr term = Builder::all(
          {held, Builder::negate(Builder::held(b.cause(id, CauseField::Active), static_cast<int>(cycles - delay)))});
      out.names.push_back(name + suffix);
      out.terms.push_back(term);
      out.delays.push_back(delay);
      out.file.properties.push_back(Builder::never(out.names.back(), "", std::move(term), {w.cause_assumption(id)}));
    }
  }
  if (out.names.empty()) return std::nullopt;
  return out;
}

}  // namespace cemv::response
