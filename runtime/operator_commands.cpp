// The operator commands (docs/semantics.md section O), runtime/operator_commands.hpp.
#include "runtime/operator_commands.hpp"

namespace cemv::runtime {

bool OperatorCommands::another_tag_in_maintenance(int cause, int position) const {
  const CauseBlock& block = causes_[cause];
  const CauseConfig& cfg = block.config();
  for (int j = 0; j < cfg.tag_count; ++j) {
    if (j == position || cfg.tag_key[j] == cfg.tag_key[position]) continue;
    if (block.tag_soft_bypassed(j)) return true;
    if (cfg.input_index[j] >= 0 && signals_.input_simulated[cfg.input_index[j]]) return true;
  }
  return false;
}

bool OperatorCommands::another_output_simulated(int effect, int position) const {
  const EffectBlock& block = effects_[effect];
  const EffectConfig& cfg = block.config();
  for (int j = 0; j < cfg.tag_count; ++j) {
    if (j == position || cfg.tag_key[j] == cfg.tag_key[position]) continue;
    if (block.output_simulated(j)) return true;
  }
  return false;
}

void OperatorCommands::end_simulation(const SimulationTarget& t) {
  if (t.input_index >= 0) signals_.input_simulated[t.input_index] = 0;
  for (auto [slot, j] : t.outputs) effects_[slot].stop_output_simulation(j);
}

bool OperatorCommands::simulate(const model::Command& c) {
  for (const SimulationTarget& t : layout_.simulation_targets) {
    if (!same_tag(t.key, c.tag_name)) continue;
    if (!t.allowed) return false;  // simulation of this tag is not allowed (O.8)
    // Mutual lock (O.8).
    for (auto [slot, i] : t.readers)
      if (causes_[slot].config().mutually_locked && another_tag_in_maintenance(slot, i)) return false;
    for (auto [slot, j] : t.outputs)
      if (effects_[slot].config().mutually_locked && another_output_simulated(slot, j)) return false;
    if (t.input_index >= 0) {
      signals_.input_simulated[t.input_index] = 1;
      signals_.input_simulated_value[t.input_index] = c.value;
    }
    for (auto [slot, j] : t.outputs) effects_[slot].simulate_output(j, c.value != 0.0f);
    return true;
  }
  return false;
}

bool OperatorCommands::stop_simulation(const model::Command& c) {
  if (c.tag_name.empty()) {
    for (const SimulationTarget& t : layout_.simulation_targets) end_simulation(t);
    return true;
  }
  for (const SimulationTarget& t : layout_.simulation_targets)
    if (same_tag(t.key, c.tag_name)) {
      end_simulation(t);
      return true;
    }
  return false;
}

// Applies one command; false when it is refused (section O).
bool OperatorCommands::apply(const model::Command& c, std::uint64_t cycle) {
  using Op = model::CommandOp;
  switch (c.op) {
    case Op::AckCause: {  // O.1
      int slot = layout_.cause_slot(c.cause);
      if (slot < 0 || !causes_[slot].config().has_ack_latch) return false;
      causes_[slot].request_ack();
      return true;
    }
    case Op::ResetEffect: {  // O.2
      int slot = layout_.effect_slot(c.effect);
      if (slot < 0) return false;
      const EffectConfig& cfg = effects_[slot].config();
      if (cfg.has_reset_tag || !cfg.has_reset_or_stored) return false;
      effects_[slot].request_reset();
      return true;
    }
    case Op::OverrideEffect:
    case Op::StopOverride: {  // O.3
      int slot = layout_.effect_slot(c.effect);
      if (slot < 0) return false;
      const EffectConfig& cfg = effects_[slot].config();
      if (cfg.has_reset_tag || !cfg.has_overridable) return false;
      effects_[slot].request_toggle();
      return true;
    }
    case Op::SoftBypassCause: {  // O.5
      int slot = layout_.cause_slot(c.cause);
      if (slot < 0 || !causes_[slot].config().soft_bypass_allowed) return false;
      causes_[slot].set_soft_bypass(c.on, cycle);
      return true;
    }
    case Op::SoftBypassTag: {  // O.6
      int slot = layout_.cause_slot(c.cause);
      if (slot < 0) return false;
      const CauseConfig& cfg = causes_[slot].config();
      const int position = c.tag - 1;
      if (position < 0 || position >= cfg.tag_count || !cfg.tag_soft_bypass_allowed[position])
        return false;
      if (c.on && cfg.mutually_locked && another_tag_in_maintenance(slot, position)) return false;
      causes_[slot].set_tag_soft_bypass(position, c.on);
      return true;
    }
    case Op::SoftBypassEffect: {  // O.7
      int slot = layout_.effect_slot(c.effect);
      if (slot < 0 || !effects_[slot].config().soft_bypass_allowed) return false;
      effects_[slot].set_soft_bypass(c.on);
      return true;
    }
    case Op::SimulateTag: return simulate(c);           // O.8
    case Op::StopSimulation: return stop_simulation(c);  // O.8
    case Op::ClearFirstOut: {  // O.9
      if (c.group < 1 || c.group > model::kMaxFirstOutGroup) return false;
      for (int slot : layout_.first_out_groups[c.group]) causes_[slot].clear_first_out();
      return true;
    }
    case Op::ClearAlarms: {  // O.10
      int cs = c.cause != 0 ? layout_.cause_slot(c.cause) : -1;
      int es = c.effect != 0 ? layout_.effect_slot(c.effect) : -1;
      if ((c.cause != 0 && cs < 0) || (c.effect != 0 && es < 0) || (cs < 0 && es < 0)) return false;
      if (cs >= 0) causes_[cs].clear_alarms();
      if (es >= 0) effects_[es].clear_alarms();
      return true;
    }
  }
  return false;
}

}  // namespace cemv::runtime
