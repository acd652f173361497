// The reference runtime: the executable meaning of a matrix, one scan cycle at
// a time, written line by line from docs/semantics.md. It shares the data model
// and the evaluation order (model/) with the SMT encoder and no semantic code.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "model/vocabulary.hpp"
#include "model/matrix.hpp"
#include "runtime/explain.hpp"

namespace cemv::runtime {

class Runtime {
 public:
  // The matrix must have passed validation without errors; the runtime keeps
  // its own copy.
  explicit Runtime(const model::Matrix& m);
  ~Runtime();
  Runtime(Runtime&&) noexcept;
  Runtime& operator=(Runtime&&) noexcept;
  // The runtime in its present state: the same cycles give both the same
  // observables (a search that runs many continuations of one prefix).
  Runtime(const Runtime& other);
  Runtime& operator=(const Runtime& other);

  const model::Matrix& matrix() const;
  // The input tags, in the order of CycleInput::tags.
  const model::InputTable& inputs() const;
  // Input values a fresh plant shows (scenario defaults: non-tripped, good quality).
  model::CycleInput default_input() const;

  // Runs exactly one scan cycle of cycle_ms. No heap allocation.
  void step(const model::CycleInput& in);
  std::uint64_t cycles_run() const;

  // The value of one observable (model::observables) after the last step:
  // Bool 0/1, Int as is, Voting as the model::Voting enumerator.
  int value(const model::Observable& o) const;
  // All observables in model::observables order.
  void snapshot(std::vector<int>& out) const;
  // The i-th of them (0-based, i < model::observables(matrix()).size()): a
  // loop that compares a few observables every cycle reads only those.
  int observable(std::size_t i) const;

  // The value of an output tag by name (case-insensitive); nullopt if unknown.
  std::optional<bool> output(std::string_view tag) const;
  // Commands refused in the last cycle (secure write, mutual lock, not allowed).
  int commands_refused() const;

  // Explanations (runtime/explain.hpp): after explain(true), each step() also
  // records why every observable that changed in that cycle changed, the
  // rule of docs/semantics.md the blocks applied. Off by default, and then
  // step() allocates nothing (bench_runtime).
  void explain(bool on);
  // The changes of the last step, in model::observables order (empty when off).
  const std::vector<Explanation>& explanations() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cemv::runtime
