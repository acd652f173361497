// A scenario written for one matrix and meant to run on another one too (a
// killing scenario on its mutant, a distinguishing scenario on the other
// version of a change): the other matrix reads every tag the scenario does
// not state at its own default, and an ETT flip changes a tag's default. So
// the first step states every tag whose default differs there, with the
// run's first-cycle value: both matrices then see the same plant.
#pragma once

#include <string>
#include <vector>

#include "formats/scenario_writer.hpp"
#include "model/matrix.hpp"
#include "model/vocabulary.hpp"

namespace cemv::cli {

// The input tags of `m` (model::InputTable indices) whose start-up value
// differs in `other`.
inline std::vector<std::size_t> other_defaults(const model::Matrix& m, const model::Matrix& other) {
  const model::InputTable table(m), theirs_table(other);
  const auto mine = model::default_cycle_input(m).tags, theirs = model::default_cycle_input(other).tags;
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < table.size(); ++i) {
    auto j = theirs_table.find(table.tags()[i].name);
    if (j && theirs[*j].value != mine[i].value) out.push_back(i);
  }
  return out;
}

// A run of `m` checked at its end, written so that it runs on `other` too.
inline std::string scenario_for_both(const model::Matrix& m, const model::Matrix& other,
                                     const std::vector<model::CycleInput>& inputs, const std::string& description,
                                     std::vector<formats::ExpectedValue> expect) {
  formats::ScenarioRun run = formats::checked_at_end(inputs, description, std::move(expect));
  run.first_step_also_states = other_defaults(m, other);
  return formats::scenario_text(m, run);
}

}  // namespace cemv::cli
