// One effect, evaluated once per scan cycle. Paragraph numbers refer to
// docs/semantics.md; read the two side by side.
#include "runtime/effect_block.hpp"

namespace cemv::runtime {

namespace {

constexpr std::pair<EffectField, const char*> kEffectFieldNames[] = {
    {EffectField::Active, "active"},
    {EffectField::Latched, "latched"},
    {EffectField::OkToReset, "ok_to_reset"},
    {EffectField::OverrideActive, "override_active"},
    {EffectField::OverrideFailedTimeout, "override_failed_timeout"},
    {EffectField::OverrideFailedCause, "override_failed_cause"},
    {EffectField::OverridePrealarm, "override_prealarm"},
    {EffectField::Bypassed, "bypassed"},
    {EffectField::SoftBypassed, "soft_bypassed"},
    {EffectField::Masked, "masked"},
    {EffectField::PassThroughActive, "pass_through_active"},
    {EffectField::OutputDelayRunning, "output_delay_running"},
};

int type_index(model::IntersectionType t) {
  switch (t) {
    case model::IntersectionType::N: return 0;
    case model::IntersectionType::S: return 1;
    case model::IntersectionType::V: return 2;
    case model::IntersectionType::R: return 3;
    default: return -1;  // X and * are never linked (M.4)
  }
}

}  // namespace

bool effect_field_from_name(const std::string& name, EffectField& out) {
  for (auto [field, text] : kEffectFieldNames)
    if (name == text) {
      out = field;
      return true;
    }
  return false;
}

EffectBlock::EffectBlock(EffectConfig config) : cfg_(std::move(config)) {
  active_at_override_start_.assign(cfg_.links.size(), 0);
}

// M.2: group deactivation ends soft bypass, output simulations and a running
// override, without an alarm.
void EffectBlock::end_maintenance() {
  soft_bypass_ = false;
  output_simulated_ = {};
  override_running_ = false;
}

void EffectBlock::evaluate(Signals& s, int slot, std::uint64_t k) {
  // E.1 Reads: bypass, reset-tag edge (no edge in cycle 1, T.4).
  const bool hard_bypass = cfg_.has_bypass_tag && s.read_bool(cfg_.bypass_tag);
  const bool bypassed_before = bypassed_;
  bypassed_ = hard_bypass || soft_bypass_;
  const bool reset_tag_edge = read_reset_edge(s, k);
  begin_facts(hard_bypass, bypassed_before, reset_tag_edge);

  // E.2 Requests per intersection type: N, S, V, R.
  const std::array<bool, 4> req = form_requests(s);
  const bool req_n = req[0], req_s = req[1], req_v = req[2], req_r = req[3];

  // E.3 Override. `was_running`: at the end of the previous cycle (so also
  // when a group deactivation ended it in phase 1 of this cycle).
  const bool was_running = override_running_before_;
  if (override_running_) end_override(s, k, req_v, req_r);
  const bool reset_request = toggle_override(s, k, req_v, req_r, reset_tag_edge);
  // Step 3: prealarm.
  override_prealarm_ = override_running_ && cfg_.override_prealarm &&
                       k - override_start_ >= cfg_.override_prealarm_cycles;

  reset_and_latch(reset_request, req_s, req_r, was_running);

  // E.6 Active.
  active_ = (req_n || s_latch_ || ((req_v || r_latch_) && !override_running_)) && !bypassed_;

  delay_outputs(k);
  write_outputs(s, slot);

  // Memory for the next cycle.
  req_s_ = req_s;
  req_r_ = req_r;
  req_r_before_ = req_r;
  override_running_before_ = override_running_;
  active_before_ = active_;
  output_state_before_ = output_state_;
  output_delay_running_before_ = output_delay_running_;
}

bool EffectBlock::read_reset_edge(Signals& s, std::uint64_t k) {
  if (!cfg_.has_reset_tag) return false;
  const bool value = s.read_bool(cfg_.reset_tag);
  const bool edge = k > 1 && value && !reset_tag_before_;
  reset_tag_before_ = value;
  return edge;
}

// The facts of this cycle (E.11) start from the previous cycle's state.
void EffectBlock::begin_facts(bool hard_bypass, bool bypassed_before, bool reset_tag_edge) {
  const std::array<bool, 4> was_request = facts_.request;
  facts_ = EffectFacts{};
  facts_.was_request = was_request;
  facts_.was_bypassed = bypassed_before;
  facts_.was_override = override_running_before_;
  facts_.was_s_latch = s_latch_;
  facts_.was_r_latch = r_latch_;
  facts_.was_output_state = output_state_before_;
  facts_.hard_bypass = hard_bypass;
  facts_.toggle_by_tag = reset_tag_edge;
  facts_.toggle_by_command = toggle_requested_;
  facts_.reset_by_command = reset_requested_;
  facts_.requesting_slot = {-1, -1, -1, -1};
}

// E.2: a linked active cause requests its intersection's type; the XooN
// causes request the XooN type when at least X of them are active.
std::array<bool, 4> EffectBlock::form_requests(const Signals& s) {
  std::array<bool, 4> req{};
  int xoon_active = 0;
  for (const EffectLink& link : cfg_.links) {
    const bool cause_active = s.cause_active[link.cause_slot] != 0;
    if (link.in_xoon) {
      if (cause_active) ++xoon_active;
    } else if (cause_active) {
      const int t = type_index(link.type);
      req[t] = true;
      if (facts_.requesting_slot[t] < 0) facts_.requesting_slot[t] = link.cause_slot;
    }
  }
  if (cfg_.has_xoon && xoon_active >= cfg_.xoon_x) req[type_index(cfg_.xoon_type)] = true;
  facts_.request = req;
  facts_.xoon_active = xoon_active;
  return req;
}

// E.3 step 1: end conditions of a running override.
void EffectBlock::end_override(const Signals& s, std::uint64_t k, bool req_v, bool req_r) {
  const bool timeout = k - override_start_ >= cfg_.override_cycles;
  bool new_cause = false;
  for (std::size_t i = 0; i < cfg_.links.size(); ++i)
    if (s.cause_active[cfg_.links[i].cause_slot] && !active_at_override_start_[i]) new_cause = true;
  const bool no_request = !req_v && !req_r;
  if (timeout) failed_timeout_ = true;
  if (new_cause) failed_cause_ = true;
  if (timeout || new_cause || no_request) override_running_ = false;
  facts_.end_timeout = timeout;
  facts_.end_new_cause = new_cause;
  facts_.end_no_request = no_request;
}

// E.3 step 2: a toggle request stops, else starts, else falls through to a
// reset. Returns whether a reset is requested this cycle.
bool EffectBlock::toggle_override(const Signals& s, std::uint64_t k, bool req_v, bool req_r, bool reset_tag_edge) {
  bool reset_request = reset_requested_;
  if (reset_tag_edge || toggle_requested_) {
    if (override_running_) {
      override_running_ = false;
      facts_.override_stopped = true;
    } else if ((req_v || req_r) && !bypassed_ && !output_delay_running_before_ && cfg_.has_override) {
      override_running_ = true;
      facts_.override_started = true;
      override_start_ = k;
      for (std::size_t i = 0; i < cfg_.links.size(); ++i)
        active_at_override_start_[i] = s.cause_active[cfg_.links[i].cause_slot];
      failed_timeout_ = false;
      failed_cause_ = false;
    } else {
      reset_request = true;
      facts_.toggle_as_reset = true;
    }
  }
  reset_requested_ = false;
  toggle_requested_ = false;
  return reset_request;
}

// E.4 Reset: only once the request is gone and no output delay runs.
// E.5 Latches; R needs no reset when its request falls during an override.
void EffectBlock::reset_and_latch(bool reset_request, bool req_s, bool req_r, bool was_running) {
  if (reset_request) {
    facts_.reset_cleared_s = s_latch_ && !req_s && !output_delay_running_before_;
    facts_.reset_cleared_r = r_latch_ && !req_r && !output_delay_running_before_;
    facts_.reset_blocked = (s_latch_ || r_latch_) && !facts_.reset_cleared_s && !facts_.reset_cleared_r;
    if (!req_s && !output_delay_running_before_) s_latch_ = false;
    if (!req_r && !output_delay_running_before_) r_latch_ = false;
  }
  if (req_s) s_latch_ = true;
  if (req_r) r_latch_ = true;
  if (was_running && req_r_before_ && !req_r) {
    facts_.r_cleared_by_override = r_latch_;
    r_latch_ = false;
  }
}

// E.7 Output delay: outputs follow once active continuously for D cycles;
// not in the first cycle after start-up.
void EffectBlock::delay_outputs(std::uint64_t k) {
  if (!active_) {
    output_state_ = false;
  } else if (output_state_before_) {
    output_state_ = true;
  } else if (k == 1) {
    output_state_ = true;
  } else {
    if (!active_before_) output_delay_start_ = k;
    output_state_ = k - output_delay_start_ >= cfg_.output_delay_cycles;
  }
  output_delay_running_ = active_ && !output_state_;
}

// E.8 Pass-through and mask, E.9 output values, then E.10 output simulation.
void EffectBlock::write_outputs(Signals& s, int slot) {
  const bool process_value = (cfg_.pass_through || cfg_.mask) && s.read_bool(cfg_.process_tag);
  masked_ = cfg_.mask && s.read_bool(cfg_.mask_tag);
  for (int j = 0; j < cfg_.tag_count; ++j) {
    const bool safe = cfg_.ett[j];  // DTT: 0 when active, ETT: 1
    const bool logic = output_state_ ? safe : !safe;
    const bool process = cfg_.ett[j] ? !process_value : process_value;
    bool out = logic;
    if (cfg_.pass_through && cfg_.mask) out = !output_state_ ? process : (masked_ ? process : safe);
    else if (cfg_.pass_through) out = !output_state_ ? process : safe;
    else if (cfg_.mask) out = masked_ ? process : logic;
    if (output_simulated_[j]) out = output_simulated_value_[j];
    output_[j] = out;
    s.effect_output[slot][j] = out;
  }
  s.effect_active[slot] = active_;
}

int EffectBlock::field(EffectField f) const {
  switch (f) {
    case EffectField::Active: return active_;
    case EffectField::Latched: return s_latch_ || r_latch_;
    case EffectField::OkToReset:
      return (s_latch_ || r_latch_) && !req_s_ && !req_r_ && !output_delay_running_;
    case EffectField::OverrideActive: return override_running_;
    case EffectField::OverrideFailedTimeout: return failed_timeout_;
    case EffectField::OverrideFailedCause: return failed_cause_;
    case EffectField::OverridePrealarm: return override_prealarm_;
    case EffectField::Bypassed: return bypassed_;
    case EffectField::SoftBypassed: return soft_bypass_;
    case EffectField::Masked: return masked_;
    case EffectField::PassThroughActive: return cfg_.pass_through && !output_state_;
    case EffectField::OutputDelayRunning: return output_delay_running_;
  }
  return 0;
}

}  // namespace cemv::runtime
