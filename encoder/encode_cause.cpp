// Phase 3 of M.1 for one cause, and phase 4 (first out): docs/semantics.md
// section C as formulas, one step per paragraph, in the order of the paragraphs.
// The order of the steps is also the creation order of their state variables,
// which fixes the encoding's text (SMT-LIB export): keep it.
#include <algorithm>
#include <stdexcept>

#include "encoder/builder.hpp"

namespace cemv::encoder::detail {

void CauseEncoder::build_cause(const model::Cause& cz) {
  const CauseSoftBypass sb = cause_soft_bypass(cz);
  const CauseTags tags = cause_tag_values(cz);
  const CauseVote vote = cause_voting(cz, tags);
  const expr delta_alarm = cause_delta_alarm(cz, tags);
  const expr prewarning = cause_prewarning(cz, tags);
  const CauseTime time = cause_time_function(cz, vote.tr);
  const CauseActive a = cause_latch_and_active(cz, sb.on, vote.tr, time.tm);
  reads_.set_cause_active(cz.id, a.active);
  name_cause_terms(cz, sb, vote, delta_alarm, prewarning, time, a);
}

// C.1: timed soft bypass, expiry checked at the start of the evaluation.
CauseEncoder::CauseSoftBypass CauseEncoder::cause_soft_bypass(const model::Cause& cz) {
  const std::string P = cause_prefix(cz.id);
  const CommandStates::CauseCommands& cmds = cmds_.cause_cmds.at(cz.id);
  expr sb = cmds.sb_on;
  expr bypass_timeout = B(false);
  expr bypass_prealarm = B(false);
  expr alarm = bool_state(P + ".bypass_timeout", false);
  expr kept = alarm && !cmds.clear_alarms;
  if (cz.soft_bypass.allowed && cz.soft_bypass.max_s > 0) {
    const int d = cycles_of(std::uint64_t{cz.soft_bypass.max_s} * 1000, m_.cycle_ms);
    expr cntv = counter(P + ".soft_bypass.elapsed", d);
    expr elapsed = z3::ite(cmds.sb_start, I(0), cntv);
    expr expired = sb && elapsed >= d;
    sb = sb && !expired;
    if (cz.soft_bypass.prealarm_s > 0) {
      const int pre = cycles_of(std::uint64_t{cz.soft_bypass.prealarm_s} * 1000, m_.cycle_ms);
      bypass_prealarm = sb && elapsed >= pre;
    }
    ts_.assign_next(cntv, z3::ite(sb, sat_inc(elapsed, d), I(0)));
    bypass_timeout = kept || expired;
  } else {
    bypass_timeout = kept;
  }
  ts_.assign_next(alarm, bypass_timeout);
  ts_.assign_next(cmds.sb_prev, sb);
  return {sb, bypass_timeout, bypass_prealarm};
}

// C.2: tag values and qualities: the simulation (O.8), the internal reference
// (I.3, good quality) or this cycle's input.
CauseEncoder::CauseTags CauseEncoder::cause_tag_values(const model::Cause& cz) {
  const Node self{Node::Kind::Cause, cz.id};
  CauseTags out;
  for (const auto& tag : cz.tags) {
    if (auto ref = model::parse_internal_ref(tag.name)) {
      out.values.push_back(reads_.ref_value(*ref, self));
      out.bads.push_back(B(false));
      continue;
    }
    std::size_t idx = *enc_.inputs.find(tag.name);
    expr raw = reads_.raw_value(idx);
    expr bad = reads_.raw_bad(idx);
    const Simulation& s = cmds_.sims.at(model::tag_key(tag.name));
    out.values.push_back(z3::ite(s.on, s.value, raw));
    out.bads.push_back(bad && !s.on);
  }
  return out;
}

// C.3: trip, taken out. C.4: voting with degraded voting and hysteresis.
CauseEncoder::CauseVote CauseEncoder::cause_voting(const model::Cause& cz, const CauseTags& tags) {
  const std::string P = cause_prefix(cz.id);
  const int n = static_cast<int>(cz.tags.size());
  const bool analog = cz.input == model::InputKind::Analog && cz.analog.has_value();
  const model::AnalogParams ap = analog ? *cz.analog : model::AnalogParams{};
  const bool high = ap.limit_type == model::LimitType::High;
  const CommandStates::CauseCommands& cmds = cmds_.cause_cmds.at(cz.id);
  const auto& values = tags.values;
  const auto& bads = tags.bads;

  expr hyst_mode = bool_state(P + ".trip_requested_prev", false);
  const float relaxed = high ? ap.limit - ap.hysteresis : ap.limit + ap.hysteresis;
  std::vector<expr> tripped, tripped_strict, out_bad, out;
  for (int t = 0; t < n; ++t) {
    const auto& tag = cz.tags[static_cast<std::size_t>(t)];
    expr by_value = B(false), by_value_strict = B(false);
    if (!analog) {
      by_value = tag.ett ? values[t] : !values[t];
      by_value_strict = by_value;
    } else {
      by_value_strict = high ? fge(values[t], fconst(ap.limit)) : fle(values[t], fconst(ap.limit));
      expr relax = high ? fge(values[t], fconst(relaxed)) : fle(values[t], fconst(relaxed));
      by_value = z3::ite(hyst_mode, relax, by_value_strict);
    }
    expr tsb = cmds.tag_sb[static_cast<std::size_t>(t)];
    expr ob = cz.bad_quality == model::BadQuality::Degrade ? (bads[t] && !tsb) : B(false);
    bool trip_bad = cz.bad_quality == model::BadQuality::Trip;
    tripped.push_back(trip_bad ? (bads[t] || by_value) : by_value);
    tripped_strict.push_back(trip_bad ? (bads[t] || by_value_strict) : by_value_strict);
    out_bad.push_back(ob);
    out.push_back(tsb || ob);
  }
  std::vector<expr> counted, counted_strict;
  for (int t = 0; t < n; ++t) {
    counted.push_back(tripped[t] && !out[t]);
    counted_strict.push_back(tripped_strict[t] && !out[t]);
  }
  expr k = count(out);
  expr cnt = count(counted);
  expr cnt_strict = count(counted_strict);
  expr any_bad_out = any(out_bad);
  int X = 1;
  if (cz.function == model::CauseFunction::And) X = n;
  if (cz.function == model::CauseFunction::TwoOoThree) X = 2;
  auto voting_code = [](int x, int of) -> int {
    using V = model::Voting;
    if (of == 1) return static_cast<int>(V::OneOoOne);
    if (of == 2) return static_cast<int>(x == 1 ? V::OneOoTwo : V::TwoOoTwo);
    return static_cast<int>(x == 1 ? V::OneOoThree : x == 2 ? V::TwoOoThree : V::ThreeOoThree);
  };
  expr tr = any_bad_out;  // m = 0
  expr tr_strict = any_bad_out;
  expr voting = z3::ite(any_bad_out, I(static_cast<int>(model::Voting::OneOoOne)),
                        I(static_cast<int>(model::Voting::Bypass)));
  for (int k0 = n - 1; k0 >= 0; --k0) {
    int xk = std::max(1, X - k0);
    tr = z3::ite(k == k0, cnt >= xk, tr);
    tr_strict = z3::ite(k == k0, cnt_strict >= xk, tr_strict);
    voting = z3::ite(k == k0, I(voting_code(xk, n - k0)), voting);
  }
  ts_.assign_next(hyst_mode, tr);
  return {hyst_mode, tr, tr_strict, k, cnt, voting};
}

// C.5: delta alarm per pair of tags (status only).
expr CauseEncoder::cause_delta_alarm(const model::Cause& cz, const CauseTags& tags) {
  const bool analog = cz.input == model::InputKind::Analog && cz.analog.has_value();
  const int n = static_cast<int>(cz.tags.size());
  if (!analog || cz.analog->delta <= 0.0f || n < 2) return B(false);
  const model::AnalogParams& ap = *cz.analog;
  const std::string P = cause_prefix(cz.id);
  std::vector<expr> pairs;
  const float clear_below = ap.delta - ap.hysteresis;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      expr st = bool_state(
          P + ".delta[" + std::to_string(i + 1) + "][" + std::to_string(j + 1) + "]", false);
      expr diff = fabs_diff(tags.values[i], tags.values[j]);
      expr now = z3::ite(fge(diff, fconst(ap.delta)), B(true),
                         z3::ite(flt(diff, fconst(clear_below)), B(false), st));
      ts_.assign_next(st, now);
      pairs.push_back(now);
    }
  return any(pairs);
}

// C.5: prewarning (status only), when it lies before the limit.
expr CauseEncoder::cause_prewarning(const model::Cause& cz, const CauseTags& tags) {
  const bool analog = cz.input == model::InputKind::Analog && cz.analog.has_value();
  if (!analog || !cz.analog->prewarning) return B(false);
  const model::AnalogParams& ap = *cz.analog;
  const bool high = ap.limit_type == model::LimitType::High;
  if (!(high ? *ap.prewarning < ap.limit : *ap.prewarning > ap.limit)) return B(false);
  std::vector<expr> pw;
  for (const auto& v : tags.values)
    pw.push_back(high ? fge(v, fconst(*ap.prewarning)) : fle(v, fconst(*ap.prewarning)));
  return any(pw);
}

// C.6: time function, TR -> TM.
CauseEncoder::CauseTime CauseEncoder::cause_time_function(const model::Cause& cz, const expr& tr) {
  const std::string P = cause_prefix(cz.id);
  const int d = cycles_of(cz.time.ms, m_.cycle_ms);
  expr tm = tr;
  expr timer_running = B(false);
  switch (cz.time.mode) {
    case model::TimeMode::None:
      break;
    case model::TimeMode::OnDelay: {
      // Counter = cycles TR has held before this cycle (saturating at D).
      expr held = counter(P + ".on_delay.elapsed", d);
      tm = tr && held >= d;
      timer_running = tr && !tm;
      ts_.assign_next(held, z3::ite(tr, sat_inc(held, d), I(0)));
      break;
    }
    case model::TimeMode::OffDelay: {
      expr tm_prev = bool_state(P + ".off_delay.tm_prev", false);
      expr since = counter(P + ".off_delay.elapsed", d);
      tm = tr || (tm_prev && since < d);
      timer_running = !tr && tm;
      ts_.assign_next(tm_prev, tm);
      ts_.assign_next(since, z3::ite(tr, I(0), sat_inc(since, d)));
      break;
    }
    case model::TimeMode::Timed: {
      expr tr_prev = bool_state(P + ".timed.tr_prev", false);
      expr running = bool_state(P + ".timed.running", false);
      expr cntv = counter(P + ".timed.elapsed", d);
      expr cont = running && cntv < d;
      expr start = tr && !tr_prev && !cont;
      tm = cont || (start && B(d > 0));
      expr elapsed = z3::ite(start, I(0), cntv);
      timer_running = tm;
      ts_.assign_next(tr_prev, tr);
      ts_.assign_next(running, tm);
      ts_.assign_next(cntv, z3::ite(tm, sat_inc(elapsed, d), I(0)));
      ts_.add_lemma(P + ".timed.running_bound", z3::implies(running, cntv <= d));
      break;
    }
  }
  return {tm, timer_running};
}

// C.8 reads (bypass and inhibit of this cycle), C.7 acknowledgement latch,
// C.8 active.
CauseEncoder::CauseActive CauseEncoder::cause_latch_and_active(const model::Cause& cz, const expr& soft_bypass,
                                                     const expr& tr, const expr& tm) {
  const Node self{Node::Kind::Cause, cz.id};
  const CommandStates::CauseCommands& cmds = cmds_.cause_cmds.at(cz.id);
  const std::string P = cause_prefix(cz.id);
  expr hard = cz.bypass_tag ? guarded(P + ".bypass_tag", reads_.bool_read(*cz.bypass_tag, self)) : B(false);
  expr inhibited = cz.inhibit_tag ? guarded(P + ".inhibit_tag", reads_.bool_read(*cz.inhibit_tag, self)) : B(false);
  expr bypassed = hard || soft_bypass;
  expr latch_now = B(false);
  bool has_latch = !cz.auto_ack && (cz.time.mode == model::TimeMode::None ||
                                    cz.time.mode == model::TimeMode::OnDelay);
  if (has_latch) {
    expr latch = bool_state(cause_prefix(cz.id) + ".ack_latch", false);
    expr cleared = latch && !(cmds.ack && !tr);
    latch_now = cleared || (tm && !bypassed && !inhibited);
    ts_.assign_next(latch, latch_now);
  }
  expr active = (tm || latch_now) && !bypassed && !inhibited;
  return {bypassed, inhibited, latch_now, active};
}

// C.9: the status fields, each a named term under its observable key; first
// out (C.11) is named in phase 4 for a cause of a group.
void CauseEncoder::name_cause_terms(const model::Cause& cz, const CauseSoftBypass& sb,
                               const CauseVote& vote, expr delta_alarm, expr prewarning,
                               const CauseTime& time, const CauseActive& a) {
  const std::string P = cause_prefix(cz.id);
  const bool analog = cz.input == model::InputKind::Analog && cz.analog.has_value();
  ts_.name_term(P + ".active", a.active);
  ts_.name_term(P + ".trip_requested", vote.tr);
  ts_.name_term(P + ".tripped_tags", vote.tripped);
  ts_.name_term(P + ".voting", vote.voting);
  ts_.name_term(P + ".degraded", vote.taken_out > 0);
  ts_.name_term(P + ".bypassed", a.bypassed);
  ts_.name_term(P + ".soft_bypassed", sb.on);
  ts_.name_term(P + ".inhibited", a.inhibited);
  ts_.name_term(P + ".ack_required", a.ack_latch);
  ts_.name_term(P + ".hysteresis_active",
                analog ? expr(vote.hysteresis_mode && vote.tr && !vote.tr_strict) : B(false));
  ts_.name_term(P + ".delta_alarm", delta_alarm);
  ts_.name_term(P + ".prewarning", prewarning);
  ts_.name_term(P + ".timer_running", time.timer_running);
  ts_.name_term(P + ".bypass_timeout", sb.timeout);
  ts_.name_term(P + ".bypass_prealarm", sb.prealarm);
  if (cz.first_out_group >= 1 && cz.first_out_group <= model::kMaxFirstOutGroup)
    first_out_groups_[cz.first_out_group].emplace_back(cz.id, a.active);
  else
    ts_.name_term(P + ".first_out", B(false));
}

// ---- Phase 4: first out (C.11) -------------------------------------------------

void CauseEncoder::build_first_out() {
  for (auto& [group, members] : first_out_groups_) {
    std::sort(members.begin(), members.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    expr clear = cmds_.clear_first_out.at(group);
    std::vector<expr> held, became, vars;
    for (auto& [id, active] : members) {
      std::string P = cause_prefix(id);
      vars.push_back(bool_state(P + ".first_out", false));
      held.push_back(vars.back() && !clear);
      expr was = bool_state(P + ".active_prev", false);
      ts_.assign_next(was, active);
      became.push_back(active && !was);
    }
    expr holds = any(held);
    expr earlier = B(false);
    for (std::size_t i = 0; i < members.size(); ++i) {
      expr now = held[i] || (!holds && became[i] && !earlier);
      earlier = earlier || became[i];
      ts_.assign_next(vars[i], now);
      ts_.name_term(cause_prefix(members[i].first) + ".first_out", now);
    }
  }
}

}  // namespace cemv::encoder::detail
