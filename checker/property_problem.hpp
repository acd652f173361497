// A property of the property language as a safety problem of the prover
// interface (checker/prover.hpp): the matrix's encoding (its cone of
// influence, or all of it), the property's monitor compiled into it, and the
// input ranges every replayable trace respects. The checker, the test
// generator and the response-time analysis all state their questions this way.
#pragma once

#include <functional>
#include <limits>
#include <vector>

#include "checker/prover.hpp"
#include "encoder/encode.hpp"
#include "model/matrix.hpp"
#include "properties/ast.hpp"

namespace cemv::checker {

// What a problem asks of the property's monitor.
enum class Goal {
  Property,     // `good` in every cycle
  Antecedent,   // never the antecedent (falsified = the antecedent is reachable)
  Assumptions,  // never any cycle at all (falsified = the assumptions can hold)
};

struct ProblemOptions {
  Goal goal = Goal::Property;
  bool sliced = true;  // the property's cone of influence only (docs/encoding.md "Slices")
  // The roots to slice by instead of the property's own (sliced only; empty:
  // the property's). A caller that asks many questions of one cone
  // (testgen's objectives of one element) names it once.
  std::vector<model::Node> roots;
  // Analog inputs range over [-analog_range, analog_range]: the finite
  // single-precision values by default, what a scenario can write
  // (docs/scenario.md), so every trace can be replayed and handed over as a
  // file. The test generator asks for what a transmitter delivers.
  float analog_range = std::numeric_limits<float>::max();
  // Per InputTable index, the only values an analog input may take (empty:
  // any in range): the values an engineer sets (testgen/search.hpp).
  std::vector<std::vector<float>> analog_values;
  // The initial state is the state these cycles leave, computed by the
  // encoding's own Evaluator, the monitor included, so that the past-time
  // operators see them: how a test is extended. Pointed at, not copied (an
  // 8 h test is 576,000 cycles, copied once more by every copy of the
  // options and of the factory holding them): it must outlive the factory.
  // nullptr or empty: from start-up.
  const std::vector<model::CycleInput>* prefix = nullptr;
  // Each removable cell guarded by an activation literal
  // (encoder::EncodeOptions::guard_cells): the support's core query.
  bool guard_cells = false;
  // Applied to every encoding before the monitor is compiled (Pono's modifiers/).
  std::function<void(encoder::Encoding&)> modify_encoding;
};

// The state `prefix` leaves, computed by the encoding's own Evaluator (the
// monitors included), becomes the encoding's initial state.
void start_after(encoder::Encoding& enc, const std::vector<model::CycleInput>& prefix);

// The factory builds the problem in any context (one per portfolio thread).
// It keeps copies of the matrix and pointers to the property and its file:
// both must outlive the factory. The owner of every built problem is its
// encoder::Encoding.
ProblemFactory property_problem(const model::Matrix& m, const properties::PropertyFile& file,
                                const properties::Property& p, const ProblemOptions& options = {});

}  // namespace cemv::checker
