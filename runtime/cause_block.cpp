// One cause, evaluated once per scan cycle. Paragraph numbers refer to
// docs/semantics.md; read the two side by side.
#include "runtime/cause_block.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace cemv::runtime {

namespace {

constexpr std::pair<CauseField, const char*> kCauseFieldNames[] = {
    {CauseField::Active, "active"},
    {CauseField::TripRequested, "trip_requested"},
    {CauseField::TrippedTags, "tripped_tags"},
    {CauseField::Voting, "voting"},
    {CauseField::Degraded, "degraded"},
    {CauseField::Bypassed, "bypassed"},
    {CauseField::SoftBypassed, "soft_bypassed"},
    {CauseField::Inhibited, "inhibited"},
    {CauseField::AckRequired, "ack_required"},
    {CauseField::FirstOut, "first_out"},
    {CauseField::HysteresisActive, "hysteresis_active"},
    {CauseField::DeltaAlarm, "delta_alarm"},
    {CauseField::Prewarning, "prewarning"},
    {CauseField::TimerRunning, "timer_running"},
    {CauseField::BypassTimeout, "bypass_timeout"},
    {CauseField::BypassPrealarm, "bypass_prealarm"},
};

// The resulting logic X oo M as the scenario spells it (C.9 `voting`).
model::Voting voting_of(int x, int m) {
  if (m == 1) return model::Voting::OneOoOne;
  if (m == 2) return x >= 2 ? model::Voting::TwoOoTwo : model::Voting::OneOoTwo;
  if (x >= 3) return model::Voting::ThreeOoThree;
  return x == 2 ? model::Voting::TwoOoThree : model::Voting::OneOoThree;
}

}  // namespace

bool cause_field_from_name(const std::string& name, CauseField& out) {
  for (auto [field, text] : kCauseFieldNames)
    if (name == text) {
      out = field;
      return true;
    }
  return false;
}

// O.5: switching on starts the timer of a timed soft bypass; switching on an
// already active soft bypass changes nothing.
void CauseBlock::set_soft_bypass(bool on, std::uint64_t k) {
  if (on && !soft_bypass_) soft_bypass_start_ = k;
  soft_bypass_ = on;
}

// M.2: group deactivation ends the soft bypasses without an alarm.
void CauseBlock::end_maintenance() {
  soft_bypass_ = false;
  tag_soft_bypassed_ = {};
}

// C.3: whether a voting tag is tripped, against threshold `threshold` (analog).
bool CauseBlock::tag_tripped(float value, bool bad, int position, float threshold) const {
  if (bad && cfg_.bad_quality == model::BadQuality::Trip) return true;
  if (!cfg_.analog) {
    bool is_true = value != 0.0f;
    return cfg_.ett[position] ? is_true : !is_true;
  }
  // IEEE single precision; a NaN compares false and never trips.
  if (cfg_.limit_type == model::LimitType::High) return value >= threshold;
  return value <= threshold;
}

// One evaluation in cycle k: the paragraphs of section C in order, each a
// step. The per-cycle values between the steps live on the stack (fixed-size
// arrays), so a cycle allocates nothing; the steps are inline (defined below,
// used only here) so that the split costs no calls (bench_runtime).
void CauseBlock::evaluate(const Signals& s, std::uint64_t k) {
  active_before_ = active_;  // prev(active), for first out (C.11)
  facts_.soft_bypass_expired = false;
  facts_.ack_cleared = facts_.ack_ignored = false;
  facts_.was_timed = timed_before_;
  facts_.was_bypassed = bypassed_;
  facts_.was_inhibited = inhibited_;
  facts_.was_latched = ack_latch_;
  expire_soft_bypass(k);                                  // C.1
  TagReadings tags{};
  read_tags(s, tags);                                     // C.2
  TakenOut out{};
  take_out(tags, out);                                    // C.3
  const bool tr = vote(tags, out);                        // C.4
  watch_delta_and_prewarning(tags);                       // C.5
  const bool tm = time_function(tr, k);                   // C.6
  read_bypass_and_inhibit(s);                             // C.8, inputs
  latch_acknowledgement(tr, tm);                          // C.7
  // C.8 Active.
  active_ = (tm || ack_latch_) && !bypassed_ && !inhibited_;
  facts_.value = tags.value;
  facts_.bad = tags.bad;
  facts_.votes = out.votes;
  facts_.timed = tm;
  trip_requested_ = tr;
  // Memory for the next cycle.
  trip_requested_before_ = tr;
  timed_before_ = tm;
}

// C.1 Timed soft bypass: removed at expiry, with the "bypass timeout" alarm.
inline void CauseBlock::expire_soft_bypass(std::uint64_t k) {
  if (soft_bypass_ && cfg_.soft_bypass_timed && k - soft_bypass_start_ >= cfg_.soft_bypass_cycles) {
    soft_bypass_ = false;
    bypass_timeout_ = true;
    facts_.soft_bypass_expired = true;
  }
  bypass_prealarm_ = soft_bypass_ && cfg_.soft_bypass_timed && cfg_.soft_bypass_prealarm &&
                     k - soft_bypass_start_ >= cfg_.soft_bypass_prealarm_cycles;
}

// C.2 Tag values (simulation, reference or input).
inline void CauseBlock::read_tags(const Signals& s, TagReadings& tags) const {
  for (int i = 0; i < cfg_.tag_count; ++i) {
    model::TagValue v = s.read_cause_input(cfg_.tag_source[i]);
    tags.value[i] = v.value;
    tags.bad[i] = v.bad_quality;
  }
}

// C.3 Taken out of the voting: soft-bypassed, or degraded for bad quality.
inline void CauseBlock::take_out(const TagReadings& tags, TakenOut& out) const {
  for (int i = 0; i < cfg_.tag_count; ++i) {
    bool out_bq = !tag_soft_bypassed_[i] && cfg_.bad_quality == model::BadQuality::Degrade && tags.bad[i];
    out.votes[i] = !tag_soft_bypassed_[i] && !out_bq;
    if (!out.votes[i]) ++out.count;
    if (out_bq) out.for_bad_quality = true;
  }
}

// C.4 Voting with degraded voting and cause-level hysteresis; returns TR.
inline bool CauseBlock::vote(const TagReadings& tags, const TakenOut& out) {
  const int voting_tags = cfg_.tag_count - out.count;
  const bool hysteresis_mode = cfg_.analog && trip_requested_before_;
  const float threshold = hysteresis_mode ? cfg_.relaxed_threshold : cfg_.limit;
  int tripped = 0;
  int tripped_strict = 0;
  facts_.tripped = {};
  facts_.threshold = threshold;
  facts_.hysteresis_mode = hysteresis_mode;
  facts_.voting_tags = voting_tags;
  for (int i = 0; i < cfg_.tag_count; ++i) {
    if (!out.votes[i]) continue;
    if (tag_tripped(tags.value[i], tags.bad[i], i, threshold)) ++tripped, facts_.tripped[i] = true;
    if (tag_tripped(tags.value[i], tags.bad[i], i, cfg_.limit)) ++tripped_strict;
  }
  bool trip_requested = false;
  bool strict_request = false;
  if (voting_tags == 0) {
    facts_.needed = 0;  // every tag taken out
    trip_requested = out.for_bad_quality;  // the "(1oo1)" rows of appendix B
    strict_request = trip_requested;
    voting_ = out.for_bad_quality ? model::Voting::OneOoOne : model::Voting::Bypass;
  } else {
    const int x = std::max(1, cfg_.configured_x - out.count);
    facts_.needed = x;
    trip_requested = tripped >= x;
    strict_request = tripped_strict >= x;
    voting_ = voting_of(x, voting_tags);
  }
  tripped_tags_ = tripped;
  degraded_ = out.count > 0;
  hysteresis_active_ = hysteresis_mode && trip_requested && !strict_request;
  return trip_requested;
}

// C.5 Delta alarm per pair of tags, and prewarning. Status only.
inline void CauseBlock::watch_delta_and_prewarning(const TagReadings& tags) {
  delta_alarm_ = false;
  if (cfg_.delta_enabled) {
    static constexpr int kPairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    for (int p = 0; p < 3; ++p) {
      int i = kPairs[p][0], j = kPairs[p][1];
      if (j >= cfg_.tag_count) continue;
      float d = std::fabs(tags.value[i] - tags.value[j]);
      if (d >= cfg_.delta) delta_pair_alarm_[p] = true;
      else if (d < cfg_.delta_clear) delta_pair_alarm_[p] = false;
      if (delta_pair_alarm_[p]) delta_alarm_ = true;
    }
  }
  prewarning_ = false;
  if (cfg_.prewarning_enabled) {
    for (int i = 0; i < cfg_.tag_count; ++i) {
      bool beyond = cfg_.limit_type == model::LimitType::High ? tags.value[i] >= cfg_.prewarning
                                                              : tags.value[i] <= cfg_.prewarning;
      if (beyond) prewarning_ = true;
    }
  }
}

// C.6 Time function: TR -> TM.
inline bool CauseBlock::time_function(bool tr, std::uint64_t k) {
  const bool tr_rose = tr && !trip_requested_before_;
  bool tm = false;
  timer_running_ = false;
  switch (cfg_.time_mode) {
    case model::TimeMode::None:
      tm = tr;
      break;
    case model::TimeMode::OnDelay:
      if (tr_rose) timer_start_ = k;
      tm = tr && k - timer_start_ >= cfg_.time_cycles;
      timer_running_ = tr && !tm;
      break;
    case model::TimeMode::OffDelay:
      if (tr) {
        timer_is_running_ = false;
        tm = true;
      } else {
        if (!timer_is_running_ && timed_before_) {
          timer_is_running_ = true;
          timer_start_ = k;
        }
        if (timer_is_running_ && k - timer_start_ >= cfg_.time_cycles) timer_is_running_ = false;
        tm = timer_is_running_;
      }
      timer_running_ = timer_is_running_;
      break;
    case model::TimeMode::Timed:
      if (timer_is_running_ && k - timer_start_ >= cfg_.time_cycles) timer_is_running_ = false;
      if (tr_rose && !timer_is_running_) {
        timer_is_running_ = true;
        timer_start_ = k;
        if (k - timer_start_ >= cfg_.time_cycles) timer_is_running_ = false;  // zero duration
      }
      tm = timer_is_running_;
      timer_running_ = timer_is_running_;
      break;
  }
  return tm;
}

// C.8 (inputs) Bypass and inhibit of this cycle.
inline void CauseBlock::read_bypass_and_inhibit(const Signals& s) {
  const bool hard_bypass = cfg_.has_bypass_tag && s.read_bool(cfg_.bypass_tag);
  facts_.hard_bypass = hard_bypass;
  bypassed_ = hard_bypass || soft_bypass_;
  inhibited_ = cfg_.has_inhibit_tag && s.read_bool(cfg_.inhibit_tag);
}

// C.7 Acknowledgement latch: cleared by an ack only once the trip is no
// longer requested; set while TM holds and the cause is neither bypassed nor
// inhibited.
inline void CauseBlock::latch_acknowledgement(bool tr, bool tm) {
  if (cfg_.has_ack_latch) {
    facts_.ack_cleared = ack_requested_ && !tr && ack_latch_;
    facts_.ack_ignored = ack_requested_ && tr;
    if (ack_requested_ && !tr) ack_latch_ = false;
    if (tm && !bypassed_ && !inhibited_) ack_latch_ = true;
  }
  ack_requested_ = false;  // an ack is never remembered past its cycle
}

int CauseBlock::field(CauseField f) const {
  switch (f) {
    case CauseField::Active: return active_;
    case CauseField::TripRequested: return trip_requested_;
    case CauseField::TrippedTags: return tripped_tags_;
    case CauseField::Voting: return static_cast<int>(voting_);
    case CauseField::Degraded: return degraded_;
    case CauseField::Bypassed: return bypassed_;
    case CauseField::SoftBypassed: return soft_bypass_;
    case CauseField::Inhibited: return inhibited_;
    case CauseField::AckRequired: return cfg_.has_ack_latch && ack_latch_;
    case CauseField::FirstOut: return first_out_;
    case CauseField::HysteresisActive: return hysteresis_active_;
    case CauseField::DeltaAlarm: return delta_alarm_;
    case CauseField::Prewarning: return prewarning_;
    case CauseField::TimerRunning: return timer_running_;
    case CauseField::BypassTimeout: return bypass_timeout_;
    case CauseField::BypassPrealarm: return bypass_prealarm_;
  }
  return 0;
}

}  // namespace cemv::runtime
