// Internal to the runtime: the operator commands (docs/semantics.md section O)
// applied to the blocks of one matrix, each accepted or refused.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/scan_layout.hpp"

namespace cemv::runtime {

class OperatorCommands {
 public:
  OperatorCommands(const ScanLayout& layout, std::vector<CauseBlock>& causes, std::vector<EffectBlock>& effects,
                   Signals& signals)
      : layout_(layout), causes_(causes), effects_(effects), signals_(signals) {}

  // Applies one command in the given cycle; false when it is refused.
  bool apply(const model::Command& c, std::uint64_t cycle);

 private:
  bool simulate(const model::Command& c);
  bool stop_simulation(const model::Command& c);
  void end_simulation(const SimulationTarget& t);
  bool another_tag_in_maintenance(int cause_slot, int position) const;
  bool another_output_simulated(int effect_slot, int position) const;

  const ScanLayout& layout_;
  std::vector<CauseBlock>& causes_;
  std::vector<EffectBlock>& effects_;
  Signals& signals_;
};

}  // namespace cemv::runtime
