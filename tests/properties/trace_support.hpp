// Runtime traces for the property tests: a scenario or a list of cycle inputs
// run on the reference runtime, with the observables after every cycle.
#pragma once

#include <filesystem>
#include <vector>

#include "formats/scenario.hpp"
#include "properties/evaluator.hpp"
#include "runtime/runtime.hpp"

namespace cemv::properties::testing {

inline Trace run_inputs(const model::Matrix& m, const std::vector<model::CycleInput>& inputs) {
  runtime::Runtime rt(m);
  Trace t;
  t.reserve(inputs.size());
  for (const auto& in : inputs) {
    rt.step(in);
    TraceCycle c;
    c.input = in;
    rt.snapshot(c.observables);
    t.push_back(std::move(c));
  }
  return t;
}

inline Trace run_scenario(const model::Matrix& m, const std::filesystem::path& file) {
  formats::Scenario sc = formats::load_scenario(file, m);
  return run_inputs(m, formats::expand_scenario(sc, m).cycles);
}

}  // namespace cemv::properties::testing
