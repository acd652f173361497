// The trace `cemv-trace/1` of a replayed scenario (docs/scenario.md, "Trace"):
// a header naming the matrix (and its signature), the input tags, the
// observables and the output tags, then one line per cycle with the inputs,
// the bad-quality tags, the commands, the refused-command count, every
// observable and every output value.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/matrix.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats {

inline constexpr const char* kTraceFormat = "cemv-trace/1";

class TraceWriter {
 public:
  // `outputs`: the output tag names, in the order of the output observables.
  TraceWriter(const model::Matrix& m, const model::InputTable& inputs,
              const std::vector<model::Observable>& observables, std::vector<std::string> outputs);

  // One cycle (0-based `cycle`, in `step`): its input, the commands refused,
  // the snapshot of every observable and each output's value (nullopt: none).
  void add_cycle(std::size_t cycle, std::size_t step, const model::CycleInput& in, int commands_refused,
                 const std::vector<int>& snapshot, const std::vector<std::optional<bool>>& outputs);

  // Writes the trace; false when the file cannot be written.
  bool write(const std::filesystem::path& file, const std::string& signature) const;

 private:
  const model::Matrix& m_;
  const model::InputTable& inputs_;
  const std::vector<model::Observable>& observables_;
  std::vector<std::string> outputs_;
  nlohmann::json cycles_ = nlohmann::json::array();
};

}  // namespace cemv::formats
