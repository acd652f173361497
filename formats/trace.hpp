// The trace `cemv-trace/1` of a replayed scenario (docs/scenario.md, "Trace"):
// a header naming the matrix (and its signature), the input tags, the
// observables and the output tags, then one line per cycle with the inputs,
// the bad-quality tags, the commands, the refused-command count, every
// observable and every output value.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/matrix.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats {

inline constexpr const char* kTraceFormat = "cemv-trace/1";

// Writes the trace as the scenario runs, through `sink` (the CLI's checked
// output), so memory stays the same however many cycles there are: the
// header first, then one line per cycle, then the closing brackets. The bytes
// are those of the whole-trace writer of earlier versions.
class TraceWriter {
 public:
  using Sink = std::function<void(std::string_view)>;
  struct Options {
    // Only the cycles whose row differs from the previous cycle's (inputs,
    // bad quality, commands, refusals, observables, outputs), plus the first
    // and the last: a long, mostly quiet run fits in a small file. The header
    // then says "changes_only": true.
    bool changes_only = false;
  };

  // `outputs`: the output tag names, in the order of the output observables.
  // Writes the header.
  TraceWriter(const model::Matrix& m, const model::InputTable& inputs,
              const std::vector<model::Observable>& observables, std::vector<std::string> outputs,
              const std::string& signature, Sink sink, Options options);
  TraceWriter(const model::Matrix& m, const model::InputTable& inputs,
              const std::vector<model::Observable>& observables, std::vector<std::string> outputs,
              const std::string& signature, Sink sink)
      : TraceWriter(m, inputs, observables, std::move(outputs), signature, std::move(sink), Options{}) {}

  // One cycle (0-based `cycle`, in `step`): its input, the commands refused,
  // the snapshot of every observable and each output's value (nullopt: none).
  void add_cycle(std::size_t cycle, std::size_t step, const model::CycleInput& in, int commands_refused,
                 const std::vector<int>& snapshot, const std::vector<std::optional<bool>>& outputs);

  // Writes the last cycle held back (changes_only) and the closing brackets.
  void finish();

  std::size_t cycles_written() const { return written_; }

 private:
  void emit(const nlohmann::json& cycle);

  const model::Matrix& m_;
  const model::InputTable& inputs_;
  const std::vector<model::Observable>& observables_;
  std::vector<std::string> outputs_;
  Sink sink_;
  Options options_;
  std::size_t written_ = 0;
  // changes_only: the previous cycle's row without cycle, t_ms and step, and
  // the last cycle not written yet (written by finish()).
  nlohmann::json previous_row_;
  std::optional<nlohmann::json> held_;
  bool finished_ = false;
};

}  // namespace cemv::formats
