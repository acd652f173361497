// The function block of one effect (docs/semantics.md section E): requests per
// intersection type -> override -> reset -> S/R latches -> active -> output
// delay -> pass-through and mask -> output values.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "model/vocabulary.hpp"
#include "model/matrix.hpp"
#include "runtime/signals.hpp"

namespace cemv::runtime {

// The status fields of an effect (model::effect_fields(), E.11).
enum class EffectField {
  Active, Latched, OkToReset, OverrideActive, OverrideFailedTimeout, OverrideFailedCause,
  OverridePrealarm, Bypassed, SoftBypassed, Masked, PassThroughActive, OutputDelayRunning,
};
bool effect_field_from_name(const std::string& name, EffectField& out);

// One processed intersection of the effect (E.2).
struct EffectLink {
  int cause_slot = 0;
  model::IntersectionType type = model::IntersectionType::N;
  bool in_xoon = false;
};

struct EffectConfig {
  int id = 0;
  int tag_count = 0;
  std::array<bool, model::kMaxEffectTags> ett{};
  std::array<std::string, model::kMaxEffectTags> tag_key{};  // case-insensitive name

  std::vector<EffectLink> links;  // in cause order
  bool has_xoon = false;
  int xoon_x = 0;
  model::IntersectionType xoon_type = model::IntersectionType::N;
  bool has_reset_or_stored = false;  // a processed S or R intersection (O.2)
  bool has_overridable = false;      // a processed V or R intersection (O.3)

  std::uint64_t output_delay_cycles = 0;
  bool soft_bypass_allowed = false;
  bool has_bypass_tag = false;
  TagSource bypass_tag;
  bool has_reset_tag = false;
  TagSource reset_tag;
  bool has_override = false;
  std::uint64_t override_cycles = 0;
  bool override_prealarm = false;
  std::uint64_t override_prealarm_cycles = 0;

  bool pass_through = false;  // E.8
  bool mask = false;
  TagSource process_tag;
  TagSource mask_tag;

  bool mutually_locked = false;
};

// What the last evaluation of an effect did, step by step (E.1-E.5), for the
// explanations of runtime/explain.hpp. Plain values written by every
// evaluation (no allocation), read only when a caller asks why a field changed.
struct EffectFacts {
  std::array<bool, 4> request{};           // req_N, req_S, req_V, req_R (E.2)
  std::array<int, 4> requesting_slot{};    // per type: the first active cause outside XooN (-1: none)
  int xoon_active = 0;                     // active causes of the XooN assignment
  bool hard_bypass = false;                // E.1
  bool toggle_by_tag = false;              // a rising edge of the reset tag (E.1)
  bool toggle_by_command = false;          // an accepted override_effect / stop_override (O.3)
  bool reset_by_command = false;           // an accepted reset_effect (O.2)
  bool toggle_as_reset = false;            // a toggle with no override to start or stop (E.3 step 2)
  bool override_started = false;           // E.3 step 2
  bool override_stopped = false;           // E.3 step 2
  bool end_timeout = false, end_new_cause = false, end_no_request = false;  // E.3 step 1
  bool reset_cleared_s = false, reset_cleared_r = false;                    // E.4
  bool r_cleared_by_override = false;      // E.5
  bool reset_blocked = false;              // a reset request while a request or the delay held the latch (E.4)
  // The previous cycle's values the rules compare with.
  std::array<bool, 4> was_request{};
  bool was_bypassed = false, was_override = false, was_s_latch = false, was_r_latch = false;
  bool was_output_state = false;
};

class EffectBlock {
 public:
  EffectBlock() = default;
  explicit EffectBlock(EffectConfig config);

  const EffectConfig& config() const { return cfg_; }

  // Evaluates the effect in cycle k (E.1-E.11) and writes its active state and
  // output values into `s` for the readers of internal references.
  void evaluate(Signals& s, int slot, std::uint64_t k);

  // ---- operator commands (section O), applied in phase 2 of a cycle ----
  void request_reset() { reset_requested_ = true; }    // O.2
  void request_toggle() { toggle_requested_ = true; }  // O.3
  void set_soft_bypass(bool on) { soft_bypass_ = on; }  // O.7
  void clear_alarms() { failed_timeout_ = failed_cause_ = false; }  // O.10
  void simulate_output(int position, bool value) {     // O.8
    output_simulated_[position] = true;
    output_simulated_value_[position] = value;
  }
  void stop_output_simulation(int position) { output_simulated_[position] = false; }
  bool output_simulated(int position) const { return output_simulated_[position]; }
  void end_maintenance();  // group deactivation (M.2)

  bool active() const { return active_; }
  bool output(int position) const { return output_[position]; }
  int field(EffectField f) const;
  const EffectFacts& facts() const { return facts_; }
  bool output_state() const { return output_state_; }  // OS of E.7

 private:
  // The steps of evaluate(), in its order (docs/semantics.md, section E).
  bool read_reset_edge(Signals& s, std::uint64_t k);                          // E.1
  void begin_facts(bool hard_bypass, bool bypassed_before, bool reset_tag_edge);
  std::array<bool, 4> form_requests(const Signals& s);                        // E.2
  void end_override(const Signals& s, std::uint64_t k, bool req_v, bool req_r);  // E.3 step 1
  bool toggle_override(const Signals& s, std::uint64_t k, bool req_v, bool req_r, bool reset_tag_edge);  // E.3 step 2
  void reset_and_latch(bool reset_request, bool req_s, bool req_r, bool was_running);  // E.4, E.5
  void delay_outputs(std::uint64_t k);                                        // E.7
  void write_outputs(Signals& s, int slot);                                   // E.8-E.10

  EffectConfig cfg_;

  // Operator state.
  bool reset_requested_ = false;
  bool toggle_requested_ = false;
  bool soft_bypass_ = false;
  std::array<bool, model::kMaxEffectTags> output_simulated_{};
  std::array<bool, model::kMaxEffectTags> output_simulated_value_{};

  // Memory between cycles.
  bool reset_tag_before_ = false;
  bool active_before_ = false;
  bool output_state_before_ = false;
  bool output_delay_running_before_ = false;
  bool req_r_before_ = false;
  bool override_running_before_ = false;
  std::uint64_t output_delay_start_ = 0;
  bool s_latch_ = false;
  bool r_latch_ = false;
  bool override_running_ = false;
  std::uint64_t override_start_ = 0;
  std::vector<std::uint8_t> active_at_override_start_;  // per link, sized once

  // Status of the last evaluation (E.11).
  bool active_ = false;
  bool req_s_ = false;
  bool req_r_ = false;
  bool bypassed_ = false;
  bool failed_timeout_ = false;
  bool failed_cause_ = false;
  bool override_prealarm_ = false;
  bool masked_ = false;
  bool output_state_ = false;
  bool output_delay_running_ = false;
  std::array<bool, model::kMaxEffectTags> output_{};
  EffectFacts facts_;
};

}  // namespace cemv::runtime
