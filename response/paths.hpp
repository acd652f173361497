// The paths of the SIF groups that `cemv response` measures
// (docs/response-time.md, "Paths"): a cause to an effect of the group, through
// a direct intersection or a chain of internal references; an XooN assignment
// is one path triggered by X of its causes.
#pragma once

#include <string>
#include <vector>

#include "model/graph.hpp"
#include "model/matrix.hpp"

namespace cemv::response {

struct Path {
  int sif = 0;                  // the SIF group
  std::vector<int> causes;      // the trigger causes (ids, ascending)
  int needed = 1;               // how many of them the trigger needs (X of XooN; 1 otherwise)
  int effect = 0;               // the effect whose outputs respond
  // Every cause and effect on some route from the trigger to the effect
  // (trigger causes, relaying causes, intermediate effects, the effect):
  // none of them may be bypassed, inhibited or overridden during a demand.
  std::vector<model::Node> elements;
  // A first guess of the logic response in cycles (the configured delays
  // along the slowest route): only where the search starts, never a result.
  long long estimate = 0;
  // Trigger causes with two or three external input tags (a voting whose
  // degraded figure is measured with one of them in bad quality).
  std::vector<int> voted;

  // "c1.e2", "c2_3_4.e1": the path's stable name (property names, files).
  std::string key() const;
};

// Every path of the given SIF groups (all declared groups when `sifs` is
// empty), by group, then effect id, then trigger causes. A path belongs to a
// group when its effect and some other element on it (a trigger or relaying
// cause) are members of the group.
std::vector<Path> response_paths(const model::Matrix& m, const std::vector<int>& sifs);

// The number of input tags a cause's voting needs for a trip (C.4: normal 1,
// or 1, and N, 2oo3 2).
int votes_needed(const model::Cause& c);

// A cause's input tags that are no internal references (6.1.3): what the
// plant sets.
std::vector<const model::CauseTag*> external_tags(const model::Cause& c);

// The duration of `ms` in whole cycles (T.2).
long long cycles_of(std::uint64_t ms, std::uint32_t cycle_ms);

}  // namespace cemv::response
