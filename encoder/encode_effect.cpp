// Phase 3 of M.1 for one effect: docs/semantics.md section E as formulas, one
// step per paragraph. The order of the steps is also the creation order of
// their state variables, which fixes the encoding's text (SMT-LIB export):
// keep it.
#include <algorithm>
#include <stdexcept>

#include "encoder/builder.hpp"

namespace cemv::encoder::detail {

void EffectEncoder::build_effect(const model::Effect& ef) {
  const EffectRequests req = effect_requests(ef);
  const EffectReads reads = effect_reads(ef);
  const EffectOverride ov = effect_override(ef, req, reads);
  const EffectLatches latches = effect_latches(ef, req, reads, ov);
  // E.6: active.
  const expr active = (req.N || latches.s || ((req.V || latches.r) && !ov.running)) && !reads.bypassed;
  reads_.set_effect_active(ef.id, active);
  const EffectOutputDelay delay = effect_output_delay(ef, active, reads.output_delay_before);
  const EffectOutputs out = effect_outputs(ef, delay.output_state);
  name_effect_terms(ef, req, reads, ov, latches, active, delay, out);
}

// E.2: the requests per intersection type, an XooN group counted as one.
EffectEncoder::EffectRequests EffectEncoder::effect_requests(const model::Effect& ef) {
  std::map<model::IntersectionType, std::vector<expr>> direct;
  std::vector<expr> xoon_members;
  std::optional<model::IntersectionType> xoon_type;
  int xoon_x = 0;
  std::vector<std::pair<int, expr>> linked;
  for (const auto* is : m_.intersections_of_effect(ef.id)) {
    if (!model::is_processed(is->type)) continue;
    const model::Cause* cz = m_.find_cause(is->cause);
    if (!cz || cz->function == model::CauseFunction::Comment) continue;
    const std::optional<expr> active = reads_.evaluated_cause(is->cause);
    if (!active) throw std::logic_error("cause read before evaluation");
    if (is->xoon) {
      linked.emplace_back(is->cause, *active);
      xoon_members.push_back(*active);
      xoon_type = is->type;
      xoon_x = xoon_x == 0 ? *is->xoon : std::min(xoon_x, *is->xoon);
    } else {
      // Guarded (EncodeOptions::guard_cells): without the cell the cause
      // requests nothing of this effect.
      const expr on = guarded("intersection[" + std::to_string(is->cause) + "," + std::to_string(ef.id) + "]",
                              *active);
      linked.emplace_back(is->cause, on);
      direct[is->type].push_back(on);
    }
  }
  auto req = [&](model::IntersectionType t) {
    std::vector<expr> parts = direct[t];
    if (xoon_type && *xoon_type == t) parts.push_back(count(xoon_members) >= xoon_x);
    return any(parts);
  };
  expr reqN = req(model::IntersectionType::N);
  expr reqS = req(model::IntersectionType::S);
  expr reqV = req(model::IntersectionType::V);
  expr reqR = req(model::IntersectionType::R);
  return {reqN, reqS, reqV, reqR, std::move(linked)};
}

// E.1: the reads of this cycle: bypass (hard or soft), the override toggle
// (commands, or the reset tag's rising edge, T.4), prev(output_delay_running).
EffectEncoder::EffectReads EffectEncoder::effect_reads(const model::Effect& ef) {
  const Node self{Node::Kind::Effect, ef.id};
  const std::string P = effect_prefix(ef.id);
  const CommandStates::EffectCommands& cmds = cmds_.effect_cmds.at(ef.id);
  expr hard = ef.bypass_tag ? guarded(P + ".bypass_tag", reads_.bool_read(*ef.bypass_tag, self)) : B(false);
  expr bypassed = hard || cmds.sb_on;
  expr toggle = cmds.toggle;
  if (ef.reset_tag) {
    const expr edge = reads_.edge_of("prev." + P + ".reset_tag", reads_.bool_read(*ef.reset_tag, self));
    toggle = guard_cells_ ? z3::ite(guard(P + ".reset_tag"), edge, cmds.toggle) : edge;
  }
  expr od_prev = bool_state(P + ".output_delay_running_prev", false);
  return {bypassed, toggle, od_prev};
}

// E.3: the override, its end conditions (step 1), the toggle (step 2) and the
// prealarm (step 3). Without an override time, a toggle is a reset (E.4).
EffectEncoder::EffectOverride EffectEncoder::effect_override(const model::Effect& ef, const EffectRequests& req,
                                                 const EffectReads& reads) {
  const CommandStates::EffectCommands& cmds = cmds_.effect_cmds.at(ef.id);
  const expr& toggle = reads.toggle;
  expr ov_now = B(false), fail_t = B(false), fail_c = B(false), prealarm = B(false);
  expr was_running = B(false);
  expr reset = cmds.reset;
  if (!ef.override_time) {
    reset = reset || toggle;
    return {ov_now, was_running, fail_t, fail_c, prealarm, reset};
  }
  const std::string P = effect_prefix(ef.id);
  const int d = cycles_of(std::uint64_t{ef.override_time->max_s} * 1000, m_.cycle_ms);
  expr ov = bool_state(P + ".override", false);
  was_running = ov;
  expr cntv = counter(P + ".override.elapsed", d);
  expr alarm_t = bool_state(P + ".override_failed_timeout", false);
  expr alarm_c = bool_state(P + ".override_failed_cause", false);
  expr running = ov && !reads_.gd();  // M.2
  std::vector<expr> newcomers;
  std::vector<std::pair<expr, expr>> snaps;  // (state, active)
  for (auto& [cid, a] : req.linked) {
    expr snap = bool_state(P + ".override.started_with[" + std::to_string(cid) + "]", false);
    snaps.emplace_back(snap, a);
    newcomers.push_back(a && !snap);
  }
  // Step 1: end conditions.
  expr timeout = running && cntv >= d;
  expr by_cause = running && any(newcomers);
  expr gone = running && !(req.V || req.R);
  running = running && !timeout && !by_cause && !gone;
  // Step 2: toggle.
  expr stop = toggle && running;
  expr start = toggle && !running && (req.V || req.R) && !reads.bypassed && !reads.output_delay_before;
  reset = reset || (toggle && !running && !start);
  running = (running && !stop) || start;
  ov_now = running;
  expr elapsed = z3::ite(start, I(0), cntv);
  fail_t = !start && ((alarm_t && !cmds.clear_alarms) || timeout);
  fail_c = !start && ((alarm_c && !cmds.clear_alarms) || by_cause);
  // Step 3: prealarm.
  if (ef.override_time->prealarm_s > 0) {
    const int pre = cycles_of(std::uint64_t{ef.override_time->prealarm_s} * 1000, m_.cycle_ms);
    prealarm = running && elapsed >= pre;
  }
  for (auto& [snap, a] : snaps) ts_.assign_next(snap, z3::ite(start, a, snap));
  ts_.assign_next(ov, running);
  ts_.assign_next(cntv, z3::ite(running, sat_inc(elapsed, d), I(0)));
  ts_.assign_next(alarm_t, fail_t);
  ts_.assign_next(alarm_c, fail_c);
  return {ov_now, was_running, fail_t, fail_c, prealarm, reset};
}

// E.4: reset, E.5: the S and R latches.
EffectEncoder::EffectLatches EffectEncoder::effect_latches(const model::Effect& ef, const EffectRequests& req,
                                               const EffectReads& reads, const EffectOverride& ov) {
  const std::string P = effect_prefix(ef.id);
  const expr& od_prev = reads.output_delay_before;
  expr s_latch = bool_state(P + ".s_latch", false);
  expr r_latch = bool_state(P + ".r_latch", false);
  expr req_r_prev = bool_state(P + ".req_r_prev", false);
  expr s_now = (s_latch && !(ov.reset && !req.S && !od_prev)) || req.S;
  expr r_now = ((r_latch && !(ov.reset && !req.R && !od_prev)) || req.R) &&
               !(req_r_prev && !req.R && ov.was_running);
  ts_.assign_next(s_latch, s_now);
  ts_.assign_next(r_latch, r_now);
  ts_.assign_next(req_r_prev, req.R);
  return {s_now, r_now};
}

// E.7: the output delay: OS follows active once it has held for the delay.
EffectEncoder::EffectOutputDelay EffectEncoder::effect_output_delay(const model::Effect& ef, const expr& active,
                                                        const expr& output_delay_before) {
  const std::string P = effect_prefix(ef.id);
  expr os = active;
  const int od = cycles_of(ef.output_delay_ms, m_.cycle_ms);
  if (od > 0) {
    expr os_prev = bool_state(P + ".output_state_prev", false);
    expr held = counter(P + ".output_delay.elapsed", od);  // cycles active before this one
    os = active && (os_prev || reads_.first() || held >= od);
    ts_.assign_next(os_prev, os);
    ts_.assign_next(held, z3::ite(active, sat_inc(held, od), I(0)));
  }
  expr od_running = active && !os;
  ts_.assign_next(output_delay_before, od_running);
  return {os, od_running};
}

// E.8: pass-through and mask, E.9: the output tags, E.10: output simulation;
// each output is a named term `effect[ID].tag[k]`.
EffectEncoder::EffectOutputs EffectEncoder::effect_outputs(const model::Effect& ef, const expr& os) {
  const Node self{Node::Kind::Effect, ef.id};
  const std::string P = effect_prefix(ef.id);
  EffectOutputs out{false, false, B(false)};
  expr process = B(false);
  if (ef.process_data && ef.process_data->tag) {
    process = reads_.bool_read(*ef.process_data->tag, self);
    out.pass = ef.process_data->pass_through;
    if (ef.process_data->mask_tag) {
      out.has_mask = true;
      out.mask = reads_.bool_read(*ef.process_data->mask_tag, self);
    }
  }
  for (std::size_t j = 0; j < ef.tags.size(); ++j) {
    const auto& tag = ef.tags[j];
    expr safe = B(tag.ett);
    expr logic = tag.ett ? os : !os;
    expr pv = tag.ett ? !process : process;
    expr value = logic;
    if (out.pass && out.has_mask) value = z3::ite(os, z3::ite(out.mask, pv, safe), pv);
    else if (out.pass) value = z3::ite(os, safe, pv);
    else if (out.has_mask) value = z3::ite(out.mask, pv, logic);
    const Simulation& s = cmds_.sims.at(model::tag_key(tag.name));
    value = z3::ite(s.on, s.value, value);
    reads_.set_effect_tag(ef.id, static_cast<int>(j + 1), value);
    ts_.name_term(P + ".tag[" + std::to_string(j + 1) + "]", value);
  }
  return out;
}

// E.11: the status fields, each a named term under its observable key.
void EffectEncoder::name_effect_terms(const model::Effect& ef, const EffectRequests& req,
                                const EffectReads& reads, const EffectOverride& ov,
                                const EffectLatches& latches, const expr& active,
                                const EffectOutputDelay& delay, const EffectOutputs& out) {
  const std::string P = effect_prefix(ef.id);
  const CommandStates::EffectCommands& cmds = cmds_.effect_cmds.at(ef.id);
  const expr latched = latches.s || latches.r;
  ts_.name_term(P + ".active", active);
  ts_.name_term(P + ".latched", latched);
  ts_.name_term(P + ".ok_to_reset", latched && !req.S && !req.R && !delay.running);
  ts_.name_term(P + ".override_active", ov.running);
  ts_.name_term(P + ".override_failed_timeout", ov.failed_timeout);
  ts_.name_term(P + ".override_failed_cause", ov.failed_cause);
  ts_.name_term(P + ".override_prealarm", ov.prealarm);
  ts_.name_term(P + ".bypassed", reads.bypassed);
  ts_.name_term(P + ".soft_bypassed", cmds.sb_on);
  ts_.name_term(P + ".masked", out.has_mask ? out.mask : B(false));
  ts_.name_term(P + ".pass_through_active", out.pass ? expr(!delay.output_state) : B(false));
  ts_.name_term(P + ".output_delay_running", delay.running);
}

}  // namespace cemv::encoder::detail
