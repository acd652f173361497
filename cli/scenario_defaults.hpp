// A scenario written for one matrix and meant to run on another one too (a
// killing scenario on its mutant, a distinguishing scenario on the other
// version of a change): the other matrix reads every tag the scenario does
// not state at its own default, and an ETT flip changes a tag's default. So
// the first step states every tag whose default differs there, with the
// run's first-cycle value: both matrices then see the same plant.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "model/matrix.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::cli {

inline std::string with_other_defaults(const std::string& scenario, const model::Matrix& m,
                                       const model::CycleInput& first, const model::Matrix& other) {
  nlohmann::ordered_json doc = nlohmann::ordered_json::parse(scenario);
  if (!doc.contains("steps") || doc["steps"].empty()) return scenario;
  const model::InputTable table(m), theirs_table(other);
  const auto mine = model::default_cycle_input(m).tags, theirs = model::default_cycle_input(other).tags;
  auto& step = doc["steps"][0];
  bool changed = false;
  for (std::size_t i = 0; i < table.size(); ++i) {
    const std::string& name = table.tags()[i].name;
    auto j = theirs_table.find(name);
    if (!j || theirs[*j].value == mine[i].value) continue;
    if (step.contains("inputs") && step["inputs"].contains(name)) continue;
    const model::TagValue& v = first.tags[i];
    step["inputs"][name] = table.tags()[i].kind == model::TagKind::Bool
                               ? nlohmann::ordered_json(v.value != 0.0f)
                               : nlohmann::ordered_json::parse(model::float_text(v.value));
    changed = true;
  }
  return changed ? doc.dump(1) + "\n" : scenario;
}

}  // namespace cemv::cli
