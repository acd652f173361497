// Internal to the runtime: the words of each rule of docs/semantics.md that
// can change a status field, chosen from what the function blocks recorded
// in their facts during the cycle (runtime/explain.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "model/vocabulary.hpp"
#include "runtime/cause_block.hpp"
#include "runtime/effect_block.hpp"

namespace cemv::runtime {

// One cycle as the explanations see it.
struct CycleView {
  const model::Matrix& m;
  const model::CycleInput& in;
  const std::vector<std::uint8_t>& accepted;  // per command of in.commands
  bool group_deactivation = false;            // M.2 fired in this cycle
  const std::vector<int>& cause_ids;          // slot -> id
  const std::vector<int>& effect_ids;
  const std::vector<CauseBlock>& causes;
  const std::vector<EffectBlock>& effects;
};

std::string why_cause(const CycleView& v, int slot, CauseField f, int before, int after);
// field: an EffectField, or -1 for output tag `tag` (0-based).
std::string why_effect(const CycleView& v, int slot, int field, int tag, int before, int after);

}  // namespace cemv::runtime
