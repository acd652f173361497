// The words of the rules, one function per status field family. Each picks
// the rule the block's facts say it applied in this cycle; paragraph numbers
// are those of docs/semantics.md.
#include "runtime/explain_rules.hpp"

#include "model/text.hpp"

namespace cemv::runtime {

namespace {

using model::CommandOp;

std::string ms_text(std::uint64_t ms) {
  if (ms % 60000 == 0 && ms >= 60000) return std::to_string(ms / 60000) + " min";
  if (ms % 1000 == 0 && ms >= 1000) return std::to_string(ms / 1000) + " s";
  return std::to_string(ms) + " ms";
}

const model::Cause& cause_of(const CycleView& v, int slot) {
  return *v.m.find_cause(v.cause_ids[static_cast<std::size_t>(slot)]);
}
const model::Effect& effect_of(const CycleView& v, int slot) {
  return *v.m.find_effect(v.effect_ids[static_cast<std::size_t>(slot)]);
}
std::string cause_name(const CycleView& v, int slot) {
  const auto& c = cause_of(v, slot);
  return "cause " + std::to_string(c.id) + " " + c.name;
}

// Whether an accepted command of this cycle matches.
bool commanded(const CycleView& v, CommandOp op, int cause, int effect, int on = -1) {
  for (std::size_t i = 0; i < v.in.commands.size(); ++i) {
    const auto& c = v.in.commands[i];
    if (!v.accepted[i] || c.op != op) continue;
    if (cause && c.cause != cause) continue;
    if (effect && c.effect != effect) continue;
    if (on >= 0 && c.on != (on == 1)) continue;
    return true;
  }
  return false;
}

// C.3/C.4: the tags as the voting saw them.
std::string trip_text(const CycleView& v, int slot) {
  const auto& c = cause_of(v, slot);
  const CauseFacts& f = v.causes[static_cast<std::size_t>(slot)].facts();
  std::string tags;
  int tripped = 0;
  for (std::size_t i = 0; i < c.tags.size() && i < f.value.size(); ++i) {
    std::string t = c.tags[i].name + " = " +
                    (c.input == model::InputKind::Analog ? model::float_text(f.value[i])
                                                         : std::string(f.value[i] != 0.0f ? "TRUE" : "FALSE"));
    if (f.bad[i]) t += " (bad quality)";
    if (!f.votes[i]) t += " (taken out)";
    else if (f.tripped[i]) t += " (tripped)", ++tripped;
    tags += (tags.empty() ? "" : ", ") + t;
  }
  if (f.needed == 0) return tags + ": every tag taken out (C.3, C.4)";
  std::string out = tags + ": " + std::to_string(tripped) + " of " + std::to_string(f.voting_tags) +
                    " voting tags tripped, " + std::to_string(f.needed) + " needed";
  if (c.input == model::InputKind::Analog)
    out += std::string(" at ") + (f.hysteresis_mode ? "the relaxed threshold " : "the limit ") +
           model::float_text(f.threshold);
  else if (c.tags.size() == 1)
    out += c.tags[0].ett ? " (energize-to-trip: trips when TRUE)" : " (de-energize-to-trip: trips when FALSE)";
  return out + " (C.3, C.4)";
}

std::string time_text(const model::Cause& c) {
  switch (c.time.mode) {
    case model::TimeMode::OnDelay: return "on-delay of " + ms_text(c.time.ms);
    case model::TimeMode::OffDelay: return "off-delay of " + ms_text(c.time.ms);
    case model::TimeMode::Timed: return "timed period of " + ms_text(c.time.ms);
    case model::TimeMode::None: break;
  }
  return "";
}

std::string cause_active(const CycleView& v, int slot, bool up) {
  const auto& c = cause_of(v, slot);
  const CauseBlock& b = v.causes[static_cast<std::size_t>(slot)];
  const CauseFacts& f = b.facts();
  const bool bypassed = b.field(CauseField::Bypassed), inhibited = b.field(CauseField::Inhibited);
  if (up) {
    if (f.was_bypassed && !bypassed) return "bypass removed with the cause still tripped (C.8)";
    if (f.was_inhibited && !inhibited) return "inhibit removed with the cause still tripped (C.8)";
    if (f.timed && !f.was_timed) {
      if (c.time.mode == model::TimeMode::OnDelay) return time_text(c) + " expired, the trip requested throughout (C.6)";
      if (c.time.mode == model::TimeMode::Timed) return "trip requested: " + time_text(c) + " starts (C.6); " + trip_text(v, slot);
      return "trip requested: " + trip_text(v, slot);
    }
    return "acknowledgement latch holds the cause active (C.7)";
  }
  if (bypassed && !f.was_bypassed)
    return f.hard_bypass ? "bypassed: bypass tag " + c.bypass_tag.value_or("") + " is TRUE (C.8)"
                         : "soft-bypassed by the operator (soft_bypass_cause, O.5, C.8)";
  if (inhibited && !f.was_inhibited) return "inhibited: inhibit tag " + c.inhibit_tag.value_or("") + " is TRUE (C.8)";
  if (f.ack_cleared) return "acknowledged: ack_cause accepted with the trip no longer requested (C.7)";
  if (!f.timed && f.was_timed) {
    if (c.time.mode == model::TimeMode::OffDelay) return time_text(c) + " expired (C.6)";
    if (c.time.mode == model::TimeMode::Timed) return time_text(c) + " over (C.6)";
    return "trip no longer requested: " + trip_text(v, slot);
  }
  return "no longer tripped (C.8)";
}

std::string soft_bypass_change(const CycleView& v, bool up, bool cause, int id, bool expired) {
  if (up) return std::string(cause ? "soft_bypass_cause" : "soft_bypass_effect") + " on accepted (" +
                 (cause ? "O.5" : "O.7") + ")";
  if (expired) return "maximum soft bypass time expired: removed with the alarm bypass_timeout (C.1)";
  if (v.group_deactivation) return "group deactivation ended every soft bypass (M.2)";
  if (commanded(v, cause ? CommandOp::SoftBypassCause : CommandOp::SoftBypassEffect, cause ? id : 0, cause ? 0 : id, 0))
    return std::string(cause ? "soft_bypass_cause" : "soft_bypass_effect") + " off accepted (" + (cause ? "O.5" : "O.7") + ")";
  return std::string("soft bypass ended (") + (cause ? "O.5" : "O.7") + ")";
}

// E.3: what toggled the override this cycle.
std::string toggle_source(const CycleView& v, int slot) {
  const auto& e = effect_of(v, slot);
  const EffectFacts& f = v.effects[static_cast<std::size_t>(slot)].facts();
  if (f.toggle_by_tag) return "the rising edge of the reset/override tag " + e.reset_tag.value_or("");
  if (commanded(v, CommandOp::StopOverride, 0, e.id)) return "the operator's stop_override";
  return "the operator's override_effect";
}

std::string requester(const CycleView& v, int slot, int type) {
  const EffectFacts& f = v.effects[static_cast<std::size_t>(slot)].facts();
  static const char* kType[] = {"N", "S", "V", "R"};
  int s = f.requesting_slot[static_cast<std::size_t>(type)];
  if (s >= 0) return cause_name(v, s) + " is active on its " + kType[type] + " intersection";
  return std::to_string(f.xoon_active) + " causes of the XooN assignment are active";
}

std::string latch_cleared(const CycleView& v, int slot) {
  const EffectFacts& f = v.effects[static_cast<std::size_t>(slot)].facts();
  if (f.r_cleared_by_override && !f.reset_cleared_s && !f.reset_cleared_r)
    return "R latch cleared without a reset: its R request fell while an override was running (E.5; 13.2.1 (4))";
  if (f.toggle_as_reset)
    return "the override toggle (" + toggle_source(v, slot) + ") found no override to start or stop and acted "
           "as a reset, which cleared the " + std::string(f.reset_cleared_r ? "R" : "S") + " latch (E.3 step 2, E.4)";
  if (f.reset_by_command) return "reset_effect accepted with no S/R request left: latch cleared (O.2, E.4)";
  return "latch cleared (E.4, E.5)";
}

std::string override_ended(const CycleView& v, int slot) {
  const auto& e = effect_of(v, slot);
  const EffectFacts& f = v.effects[static_cast<std::size_t>(slot)].facts();
  if (f.end_timeout)
    return "override ended: its maximum time of " +
           ms_text(std::uint64_t{e.override_time ? e.override_time->max_s : 0} * 1000) +
           " expired, alarm override_failed_timeout (E.3 step 1a)";
  if (f.end_new_cause)
    return "override ended: a linked cause that was not active when it started became active, alarm "
           "override_failed_cause (E.3 step 1b)";
  if (f.end_no_request) return "override ended: no V or R request is left (E.3 step 1c)";
  if (f.override_stopped) return "override stopped by " + toggle_source(v, slot) + " (E.3 step 2)";
  if (v.group_deactivation) return "group deactivation ended the override (M.2)";
  return "override ended (E.3)";
}

std::string effect_active(const CycleView& v, int slot, bool up) {
  const auto& e = effect_of(v, slot);
  const EffectBlock& b = v.effects[static_cast<std::size_t>(slot)];
  const EffectFacts& f = b.facts();
  const bool bypassed = b.field(EffectField::Bypassed), overridden = b.field(EffectField::OverrideActive);
  if (up) {
    if (f.was_bypassed && !bypassed) return "bypass removed while tripped (E.1, E.6)";
    if (f.request[0]) return "N request: " + requester(v, slot, 0) + " (E.2, E.6)";
    if (f.request[1]) return "S request: " + requester(v, slot, 1) + "; the S latch is set (E.2, E.5)";
    if (f.was_override && !overridden) return override_ended(v, slot) + "; the V/R trip acts again (E.6)";
    if (f.request[2]) return "V request: " + requester(v, slot, 2) + " (E.2, E.6)";
    if (f.request[3]) return "R request: " + requester(v, slot, 3) + "; the R latch is set (E.2, E.5)";
    return "a latch holds the effect active (E.5, E.6)";
  }
  if (bypassed && !f.was_bypassed)
    return f.hard_bypass ? "bypassed: bypass tag " + e.bypass_tag.value_or("") + " is TRUE (E.1, E.6)"
                         : "soft-bypassed by the operator (soft_bypass_effect, O.7, E.6)";
  if (f.override_started)
    return "override started by " + toggle_source(v, slot) + ": the V and R trips are suppressed (E.3, E.6)";
  if (f.reset_cleared_s || f.reset_cleared_r || f.r_cleared_by_override) return latch_cleared(v, slot) + " (E.6)";
  return "no request left: no linked cause is active (E.2, E.6)";
}

std::string output_tag(const CycleView& v, int slot, int tag, int after) {
  const auto& e = effect_of(v, slot);
  const EffectBlock& b = v.effects[static_cast<std::size_t>(slot)];
  const std::string name = e.tags[static_cast<std::size_t>(tag)].name;
  if (b.output_simulated(tag)) return "output " + name + " simulated to " + std::to_string(after) + " (O.8, E.10)";
  const bool state_changed = b.facts().was_output_state != b.output_state();
  if (!state_changed && (commanded(v, CommandOp::StopSimulation, 0, 0) || v.group_deactivation))
    return "simulation of " + name + " ended (" + (v.group_deactivation ? "M.2" : "O.8") + ", E.10)";
  if (state_changed) {
    bool tripped = b.output_state();
    std::string side = e.tags[static_cast<std::size_t>(tag)].ett ? "energize-to-trip" : "de-energize-to-trip";
    return std::string("the effect's output state turned ") + (tripped ? "ON" : "OFF") +
           (tripped && e.output_delay_ms ? " after its output delay of " + ms_text(e.output_delay_ms) : "") +
           ": output " + name + " = " + std::to_string(after) + " (" + side + ", E.7, E.9)";
  }
  if (e.process_data) return "output " + name + " follows the process value (pass-through or mask, E.8, E.9)";
  return "output " + name + " = " + std::to_string(after) + ": the effect's output state is " +
         (b.output_state() ? "ON" : "OFF") + " (" +
         (e.tags[static_cast<std::size_t>(tag)].ett ? "energize-to-trip" : "de-energize-to-trip") +
         "; every output reads 0 before the first cycle, T.3, E.9)";
}

}  // namespace

std::string why_cause(const CycleView& v, int slot, CauseField f, int before, int after) {
  const auto& c = cause_of(v, slot);
  const CauseBlock& b = v.causes[static_cast<std::size_t>(slot)];
  const bool up = after > before;
  switch (f) {
    case CauseField::Active: return cause_active(v, slot, up);
    case CauseField::TripRequested:
      return std::string(up ? "trip requested: " : "trip no longer requested: ") + trip_text(v, slot);
    case CauseField::TrippedTags: return std::to_string(after) + " voting tags tripped: " + trip_text(v, slot);
    case CauseField::Voting:
      return "resulting logic " + std::string(model::to_string(static_cast<model::Voting>(after))) +
             " after the tags taken out (degraded voting, C.4)";
    case CauseField::Degraded:
      return up ? "a tag is taken out of the voting (soft bypass or bad quality, C.3)"
                : "every tag votes again (C.3)";
    case CauseField::Bypassed: {
      const CauseFacts& cf = b.facts();
      const bool soft_ended = cf.soft_bypass_expired || v.group_deactivation ||
                              commanded(v, CommandOp::SoftBypassCause, c.id, 0, 0);
      if (up ? cf.hard_bypass : (c.bypass_tag && !soft_ended))
        return "bypass tag " + c.bypass_tag.value_or("") + " is " + (up ? "TRUE" : "FALSE") + " (C.8)";
      return soft_bypass_change(v, up, true, c.id, cf.soft_bypass_expired) + " (C.8)";
    }
    case CauseField::SoftBypassed: return soft_bypass_change(v, up, true, c.id, b.facts().soft_bypass_expired);
    case CauseField::Inhibited:
      return "inhibit tag " + c.inhibit_tag.value_or("") + " is " + (up ? "TRUE" : "FALSE") + " (C.8)";
    case CauseField::AckRequired:
      return up ? "tripped with manual acknowledgement: latched until ack_cause (C.7)"
                : "acknowledged: ack_cause accepted with the trip no longer requested (C.7)";
    case CauseField::FirstOut:
      return up ? "the first cause of first-out group " + std::to_string(c.first_out_group) +
                      " to become active (C.11)"
                : "clear_first_out for group " + std::to_string(c.first_out_group) + " (O.9)";
    case CauseField::HysteresisActive:
      return up ? "inside the dead band: the limit no longer requests the trip, the relaxed threshold still does (C.4)"
                : "out of the dead band (C.4)";
    case CauseField::DeltaAlarm:
      return up ? "two tags differ by at least the delta (C.5)" : "the tags agree again within delta - hysteresis (C.5)";
    case CauseField::Prewarning:
      return up ? "a tag at or beyond the prewarning limit (C.5)" : "no tag beyond the prewarning limit (C.5)";
    case CauseField::TimerRunning:
      return (up ? time_text(c) + " running (C.6)" : time_text(c) + " no longer running (C.6)");
    case CauseField::BypassTimeout:
      return up ? "soft bypass removed at its maximum time of " +
                      ms_text(std::uint64_t{c.soft_bypass.max_s} * 1000) + " (C.1)"
                : "clear_alarms accepted (O.10)";
    case CauseField::BypassPrealarm:
      return up ? "soft bypass on for its prealarm time of " + ms_text(std::uint64_t{c.soft_bypass.prealarm_s} * 1000) +
                      " (C.1)"
                : "soft bypass ended or timed out (C.1)";
  }
  return "(C.9)";
}

std::string why_effect(const CycleView& v, int slot, int field, int tag, int before, int after) {
  if (field < 0) return output_tag(v, slot, tag, after);
  const auto& e = effect_of(v, slot);
  const EffectBlock& b = v.effects[static_cast<std::size_t>(slot)];
  const EffectFacts& f = b.facts();
  const bool up = after > before;
  switch (static_cast<EffectField>(field)) {
    case EffectField::Active: return effect_active(v, slot, up);
    case EffectField::Latched:
      if (up) return f.request[1] ? "S latch set: " + requester(v, slot, 1) + " (E.5)"
                                  : "R latch set: " + requester(v, slot, 3) + " (E.5)";
      return latch_cleared(v, slot);
    case EffectField::OkToReset:
      return up ? "latched with no S/R request left and no output delay running: a reset would clear it (E.11)"
                : "no longer resettable: a latch cleared, or an S/R request or the output delay holds it (E.11)";
    case EffectField::OverrideActive:
      return up ? "override started by " + toggle_source(v, slot) + " while a V/R trip was requested (E.3 step 2)"
                : override_ended(v, slot);
    case EffectField::OverrideFailedTimeout:
      return up ? override_ended(v, slot)
                : f.override_started ? "a new override started (E.3)" : "clear_alarms accepted (O.10)";
    case EffectField::OverrideFailedCause:
      return up ? override_ended(v, slot)
                : f.override_started ? "a new override started (E.3)" : "clear_alarms accepted (O.10)";
    case EffectField::OverridePrealarm:
      return up ? "override running for its prealarm time of " +
                      ms_text(std::uint64_t{e.override_time ? e.override_time->prealarm_s : 0} * 1000) + " (E.3 step 3)"
                : override_ended(v, slot);
    case EffectField::Bypassed: {
      const bool soft_ended = v.group_deactivation || commanded(v, CommandOp::SoftBypassEffect, 0, e.id, 0);
      if (up ? f.hard_bypass : (e.bypass_tag && !soft_ended))
        return "bypass tag " + e.bypass_tag.value_or("") + " is " + (up ? "TRUE" : "FALSE") + " (E.1)";
      return soft_bypass_change(v, up, false, e.id, false) + " (E.1)";
    }
    case EffectField::SoftBypassed: return soft_bypass_change(v, up, false, e.id, false);
    case EffectField::Masked:
      return "mask tag " + (e.process_data && e.process_data->mask_tag ? *e.process_data->mask_tag : std::string()) +
             " is " + (up ? "TRUE" : "FALSE") + " (E.8)";
    case EffectField::PassThroughActive:
      return up ? "output state OFF: the process value is passed through (E.8)"
                : "output state ON: the safe value replaces the process value (E.8)";
    case EffectField::OutputDelayRunning:
      if (up) return "active: the output delay of " + ms_text(e.output_delay_ms) + " starts (E.7)";
      return b.active() ? "output delay of " + ms_text(e.output_delay_ms) + " expired: the outputs follow (E.7)"
                        : "no longer active: the output delay stops (E.7)";
  }
  return "(E.11)";
}

}  // namespace cemv::runtime
