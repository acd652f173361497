// Internal to the runtime: the matrix laid out for the scan cycle, once, when
// the runtime is made: the processed elements in slots by ascending id, each
// block's configuration with its tags resolved (I.3), the one evaluation
// order (I.4), the first-out groups (C.11), the tags an operator may simulate
// (O.8), and the tags of secure write (M.3) and group deactivation (M.2).
#pragma once

#include <cctype>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "model/matrix.hpp"
#include "runtime/cause_block.hpp"
#include "runtime/effect_block.hpp"
#include "runtime/signals.hpp"

namespace cemv::runtime {

// Case-insensitive comparison of a tag name with a key made by model::tag_key,
// without allocating (commands are handled inside step()).
inline bool same_tag(std::string_view key, std::string_view name) {
  if (key.size() != name.size()) return false;
  for (std::size_t i = 0; i < key.size(); ++i)
    if (key[i] != static_cast<char>(std::toupper(static_cast<unsigned char>(name[i])))) return false;
  return true;
}

// One evaluation step of the cycle: a cause or an effect slot.
struct Step {
  bool is_cause = true;
  int slot = 0;
};

// A tag an operator may simulate (O.8): a cause input tag and/or an output tag.
struct SimulationTarget {
  std::string key;
  int input_index = -1;                          // cause input tag
  bool allowed = true;                           // no reader or writer forbids it (O.8)
  std::vector<std::pair<int, int>> readers;      // (cause slot, position) reading it
  std::vector<std::pair<int, int>> outputs;      // (effect slot, position) writing it
};

struct GroupDeactivationTags {
  TagSource enable;
  TagSource set;
};

struct ScanLayout {
  std::vector<int> cause_ids;  // slot -> id (ascending)
  std::vector<int> effect_ids;
  std::vector<CauseConfig> causes;  // by slot
  std::vector<EffectConfig> effects;
  std::vector<Step> order;  // the dependency graph's evaluation order (I.4)
  std::vector<std::vector<int>> first_out_groups;  // group -> cause slots by id (C.11)
  std::vector<SimulationTarget> simulation_targets;
  std::optional<TagSource> secure_write_enable;
  std::optional<GroupDeactivationTags> group_deactivation;

  // The slot of a processed element; -1 for any other id.
  int cause_slot(int id) const;
  int effect_slot(int id) const;
};

// Throws std::invalid_argument for a cycle of 0 ms.
ScanLayout lay_out(const model::Matrix& m, const model::InputTable& inputs);

}  // namespace cemv::runtime
