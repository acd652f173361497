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

std::string others_inactive(const model::Matrix& m, const std::vector<const model::Intersection*>& ls, int except) {
  std::string s;
  for (const auto* x : ls)
    if (x->cause != except) s += " and not " + ck(cause_of(m, x->cause), "active");
  return s;
}

std::string any_active(const model::Matrix& m, const std::vector<const model::Intersection*>& ls,
                       bool (*keep)(IntersectionType)) {
  std::vector<std::string> parts;
  for (const auto* x : ls)
    if (keep(x->type)) parts.push_back(ck(cause_of(m, x->cause), "active"));
  return parts.empty() ? "false" : "(" + join(parts, " or ") + ")";
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

}  // namespace

void intersection_objectives(ObjectiveBuilder& b, const Effect& e) {
  const model::Matrix& m = b.matrix();
  const auto ls = links(m, e);
  const model::Node node{model::Node::Kind::Effect, e.id};
  const std::string act = ek(e, "active");
  for (const auto* x : ls) {
    if (x->xoon) continue;
    const model::Cause& c = cause_of(m, x->cause);
    const std::string id = "intersection.c" + std::to_string(c.id) + ".e" + std::to_string(e.id);
    const std::string type = model::to_string(x->type);
    const int sif = sif_of(m, *x, e);
    const std::string others = others_inactive(m, ls, c.id);
    b.add(id + ".trip", "intersection",
          label(c) + " alone trips " + label(e) + " (intersection " + type + ")", node, sif,
          "rose(" + act + ") and " + ck(c, "active") + others, 1, {ck(c, "active"), act});
    if (latching(x->type))
      b.add(id + ".latched", "intersection",
            label(e) + " stays latched after " + label(c) + " clears (intersection " + type + ")", node, sif,
            "fell(" + ck(c, "active") + ") and " + act + " and " + ek(e, "latched") + others, 2,
            {ck(c, "active"), act, ek(e, "latched")});
    else
      b.add(id + ".follow", "intersection",
            label(e) + " goes inactive with " + label(c) + " (intersection " + type + ")", node, sif,
            "fell(" + ck(c, "active") + ") and fell(" + act + ")" + others, 2, {ck(c, "active"), act});
    if (overridable(x->type) && e.override_time)
      b.add(id + ".overridden", "intersection",
            "Override of " + label(e) + " suppresses the request of " + label(c) + " (intersection " + type + ")", node,
            sif, ck(c, "active") + " and " + ek(e, "override_active") + " and not " + act + others, 2,
            {ck(c, "active"), act, ek(e, "override_active")});
    // N and S requests ignore an override (E.6): an S or N cell changed to R
    // or V would let it through. The toggle must be one that would start an
    // override on a V/R request (E.3 step 2): a reset-tag edge where the
    // effect has a reset tag (the override command is refused then, O.3),
    // no override running, the effect not bypassed, no output delay running.
    if (!overridable(x->type) && e.override_time) {
      const std::string ov = ek(e, "override_active");
      const std::string toggle =
          e.reset_tag ? "rose(" + tag_atom(*e.reset_tag) + ")"
                      : "issued(override_effect, effect = " + std::to_string(e.id) + ")" +
                            (m.secure_write ? " and " + tag_atom(m.secure_write->enable_tag) : "");
      b.add(id + ".not_overridden", "intersection",
            "An override of " + label(e) + " does not suppress the request of " + label(c) + " (intersection " +
                type + ")",
            node, sif,
            toggle + " and not prev(" + ov + ") and not " + ek(e, "bypassed") +
                (e.output_delay_ms > 0 ? " and not prev(" + ek(e, "output_delay_running") + ")" : "") + " and " +
                ck(c, "active") + " and " + act + " and not " + ov + others,
            2, {ck(c, "active"), act, ov});
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
  std::vector<std::string> counted;
  std::string others;
  for (const auto* x : ls) {
    if (x->xoon) counted.push_back(ck(cause_of(m, x->cause), "active"));
    else others += " and not " + ck(cause_of(m, x->cause), "active");
  }
  const std::string cnt = "count(" + join(counted, ", ") + ")";
  const std::string id = "xoon.e" + std::to_string(e.id);
  const std::string xn = std::to_string(x_min) + "oo" + std::to_string(xoon.size());
  const int sif = sif_of(m, *xoon.front(), e);
  b.add(id + ".below", "xoon", label(e) + ": " + xn + " with " + std::to_string(x_min - 1) + " cause(s) active does not trip",
        node, sif, cnt + " == " + std::to_string(x_min - 1) + " and not " + act + " and not " + ek(e, "latched") + others,
        1, {act});
  b.add(id + ".at", "xoon", label(e) + ": " + xn + " with " + std::to_string(x_min) + " causes active trips", node, sif,
        "rose(" + act + ") and " + cnt + " == " + std::to_string(x_min) + others, 2, {act});
}

void effect_objectives(ObjectiveBuilder& b, const Effect& e) {
  const model::Matrix& m = b.matrix();
  const auto ls = links(m, e);
  const model::Node node{model::Node::Kind::Effect, e.id};
  const std::string id = "effect." + std::to_string(e.id);
  const int sif = first_sif(e.sif);
  const std::string act = ek(e, "active"), latched = ek(e, "latched"), odr = ek(e, "output_delay_running");
  const std::string any = any_active(m, ls, any_type);
  bool has_latch = false, has_vr = false;
  for (const auto* x : ls) {
    has_latch |= latching(x->type);
    has_vr |= overridable(x->type);
  }
  // Reset (E.4, O.2).
  if (has_latch) {
    const std::string rq = e.reset_tag ? "rose(" + tag_atom(*e.reset_tag) + ")"
                                       : "issued(reset_effect, effect = " + std::to_string(e.id) + ")" +
                                             (m.secure_write ? " and " + tag_atom(m.secure_write->enable_tag) : "");
    const std::string how = e.reset_tag ? "Reset with " + *e.reset_tag : "Reset command";
    const std::string latching_causes = any_active(m, ls, latching);
    b.add(id + ".reset.refused_cause", "reset", how + " for " + label(e) + " refused while a latching cause is active",
          node, sif, rq + " and prev(" + latched + ") and " + latched + " and " + latching_causes, 2,
          {latched, act, ek(e, "ok_to_reset")});
    if (e.output_delay_ms > 0)
      b.add(id + ".reset.refused_delay", "reset", how + " for " + label(e) + " refused while the output delay runs",
            node, sif, rq + " and prev(" + latched + ") and " + latched + " and prev(" + odr + ") and not " + latching_causes,
            2, {latched, act, odr});
    b.add(id + ".reset.accepted", "reset", how + " for " + label(e) + " accepted once the causes have cleared", node, sif,
          rq + " and prev(" + latched + ") and not " + latched, 2, {latched, act});
  }
  // Override (E.3, O.3).
  if (e.override_time && has_vr) {
    const std::string tg = e.reset_tag ? "rose(" + tag_atom(*e.reset_tag) + ")"
                                       : "(issued(override_effect, effect = " + std::to_string(e.id) +
                                             ") or issued(stop_override, effect = " + std::to_string(e.id) + "))";
    const std::string ov = ek(e, "override_active");
    b.add(id + ".override.start", "override", "Override of " + label(e) + " started", node, sif, "rose(" + ov + ")", 2,
          {ov, act});
    b.add(id + ".override.stop", "override", "Override of " + label(e) + " stopped by the operator", node, sif,
          "fell(" + ov + ") and " + tg + " and not " + ek(e, "override_failed_timeout") + " and not " +
              ek(e, "override_failed_cause"),
          3, {ov, act});
    if (e.override_time->max_s > 0)
      b.add(id + ".override.timeout", "override",
            "Override of " + label(e) + " times out after " + std::to_string(e.override_time->max_s) +
                " s with the timeout alarm",
            node, sif, "rose(" + ek(e, "override_failed_timeout") + ")", b.cycles(e.override_time->max_s * 1000ULL) + 2,
            {ov, ek(e, "override_failed_timeout"), act});
    // The cycle before each boundary too: a timeout or prealarm moved earlier
    // shows there (T.2: started in cycle s, the override runs s .. s+D-1).
    auto on_for = [&](int n) {
      auto held = [&](int k) { return k <= 0 ? ov : "held(" + ov + ", " + std::to_string(k) + " cycles)"; };
      return ov + " and " + held(n - 1) + " and not " + held(n);
    };
    if (e.override_time->max_s > 0)
      b.add(id + ".override.timeout.before", "override",
            "Override of " + label(e) + ": still running one cycle before its timeout", node, sif,
            on_for(b.cycles(e.override_time->max_s * 1000ULL)), b.cycles(e.override_time->max_s * 1000ULL) + 1,
            {ov, ek(e, "override_failed_timeout"), act});
    if (e.override_time->prealarm_s > 0 && e.override_time->prealarm_s < e.override_time->max_s)
      b.add(id + ".override.prealarm.before", "override",
            "Override of " + label(e) + ": one cycle before its prealarm", node, sif,
            on_for(b.cycles(e.override_time->prealarm_s * 1000ULL)) + " and not " + ek(e, "override_prealarm"),
            b.cycles(e.override_time->prealarm_s * 1000ULL) + 1, {ov, ek(e, "override_prealarm")});
    if (e.override_time->prealarm_s > 0 && e.override_time->prealarm_s < e.override_time->max_s)
      b.add(id + ".override.prealarm", "override", "Override prealarm of " + label(e), node, sif,
            "rose(" + ek(e, "override_prealarm") + ")", b.cycles(e.override_time->prealarm_s * 1000ULL) + 2,
            {ek(e, "override_prealarm")});
    if (ls.size() >= 2)
      b.add(id + ".override.new_cause", "override", "Override of " + label(e) + " fails on a new cause", node, sif,
            "rose(" + ek(e, "override_failed_cause") + ")", 3, {ov, ek(e, "override_failed_cause"), act});
  }
  // Output delay (E.7).
  if (e.output_delay_ms > 0) {
    const int d = b.cycles(e.output_delay_ms);
    auto held = [](const std::string& x, int n) { return n == 0 ? x : "held(" + x + ", " + std::to_string(n) + " cycles)"; };
    const std::string dur = std::to_string(e.output_delay_ms) + " ms";
    b.add(id + ".delay.before", "output-delay", "Output delay (" + dur + ") of " + label(e) + ": one cycle before expiry",
          node, sif, odr + " and " + held(act, d - 1) + " and not " + held(act, d), d + 2, {odr, act});
    b.add(id + ".delay.expiry", "output-delay", "Output delay (" + dur + ") of " + label(e) + ": expiry cycle", node, sif,
          "prev(" + odr + ") and not " + odr + " and " + act, d + 3, {odr, act});
    // Restarted, not resumed: a bypass interrupts the running delay, and one
    // cycle before the full duration has run again since the bypass ended,
    // the outputs still wait (E.7 "any interruption ... restarts it").
    if (e.bypass_tag || e.soft_bypass_allowed)
      b.add(id + ".delay.restart", "output-delay",
            "Output delay (" + dur + ") of " + label(e) + " restarted by a bypass that interrupted it: one cycle "
            "before expiry, counted from the end of the bypass",
            node, sif,
            odr + " and " + held(act, d - 1) + " and not " + held(act, d) + " and within(" + ek(e, "bypassed") +
                " and prev(" + odr + "), " + std::to_string(2 * d + 4) + " cycles)",
            2 * d + 4, {odr, act, ek(e, "bypassed")});
  }
  // Bypass (E.1, E.6).
  if (e.bypass_tag)
    b.add(id + ".bypass.hard", "bypass", "Bypass tag " + *e.bypass_tag + " suppresses " + label(e), node, sif,
          tag_atom(*e.bypass_tag) + " and not " + ek(e, "soft_bypassed") + " and not " + act + " and " + any, 1,
          {ek(e, "bypassed"), act});
  if (e.soft_bypass_allowed)
    b.add(id + ".bypass.soft", "bypass", "Soft bypass of " + label(e) + " suppresses it", node, sif,
          ek(e, "soft_bypassed") + " and not " + act + " and " + any, 1, {ek(e, "soft_bypassed"), act});
  // Pass-through and mask (E.8, E.9): every row of the table.
  const bool pt = e.process_data && e.process_data->tag && e.process_data->pass_through;
  const bool mask = e.process_data && e.process_data->tag && e.process_data->mask_tag;
  std::vector<std::string> tags_observed;
  for (std::size_t k = 0; k < e.tags.size(); ++k) tags_observed.push_back(ek(e, "tag[" + std::to_string(k + 1) + "]"));
  if (pt || mask) {
    const std::string p = tag_atom(*e.process_data->tag);
    for (int os = 0; os <= 1; ++os)
      for (int mk = 0; mk <= (mask ? 1 : 0); ++mk)
        for (int pv = 0; pv <= 1; ++pv) {
          std::string expr = std::string(os ? "" : "not ") + "(" + act + " and not " + odr + ") and " +
                             (mask ? std::string(mk ? "" : "not ") + ek(e, "masked") + " and " : "") + (pv ? "" : "not ") + p;
          std::string text = "Pass-through/mask row of " + label(e) + ": outputs " + (os ? "acting" : "not acting") +
                             (mask ? std::string(", mask ") + (mk ? "on" : "off") : "") + ", process value " + (pv ? "1" : "0");
          auto obs = tags_observed;
          obs.push_back(ek(e, "pass_through_active"));
          obs.push_back(ek(e, "masked"));
          b.add(id + ".process.os" + std::to_string(os) + (mask ? ".m" + std::to_string(mk) : "") + ".p" + std::to_string(pv),
                "pass-through", text, node, sif, expr, 2, obs);
        }
  }
  // Output values, DTT/ETT (E.9).
  for (std::size_t k = 0; k < e.tags.size(); ++k) {
    const auto& t = e.tags[k];
    const std::string tk = ek(e, "tag[" + std::to_string(k + 1) + "]");
    const std::string kind = t.ett ? "ETT" : "DTT";
    b.add(id + ".tag" + std::to_string(k + 1) + ".safe", "output",
          "Output " + t.name + " (" + kind + ") goes to its safe value " + (t.ett ? "1" : "0") + " when " + label(e) + " acts",
          node, sif, act + " and not " + odr + (mask ? " and not " + ek(e, "masked") : "") + " and " + tk + " == " + (t.ett ? "true" : "false"),
          1, {tk});
    std::string normal = "not " + act;
    if (pt) normal += " and " + tag_atom(*e.process_data->tag);
    else if (mask) normal += " and not " + ek(e, "masked");
    b.add(id + ".tag" + std::to_string(k + 1) + ".normal", "output",
          "Output " + t.name + " (" + kind + ") at its normal value " + (t.ett ? "0" : "1") + " while " + label(e) + " is inactive",
          node, sif, normal + " and " + tk + " == " + (t.ett ? "false" : "true"), 1, {tk});
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
    std::vector<std::string> quiet;
    std::vector<std::string> seen{ck(c, "active")};
    for (const auto& e : m.effects) {
      if (e.function == model::EffectFunction::Comment) continue;
      if (std::binary_search(reach.begin(), reach.end(), model::Node{model::Node::Kind::Effect, e.id})) {
        if (!linked(m, c.id, e)) apart.push_back({&c, &e});
        continue;
      }
      quiet.push_back("not " + ek(e, "active"));
      seen.push_back(ek(e, "active"));
    }
    if (quiet.empty()) continue;
    b.add("intersection.c" + std::to_string(c.id) + ".none", "intersection",
          label(c) + " trips none of the effects it has no intersection with", {model::Node::Kind::Cause, c.id},
          first_sif(c.sif), ck(c, "active") + " and " + join(quiet, " and "), 1, seen);
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
    const std::string edge = "rose(" + tag_atom(m.group_deactivation->set_tag) + ") and " +
                             tag_atom(m.group_deactivation->enable_tag);
    auto ends = [&](const std::string& id, const std::string& what, model::Node n, int sif, const std::string& key) {
      b.add("matrix.group_deactivation." + id, "group-deactivation", "Group deactivation ends the " + what, n, sif,
            edge + " and prev(" + key + ") and not " + key, 3, {key});
    };
    if (soft_cause)
      ends("cause_bypass", "soft bypass of " + label(*soft_cause), {model::Node::Kind::Cause, soft_cause->id},
           first_sif(soft_cause->sif), ck(*soft_cause, "soft_bypassed"));
    if (soft_effect)
      ends("effect_bypass", "soft bypass of " + label(*soft_effect), {model::Node::Kind::Effect, soft_effect->id},
           first_sif(soft_effect->sif), ek(*soft_effect, "soft_bypassed"));
    if (override_effect)
      ends("override", "override of " + label(*override_effect), {model::Node::Kind::Effect, override_effect->id},
           first_sif(override_effect->sif), ek(*override_effect, "override_active"));
  }
  if (m.secure_write) {
    const std::string off = "not " + tag_atom(m.secure_write->enable_tag);
    if (soft_cause)
      b.add("matrix.secure_write.refused", "secure-write",
            "Secure write disabled: the soft bypass of " + label(*soft_cause) + " is refused",
            {model::Node::Kind::Cause, soft_cause->id}, first_sif(soft_cause->sif),
            off + " and issued(soft_bypass_cause, cause = " + std::to_string(soft_cause->id) + ", on = true) and not " +
                ck(*soft_cause, "soft_bypassed"),
            1, {ck(*soft_cause, "soft_bypassed")});
    else if (soft_effect)
      b.add("matrix.secure_write.refused", "secure-write",
            "Secure write disabled: the soft bypass of " + label(*soft_effect) + " is refused",
            {model::Node::Kind::Effect, soft_effect->id}, first_sif(soft_effect->sif),
            off + " and issued(soft_bypass_effect, effect = " + std::to_string(soft_effect->id) + ", on = true) and not " +
                ek(*soft_effect, "soft_bypassed"),
            1, {ek(*soft_effect, "soft_bypassed")});
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
          ck(*c, "active") + " and not " + ek(*e, "active") + " and not " + ek(*e, "bypassed"),
          // The cause's own time function first (an on-delay of 2 s is 40
          // cycles): the horizon lets accelerated BMC hold the inputs.
          b.cycles(c->time.ms) + 2,
          {ck(*c, "active"), ek(*e, "active")}, true);
}

}  // namespace cemv::testgen::detail
