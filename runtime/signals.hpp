// Internal to the runtime: where a tag's value comes from, and the one table of
// values every function block reads in a scan cycle (docs/semantics.md I.1-I.4).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "model/vocabulary.hpp"
#include "model/matrix.hpp"

namespace cemv::runtime {

// One tag as a block reads it, resolved once at construction.
struct TagSource {
  enum class Kind {
    None,          // not configured, or an internal reference to nothing (I.3: reads 0)
    Input,         // an external input tag: index into the InputTable
    CauseActive,   // Cause[x]: slot of cause x
    EffectActive,  // Effect[x]: slot of effect x
    EffectOutput,  // Effect[x][y]: slot of effect x, output tag y (0-based)
  } kind = Kind::None;
  int index = 0;
  int tag = 0;
};

// The values of one scan cycle. Cause and effect results are written in place
// as each block is evaluated, in the evaluation order of the dependency graph:
// a reader therefore sees the current value of an element evaluated earlier in
// this cycle and the previous cycle's value of one evaluated later, which is
// exactly DependencyGraph::reads_previous (I.4). Before cycle 1 everything is 0
// (T.3).
struct Signals {
  const model::CycleInput* input = nullptr;

  // Simulation of input tags (O.8), by InputTable index.
  std::vector<std::uint8_t> input_simulated;
  std::vector<float> input_simulated_value;

  // Results read through internal references, by cause / effect slot.
  std::vector<std::uint8_t> cause_active;
  std::vector<std::uint8_t> effect_active;
  std::vector<std::array<std::uint8_t, model::kMaxEffectTags>> effect_output;

  // A cause input tag (C.2): simulation first, then reference, then input.
  model::TagValue read_cause_input(const TagSource& s) const {
    if (s.kind == TagSource::Kind::Input && input_simulated[s.index])
      return model::TagValue{input_simulated_value[s.index], false};
    return read_raw(s);
  }

  // Any other tag (bypass, inhibit, reset, process value, mask, enable, set):
  // by value alone, quality not evaluated (I.2).
  bool read_bool(const TagSource& s) const { return read_raw(s).value != 0.0f; }

 private:
  model::TagValue read_raw(const TagSource& s) const {
    switch (s.kind) {
      case TagSource::Kind::None: return {};
      case TagSource::Kind::Input: return input->tags[s.index];
      case TagSource::Kind::CauseActive: return {cause_active[s.index] ? 1.0f : 0.0f, false};
      case TagSource::Kind::EffectActive: return {effect_active[s.index] ? 1.0f : 0.0f, false};
      case TagSource::Kind::EffectOutput:
        return {effect_output[s.index][s.tag] ? 1.0f : 0.0f, false};
    }
    return {};
  }
};

// Whole cycles of a duration (T.2): ceil(ms / cycle_ms), in 64 bits.
inline std::uint64_t duration_cycles(std::uint64_t ms, std::uint32_t cycle_ms) {
  return (ms + cycle_ms - 1) / cycle_ms;
}

}  // namespace cemv::runtime
