// The function block of one cause (docs/semantics.md section C): tag values ->
// trip and taken-out state -> voting with hysteresis (trip requested) -> time
// function -> acknowledgement latch -> bypass and inhibit -> active.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "model/vocabulary.hpp"
#include "model/matrix.hpp"
#include "runtime/signals.hpp"

namespace cemv::runtime {

// The status fields of a cause (model::cause_fields(), C.9).
enum class CauseField {
  Active, TripRequested, TrippedTags, Voting, Degraded, Bypassed, SoftBypassed, Inhibited,
  AckRequired, FirstOut, HysteresisActive, DeltaAlarm, Prewarning, TimerRunning,
  BypassTimeout, BypassPrealarm,
};
// The field of that name; false when the name is not a cause field.
bool cause_field_from_name(const std::string& name, CauseField& out);

// A cause's configuration, resolved once from the matrix.
struct CauseConfig {
  int id = 0;
  int tag_count = 0;
  std::array<TagSource, model::kMaxCauseTags> tag_source{};
  std::array<int, model::kMaxCauseTags> input_index{};  // InputTable index, -1 for a reference
  std::array<std::string, model::kMaxCauseTags> tag_key{};  // case-insensitive name
  std::array<bool, model::kMaxCauseTags> ett{};
  std::array<bool, model::kMaxCauseTags> tag_soft_bypass_allowed{};

  int configured_x = 1;  // X of the configured XooN (C.4)
  bool analog = false;
  model::LimitType limit_type = model::LimitType::High;
  float limit = 0.0f;
  float relaxed_threshold = 0.0f;  // limit -/+ hysteresis, as float (C.4)
  bool prewarning_enabled = false;  // C.5
  float prewarning = 0.0f;
  bool delta_enabled = false;
  float delta = 0.0f;
  float delta_clear = 0.0f;  // delta - hysteresis, as float (C.5)
  model::BadQuality bad_quality = model::BadQuality::Trip;

  model::TimeMode time_mode = model::TimeMode::None;
  std::uint64_t time_cycles = 0;
  bool has_ack_latch = false;  // C.7

  bool soft_bypass_allowed = true;
  bool soft_bypass_timed = false;
  std::uint64_t soft_bypass_cycles = 0;
  bool soft_bypass_prealarm = false;
  std::uint64_t soft_bypass_prealarm_cycles = 0;

  bool has_bypass_tag = false;
  TagSource bypass_tag;
  bool has_inhibit_tag = false;
  TagSource inhibit_tag;

  int first_out_group = 0;
  bool mutually_locked = false;
};

// What the last evaluation of a cause did (C.1-C.8), for the explanations of
// runtime/explain.hpp: plain values written by every evaluation, read only
// when a caller asks why a field changed.
struct CauseFacts {
  std::array<float, model::kMaxCauseTags> value{};  // C.2
  std::array<bool, model::kMaxCauseTags> bad{};
  std::array<bool, model::kMaxCauseTags> votes{};   // not taken out (C.3)
  std::array<bool, model::kMaxCauseTags> tripped{}; // among the voting tags, at the threshold in use (C.3)
  int needed = 1;                    // X' of the resulting logic (C.4)
  int voting_tags = 0;               // m (C.4)
  float threshold = 0.0f;            // analog: the threshold in use (C.4)
  bool hysteresis_mode = false;      // C.4
  bool timed = false;                // TM (C.6)
  bool soft_bypass_expired = false;  // C.1
  bool hard_bypass = false;          // C.8
  bool ack_cleared = false;          // C.7: an accepted ack_cause cleared the latch
  bool ack_ignored = false;          // C.7: an ack while the trip was still requested
  // The previous cycle's values the rules compare with.
  bool was_timed = false, was_bypassed = false, was_inhibited = false, was_latched = false;
};

class CauseBlock {
 public:
  CauseBlock() = default;
  explicit CauseBlock(CauseConfig config) : cfg_(std::move(config)) {}

  const CauseConfig& config() const { return cfg_; }

  // Evaluates the cause in cycle k (C.1-C.9).
  void evaluate(const Signals& s, std::uint64_t k);

  // ---- operator commands (section O), applied in phase 2 of a cycle ----
  void request_ack() { ack_requested_ = true; }                         // O.1
  void set_soft_bypass(bool on, std::uint64_t k);                       // O.5
  void set_tag_soft_bypass(int position, bool on) { tag_soft_bypassed_[position] = on; }  // O.6
  bool tag_soft_bypassed(int position) const { return tag_soft_bypassed_[position]; }
  void clear_alarms() { bypass_timeout_ = false; }                      // O.10
  void clear_first_out() { first_out_ = false; }                        // O.9
  void end_maintenance();  // group deactivation (M.2): soft bypasses off, no alarm

  // ---- first out (C.11), phase 4 ----
  bool became_active() const { return active_ && !active_before_; }
  void give_first_out() { first_out_ = true; }

  bool active() const { return active_; }
  int field(CauseField f) const;
  const CauseFacts& facts() const { return facts_; }

 private:
  // The per-cycle values passed between the steps of evaluate(), on the stack.
  struct TagReadings {
    std::array<float, model::kMaxCauseTags> value;
    std::array<bool, model::kMaxCauseTags> bad;
  };
  struct TakenOut {
    std::array<bool, model::kMaxCauseTags> votes;  // the tag votes (not taken out)
    int count;                                     // tags taken out
    bool for_bad_quality;                          // one of them for bad quality
  };
  // The steps of evaluate(), one per paragraph of docs/semantics.md section C.
  void expire_soft_bypass(std::uint64_t k);                           // C.1
  void read_tags(const Signals& s, TagReadings& tags) const;          // C.2
  void take_out(const TagReadings& tags, TakenOut& out) const;       // C.3
  bool vote(const TagReadings& tags, const TakenOut& out);            // C.4
  void watch_delta_and_prewarning(const TagReadings& tags);           // C.5
  bool time_function(bool tr, std::uint64_t k);                       // C.6
  void read_bypass_and_inhibit(const Signals& s);                     // C.8, inputs
  void latch_acknowledgement(bool tr, bool tm);                       // C.7
  bool tag_tripped(float value, bool bad, int position, float threshold) const;

  CauseConfig cfg_;

  // Operator state.
  bool ack_requested_ = false;
  bool soft_bypass_ = false;
  std::uint64_t soft_bypass_start_ = 0;
  std::array<bool, model::kMaxCauseTags> tag_soft_bypassed_{};

  // Memory between cycles.
  bool trip_requested_before_ = false;  // prev(TR): hysteresis mode, edges (C.4, C.6)
  bool timed_before_ = false;           // prev(TM) (C.6)
  bool active_before_ = false;          // C.11
  bool timer_is_running_ = false;       // off_delay / timed timer (C.6)
  std::uint64_t timer_start_ = 0;       // on_delay / off_delay / timed start cycle
  std::array<bool, 3> delta_pair_alarm_{};  // pairs (1,2), (1,3), (2,3) (C.5)
  bool ack_latch_ = false;

  // Status of the last evaluation (C.9).
  bool active_ = false;
  bool trip_requested_ = false;
  int tripped_tags_ = 0;
  model::Voting voting_ = model::Voting::OneOoOne;
  bool degraded_ = false;
  bool bypassed_ = false;
  bool inhibited_ = false;
  bool first_out_ = false;
  bool hysteresis_active_ = false;
  bool delta_alarm_ = false;
  bool prewarning_ = false;
  bool timer_running_ = false;
  bool bypass_timeout_ = false;
  bool bypass_prealarm_ = false;
  CauseFacts facts_;
};

}  // namespace cemv::runtime
