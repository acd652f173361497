// The objectives of intersections and effects (docs/testgen.md,
// "Intersections", "Effects"): each cause trips each linked effect on its own
// and the effect follows or stays latched when it clears (docs/semantics.md
// E.2, E.5, E.6), XooN at X-1 and X (E.2), reset (E.4), overrides (E.3), the
// output delay (E.7), bypass (E.1), the pass-through/mask table and the
// output values (E.8, E.9).
#include <algorithm>
#include <map>

#include "model/graph.hpp"
#include "testgen/objective_builder.hpp"

namespace cemv::testgen::detail {

namespace {

using model::Effect;
using model::IntersectionType;

using CF = CauseField;
using EF = EffectField;

const model::Cause& cause_of(const model::Matrix& m, int id) { return *m.find_cause(id); }

// The processed intersections of an effect whose cause is processed.
std::vector<const model::Intersection*> links(const model::Matrix& m, const Effect& e) {
  std::vector<const model::Intersection*> out;
  for (const auto* x : m.intersections_of_effect(e.id)) {
    const model::Cause* c = m.find_cause(x->cause);
    if (model::is_processed(x->type) && c && c->function != model::CauseFunction::Comment) out.push_back(x);
  }
  return out;
}

All others_inactive(const ObjectiveBuilder& b, const std::vector<const model::Intersection*>& ls, int except) {
  All s;
  for (const auto* x : ls)
    if (x->cause != except) s << Builder::negate(b.cause(cause_of(b.matrix(), x->cause), CF::Active));
  return s;
}

Expr any_active(const ObjectiveBuilder& b, const std::vector<const model::Intersection*>& ls,
                bool (*keep)(IntersectionType)) {
  std::vector<Expr> parts;
  for (const auto* x : ls)
    if (keep(x->type)) parts.push_back(b.cause(cause_of(b.matrix(), x->cause), CF::Active));
  return any_of(std::move(parts));
}

bool any_type(IntersectionType) { return true; }
bool latching(IntersectionType t) { return t == IntersectionType::S || t == IntersectionType::R; }
bool overridable(IntersectionType t) { return t == IntersectionType::V || t == IntersectionType::R; }

bool linked(const model::Matrix& m, int cause, const Effect& e) {
  for (const auto* x : links(m, e))
    if (x->cause == cause) return true;
  return false;
}

int sif_of(const model::Matrix& m, const model::Intersection& x, const Effect& e) {
  const model::Cause* c = m.find_cause(x.cause);
  return c && !c->sif.empty() ? c->sif.front() : first_sif(e.sif);
}

// A command of the effect's operator, with secure write enabled where the
// matrix has it (M.3).
All command(const ObjectiveBuilder& b, model::CommandOp op, const Effect& e) {
  All out{Builder::issued(op, 0, e.id)};
  if (b.matrix().secure_write) out << b.tag(b.matrix().secure_write->enable_tag);
  return out;
}

}  // namespace

void intersection_objectives(ObjectiveBuilder& b, const Effect& e) {
  const model::Matrix& m = b.matrix();
  const auto ls = links(m, e);
  const model::Node node{model::Node::Kind::Effect, e.id};
  const Expr act = b.effect(e, EF::Active);
  for (const auto* x : ls) {
    if (x->xoon) continue;
    const model::Cause& c = cause_of(m, x->cause);
    const Expr cact = b.cause(c, CF::Active);
    const std::string id = "intersection.c" + std::to_string(c.id) + ".e" + std::to_string(e.id);
    const std::string type = model::to_string(x->type);
    const int sif = sif_of(m, *x, e);
    const All others = others_inactive(b, ls, c.id);
    b.add(id + ".trip", "intersection",
          label(c) + " alone trips " + label(e) + " (intersection " + type + ")", node, sif,
          (All{Builder::rose(act), cact} << others).expr(), 1, {ck(c, CF::Active), ek(e, EF::Active)});
    if (latching(x->type))
      b.add(id + ".latched", "intersection",
            label(e) + " stays latched after " + label(c) + " clears (intersection " + type + ")", node, sif,
            (All{Builder::fell(cact), act, b.effect(e, EF::Latched)} << others).expr(), 2,
            {ck(c, CF::Active), ek(e, EF::Active), ek(e, EF::Latched)});
    else
      b.add(id + ".follow", "intersection",
            label(e) + " goes inactive with " + label(c) + " (intersection " + type + ")", node, sif,
            (All{Builder::fell(cact), Builder::fell(act)} << others).expr(), 2,
            {ck(c, CF::Active), ek(e, EF::Active)});
    if (overridable(x->type) && e.override_time)
      b.add(id + ".overridden", "intersection",
            "Override of " + label(e) + " suppresses the request of " + label(c) + " (intersection " + type + ")", node,
            sif, (All{cact, b.effect(e, EF::OverrideActive), Builder::negate(act)} << others).expr(), 2,
            {ck(c, CF::Active), ek(e, EF::Active), ek(e, EF::OverrideActive)});
    // N and S requests ignore an override (E.6): an S or N cell changed to R
    // or V would let it through. The toggle must be one that would start an
    // override on a V/R request (E.3 step 2): a reset-tag edge where the
    // effect has a reset tag (the override command is refused then, O.3),
    // no override running, the effect not bypassed, no output delay running.
    // The edge is the runtime's (T.4): the tag TRUE now and FALSE in the
    // cycle before. `rose` also holds in the first cycle for a tag that
    // starts TRUE, where the runtime sees no edge: a witness there toggles
    // nothing, and an S cell changed to R goes unseen.
    if (!overridable(x->type) && e.override_time) {
      const Expr ov = b.effect(e, EF::OverrideActive);
      All toggle = e.reset_tag ? All{b.tag(*e.reset_tag), Builder::prev(Builder::negate(b.tag(*e.reset_tag)))}
                               : command(b, model::CommandOp::OverrideEffect, e);
      toggle << Builder::negate(Builder::prev(ov)) << Builder::negate(b.effect(e, EF::Bypassed));
      if (e.output_delay_ms > 0) toggle << Builder::negate(Builder::prev(b.effect(e, EF::OutputDelayRunning)));
      toggle << cact << act << Builder::negate(ov) << others;
      b.add(id + ".not_overridden", "intersection",
            "An override of " + label(e) + " does not suppress the request of " + label(c) + " (intersection " +
                type + ")",
            node, sif, toggle.expr(), 2, {ck(c, CF::Active), ek(e, EF::Active), ek(e, EF::OverrideActive)});
    }
  }
  // XooN assignment (E.2): X the smallest, the type of the lowest cause id.
  std::vector<const model::Intersection*> xoon;
  int x_min = 0;
  for (const auto* x : ls)
    if (x->xoon) {
      xoon.push_back(x);
      x_min = x_min == 0 ? *x->xoon : std::min(x_min, *x->xoon);
    }
  if (xoon.empty()) return;
  std::vector<Expr> counted;
  All others;
  for (const auto* x : ls) {
    if (x->xoon) counted.push_back(b.cause(cause_of(m, x->cause), CF::Active));
    else others << Builder::negate(b.cause(cause_of(m, x->cause), CF::Active));
  }
  const Expr cnt = Builder::count(counted);
  const std::string id = "xoon.e" + std::to_string(e.id);
  const std::string xn = std::to_string(x_min) + "oo" + std::to_string(xoon.size());
  const int sif = sif_of(m, *xoon.front(), e);
  b.add(id + ".below", "xoon", label(e) + ": " + xn + " with " + std::to_string(x_min - 1) + " cause(s) active does not trip",
        node, sif,
        (All{Builder::equals(cnt, std::int64_t{x_min - 1}), Builder::negate(act),
             Builder::negate(b.effect(e, EF::Latched))}
         << others)
            .expr(),
        1, {ek(e, EF::Active)});
  b.add(id + ".at", "xoon", label(e) + ": " + xn + " with " + std::to_string(x_min) + " causes active trips", node, sif,
        (All{Builder::rose(act), Builder::equals(cnt, std::int64_t{x_min})} << others).expr(), 2, {ek(e, EF::Active)});
  // Each cause counts (an MC/DC of the assignment): the effect trips with
  // exactly X causes active, this one among them. `.at` alone lets the
  // search pick any X causes, and a cell of a cause never among them can be
  // removed unseen (the rest are X - 1 then, no trip).
  if (x_min >= static_cast<int>(xoon.size())) return;  // X of X: `.at` has every cause active
  for (const auto* x : xoon) {
    const model::Cause& c = cause_of(m, x->cause);
    b.add(id + ".c" + std::to_string(c.id) + ".counts", "xoon",
          label(e) + ": " + xn + " trips with " + label(c) + " and " + std::to_string(x_min - 1) +
              " other cause(s) active",
          node, sif,
          (All{Builder::rose(act), b.cause(c, CF::Active), Builder::equals(cnt, std::int64_t{x_min})} << others)
              .expr(),
          2, {ck(c, CF::Active), ek(e, EF::Active)});
  }
}

void effect_objectives(ObjectiveBuilder& b, const Effect& e) {
  const model::Matrix& m = b.matrix();
  const auto ls = links(m, e);
  const model::Node node{model::Node::Kind::Effect, e.id};
  const std::string id = "effect." + std::to_string(e.id);
  const int sif = first_sif(e.sif);
  const Expr act = b.effect(e, EF::Active), latched = b.effect(e, EF::Latched), odr = b.effect(e, EF::OutputDelayRunning);
  const Expr any = any_active(b, ls, any_type);
  bool has_latch = false, has_vr = false;
  for (const auto* x : ls) {
    has_latch |= latching(x->type);
    has_vr |= overridable(x->type);
  }
  // Reset (E.4, O.2).
  if (has_latch) {
    const All rq = e.reset_tag ? All{Builder::rose(b.tag(*e.reset_tag))} : command(b, model::CommandOp::ResetEffect, e);
    const std::string how = e.reset_tag ? "Reset with " + *e.reset_tag : "Reset command";
    const Expr latching_causes = any_active(b, ls, latching);
    b.add(id + ".reset.refused_cause", "reset", how + " for " + label(e) + " refused while a latching cause is active",
          node, sif, (All(rq) << Builder::prev(latched) << latched << latching_causes).expr(), 2,
          {ek(e, EF::Latched), ek(e, EF::Active), ek(e, EF::OkToReset)});
    if (e.output_delay_ms > 0)
      b.add(id + ".reset.refused_delay", "reset", how + " for " + label(e) + " refused while the output delay runs",
            node, sif,
            (All(rq) << Builder::prev(latched) << latched << Builder::prev(odr) << Builder::negate(latching_causes))
                .expr(),
            2, {ek(e, EF::Latched), ek(e, EF::Active), ek(e, EF::OutputDelayRunning)});
    b.add(id + ".reset.accepted", "reset", how + " for " + label(e) + " accepted once the causes have cleared", node, sif,
          (All(rq) << Builder::prev(latched) << Builder::negate(latched)).expr(), 2,
          {ek(e, EF::Latched), ek(e, EF::Active)});
  }
  // Override (E.3, O.3).
  if (e.override_time && has_vr) {
    const Expr tg = e.reset_tag ? Builder::rose(b.tag(*e.reset_tag))
                                : Builder::any({Builder::issued(model::CommandOp::OverrideEffect, 0, e.id),
                                                Builder::issued(model::CommandOp::StopOverride, 0, e.id)});
    const Expr ov = b.effect(e, EF::OverrideActive);
    const std::string kov = ek(e, EF::OverrideActive), kact = ek(e, EF::Active);
    const std::string kto = ek(e, EF::OverrideFailedTimeout), kpre = ek(e, EF::OverridePrealarm);
    b.add(id + ".override.start", "override", "Override of " + label(e) + " started", node, sif, Builder::rose(ov), 2,
          {kov, kact});
    b.add(id + ".override.stop", "override", "Override of " + label(e) + " stopped by the operator", node, sif,
          Builder::all({Builder::fell(ov), tg, Builder::negate(b.effect(e, EF::OverrideFailedTimeout)),
                        Builder::negate(b.effect(e, EF::OverrideFailedCause))}),
          3, {kov, kact});
    if (e.override_time->max_s > 0)
      b.add(id + ".override.timeout", "override",
            "Override of " + label(e) + " times out after " + std::to_string(e.override_time->max_s) +
                " s with the timeout alarm",
            node, sif, Builder::rose(b.effect(e, EF::OverrideFailedTimeout)),
            b.cycles(e.override_time->max_s * 1000ULL) + 2, {kov, kto, kact});
    // The cycle before each boundary too: a timeout or prealarm moved earlier
    // shows there (T.2: started in cycle s, the override runs s .. s+D-1).
    auto on_for = [&](int n) { return All{ov, held(ov, n - 1), Builder::negate(held(ov, n))}; };
    if (e.override_time->max_s > 0)
      b.add(id + ".override.timeout.before", "override",
            "Override of " + label(e) + ": still running one cycle before its timeout", node, sif,
            on_for(b.cycles(e.override_time->max_s * 1000ULL)).expr(), b.cycles(e.override_time->max_s * 1000ULL) + 1,
            {kov, kto, kact});
    if (e.override_time->prealarm_s > 0 && e.override_time->prealarm_s < e.override_time->max_s)
      b.add(id + ".override.prealarm.before", "override",
            "Override of " + label(e) + ": one cycle before its prealarm", node, sif,
            (on_for(b.cycles(e.override_time->prealarm_s * 1000ULL))
             << Builder::negate(b.effect(e, EF::OverridePrealarm)))
                .expr(),
            b.cycles(e.override_time->prealarm_s * 1000ULL) + 1, {kov, kpre});
    if (e.override_time->prealarm_s > 0 && e.override_time->prealarm_s < e.override_time->max_s)
      b.add(id + ".override.prealarm", "override", "Override prealarm of " + label(e), node, sif,
            Builder::rose(b.effect(e, EF::OverridePrealarm)), b.cycles(e.override_time->prealarm_s * 1000ULL) + 2,
            {kpre});
    if (ls.size() >= 2)
      b.add(id + ".override.new_cause", "override", "Override of " + label(e) + " fails on a new cause", node, sif,
            Builder::rose(b.effect(e, EF::OverrideFailedCause)), 3, {kov, ek(e, EF::OverrideFailedCause), kact});
  }
  // Output delay (E.7).
  if (e.output_delay_ms > 0) {
    const int d = b.cycles(e.output_delay_ms);
    const std::string dur = std::to_string(e.output_delay_ms) + " ms";
    const std::string kodr = ek(e, EF::OutputDelayRunning), kact = ek(e, EF::Active);
    b.add(id + ".delay.before", "output-delay", "Output delay (" + dur + ") of " + label(e) + ": one cycle before expiry",
          node, sif, Builder::all({odr, held(act, d - 1), Builder::negate(held(act, d))}), d + 2, {kodr, kact});
    b.add(id + ".delay.expiry", "output-delay", "Output delay (" + dur + ") of " + label(e) + ": expiry cycle", node, sif,
          Builder::all({Builder::prev(odr), Builder::negate(odr), act}), d + 3, {kodr, kact});
    // Restarted, not resumed: a bypass interrupts the running delay, and one
    // cycle before the full duration has run again since the bypass ended,
    // the outputs still wait (E.7 "any interruption ... restarts it").
    if (e.bypass_tag || e.soft_bypass_allowed)
      b.add(id + ".delay.restart", "output-delay",
            "Output delay (" + dur + ") of " + label(e) + " restarted by a bypass that interrupted it: one cycle "
            "before expiry, counted from the end of the bypass",
            node, sif,
            Builder::all({odr, held(act, d - 1), Builder::negate(held(act, d)),
                          Builder::within(Builder::all({b.effect(e, EF::Bypassed), Builder::prev(odr)}), 2 * d + 4)}),
            2 * d + 4, {kodr, kact, ek(e, EF::Bypassed)});
  }
  // Bypass (E.1, E.6).
  if (e.bypass_tag)
    b.add(id + ".bypass.hard", "bypass", "Bypass tag " + *e.bypass_tag + " suppresses " + label(e), node, sif,
          Builder::all({b.tag(*e.bypass_tag), Builder::negate(b.effect(e, EF::SoftBypassed)), Builder::negate(act), any}),
          1, {ek(e, EF::Bypassed), ek(e, EF::Active)});
  if (e.soft_bypass_allowed)
    b.add(id + ".bypass.soft", "bypass", "Soft bypass of " + label(e) + " suppresses it", node, sif,
          Builder::all({b.effect(e, EF::SoftBypassed), Builder::negate(act), any}), 1,
          {ek(e, EF::SoftBypassed), ek(e, EF::Active)});
  // Pass-through and mask (E.8, E.9): every row of the table.
  const bool pt = e.process_data && e.process_data->tag && e.process_data->pass_through;
  const bool mask = e.process_data && e.process_data->tag && e.process_data->mask_tag;
  const Expr masked = b.effect(e, EF::Masked);
  std::vector<std::string> tags_observed;
  for (std::size_t k = 0; k < e.tags.size(); ++k) tags_observed.push_back(ek_tag(e, k + 1));
  if (pt || mask) {
    const Expr p = b.tag(*e.process_data->tag);
    const Expr acting = Builder::all({act, Builder::negate(odr)});
    for (int os = 0; os <= 1; ++os)
      for (int mk = 0; mk <= (mask ? 1 : 0); ++mk)
        for (int pv = 0; pv <= 1; ++pv) {
          All expr{os ? acting : Builder::negate(acting)};
          if (mask) expr << (mk ? masked : Builder::negate(masked));
          expr << (pv ? p : Builder::negate(p));
          std::string text = "Pass-through/mask row of " + label(e) + ": outputs " + (os ? "acting" : "not acting") +
                             (mask ? std::string(", mask ") + (mk ? "on" : "off") : "") + ", process value " + (pv ? "1" : "0");
          auto obs = tags_observed;
          obs.push_back(ek(e, EF::PassThroughActive));
          obs.push_back(ek(e, EF::Masked));
          b.add(id + ".process.os" + std::to_string(os) + (mask ? ".m" + std::to_string(mk) : "") + ".p" + std::to_string(pv),
                "pass-through", text, node, sif, expr.expr(), 2, obs);
        }
  }
  // Output values, DTT/ETT (E.9).
  for (std::size_t k = 0; k < e.tags.size(); ++k) {
    const auto& t = e.tags[k];
    const Expr tk = b.output(e, static_cast<int>(k + 1));
    const std::string kind = t.ett ? "ETT" : "DTT";
    All safe{act, Builder::negate(odr)};
    if (mask) safe << Builder::negate(masked);
    safe << Builder::equals(tk, t.ett);
    b.add(id + ".tag" + std::to_string(k + 1) + ".safe", "output",
          "Output " + t.name + " (" + kind + ") goes to its safe value " + (t.ett ? "1" : "0") + " when " + label(e) + " acts",
          node, sif, safe.expr(), 1, {ek_tag(e, k + 1)});
    All normal{Builder::negate(act)};
    if (pt) normal << b.tag(*e.process_data->tag);
    else if (mask) normal << Builder::negate(masked);
    normal << Builder::equals(tk, !t.ett);
    b.add(id + ".tag" + std::to_string(k + 1) + ".normal", "output",
          "Output " + t.name + " (" + kind + ") at its normal value " + (t.ett ? "0" : "1") + " while " + label(e) + " is inactive",
          node, sif, normal.expr(), 1, {ek_tag(e, k + 1)});
  }
}

void matrix_objectives(ObjectiveBuilder& b) {
  const model::Matrix& m = b.matrix();
  // Per cause: active, and no effect it cannot reach (no intersection, no
  // reference) active, so that an intersection added in an empty cell shows.
  const model::DependencyGraph graph(m);
  std::vector<std::pair<const model::Cause*, const Effect*>> apart;  // reached through references only
  for (const auto& c : m.causes) {
    if (c.function == model::CauseFunction::Comment) continue;
    // Effects that what the cause reads (its internal references, I.3) also
    // drives are left out: `Cause[1]` tripping cause 8 trips effect 1 through
    // cause 1 as well, and a cause reading `Effect[1]` is active only with
    // effect 1, so "cause active, that effect inactive" cannot happen.
    const model::Node self{model::Node::Kind::Cause, c.id};
    std::vector<model::Node> reach = graph.reach_of(self);
    for (const auto& edge : graph.edges())
      if (edge.kind == model::Edge::Kind::Reference && edge.to == self)
        for (const auto& r : graph.reach_of(edge.from)) reach.push_back(r);
    std::sort(reach.begin(), reach.end());
    reach.erase(std::unique(reach.begin(), reach.end()), reach.end());
    All quiet;
    std::vector<std::string> seen{ck(c, CF::Active)};
    for (const auto& e : m.effects) {
      if (e.function == model::EffectFunction::Comment) continue;
      if (std::binary_search(reach.begin(), reach.end(), model::Node{model::Node::Kind::Effect, e.id})) {
        if (!linked(m, c.id, e)) apart.push_back({&c, &e});
        continue;
      }
      quiet << Builder::negate(b.effect(e, EF::Active));
      seen.push_back(ek(e, EF::Active));
    }
    if (quiet.empty()) continue;
    b.add("intersection.c" + std::to_string(c.id) + ".none", "intersection",
          label(c) + " trips none of the effects it has no intersection with", {model::Node::Kind::Cause, c.id},
          first_sif(c.sif), (All{b.cause(c, CF::Active)} << quiet).expr(), 1, seen);
  }
  const model::Cause* soft_cause = nullptr;
  const model::Effect* soft_effect = nullptr;
  const model::Effect* override_effect = nullptr;
  for (const auto& c : m.causes)
    if (!soft_cause && c.function != model::CauseFunction::Comment && c.soft_bypass.allowed) soft_cause = &c;
  for (const auto& e : m.effects) {
    if (e.function == model::EffectFunction::Comment) continue;
    if (!soft_effect && e.soft_bypass_allowed) soft_effect = &e;
    if (!override_effect && e.override_time)
      for (const auto* x : links(m, e))
        if (overridable(x->type)) override_effect = &e;
  }
  if (m.group_deactivation) {
    const All edge{Builder::rose(b.tag(m.group_deactivation->set_tag)), b.tag(m.group_deactivation->enable_tag)};
    auto ends = [&](const std::string& id, const std::string& what, model::Node n, int sif, const Expr& key,
                    const std::string& k) {
      b.add("matrix.group_deactivation." + id, "group-deactivation", "Group deactivation ends the " + what, n, sif,
            (All(edge) << Builder::prev(key) << Builder::negate(key)).expr(), 3, {k});
    };
    if (soft_cause)
      ends("cause_bypass", "soft bypass of " + label(*soft_cause), {model::Node::Kind::Cause, soft_cause->id},
           first_sif(soft_cause->sif), b.cause(*soft_cause, CF::SoftBypassed), ck(*soft_cause, CF::SoftBypassed));
    if (soft_effect)
      ends("effect_bypass", "soft bypass of " + label(*soft_effect), {model::Node::Kind::Effect, soft_effect->id},
           first_sif(soft_effect->sif), b.effect(*soft_effect, EF::SoftBypassed), ek(*soft_effect, EF::SoftBypassed));
    if (override_effect)
      ends("override", "override of " + label(*override_effect), {model::Node::Kind::Effect, override_effect->id},
           first_sif(override_effect->sif), b.effect(*override_effect, EF::OverrideActive),
           ek(*override_effect, EF::OverrideActive));
  }
  if (m.secure_write) {
    const Expr off = Builder::negate(b.tag(m.secure_write->enable_tag));
    if (soft_cause)
      b.add("matrix.secure_write.refused", "secure-write",
            "Secure write disabled: the soft bypass of " + label(*soft_cause) + " is refused",
            {model::Node::Kind::Cause, soft_cause->id}, first_sif(soft_cause->sif),
            Builder::all({off, Builder::issued(model::CommandOp::SoftBypassCause, soft_cause->id, 0, true),
                          Builder::negate(b.cause(*soft_cause, CF::SoftBypassed))}),
            1, {ck(*soft_cause, CF::SoftBypassed)});
    else if (soft_effect)
      b.add("matrix.secure_write.refused", "secure-write",
            "Secure write disabled: the soft bypass of " + label(*soft_effect) + " is refused",
            {model::Node::Kind::Effect, soft_effect->id}, first_sif(soft_effect->sif),
            Builder::all({off, Builder::issued(model::CommandOp::SoftBypassEffect, 0, soft_effect->id, true),
                          Builder::negate(b.effect(*soft_effect, EF::SoftBypassed))}),
            1, {ek(*soft_effect, EF::SoftBypassed)});
  }
  // An effect that a cause reaches only through internal references (I.3:
  // cause 6 reads `Effect[1][2]` and drives effect 2, so every cause of
  // effect 1 trips effect 2 as well) is covered by no `none` objective, and
  // an intersection added in that empty cell changes nothing a run without
  // maintenance shows. Forcing the referenced output (simulate_tag, E.10)
  // interrupts the reference: the cause active, the effect not bypassed and
  // inactive. Where no forcing interrupts it (`Effect[x]` reads the active
  // state itself), the objective is proved infeasible: the effect follows the
  // cause whatever the operator does, which the report lists. Last in the
  // catalogue, so tests that force outputs come after the others.
  for (const auto& [c, e] : apart)
    b.add("reference.c" + std::to_string(c->id) + ".e" + std::to_string(e->id) + ".apart", "reference",
          label(*c) + " active while " + label(*e) +
              ", which it reaches only through internal references, stays inactive when the reference is forced"
              " (output simulation)",
          {model::Node::Kind::Cause, c->id}, first_sif(c->sif),
          Builder::all({b.cause(*c, CF::Active), Builder::negate(b.effect(*e, EF::Active)),
                        Builder::negate(b.effect(*e, EF::Bypassed))}),
          // The cause's own time function first (an on-delay of 2 s is 40
          // cycles): the horizon lets accelerated BMC hold the inputs.
          b.cycles(c->time.ms) + 2,
          {ck(*c, CF::Active), ek(*e, EF::Active)}, true);
}

}  // namespace cemv::testgen::detail
