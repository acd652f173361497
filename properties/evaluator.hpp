// The concrete evaluator of the property language: decides properties on one
// finite runtime trace, straight from the definitions of docs/properties.md
// ("Semantics"), looking back over the whole trace. It is the independent
// judge of counterexamples found by the symbolic monitor (properties/monitor.*),
// with which it shares no code.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/vocabulary.hpp"
#include "model/matrix.hpp"
#include "properties/ast.hpp"

namespace cemv::properties {

// One scan cycle of a trace: what the runtime consumed and the observables
// after the scan (runtime::Runtime::snapshot, model::observables order:
// Bool 0/1, Int as is, Voting as the model::Voting enumerator).
struct TraceCycle {
  model::CycleInput input;
  std::vector<int> observables;
};
using Trace = std::vector<TraceCycle>;  // index 0 = the first cycle after start-up

struct Evaluation {
  std::string name;
  PropertyKind kind = PropertyKind::Invariant;
  // Invariant / Never / Response: no violation inside the judged part of the
  // trace. Reachable: a witness inside it.
  bool holds = true;
  // Invariant / Never: the first violating cycle. Response: the cycle where the
  // first violation becomes definite (trigger cycle + within_cycles).
  // Reachable: the first witness. 0-based trace indices.
  std::optional<std::size_t> cycle;
  std::optional<std::size_t> trigger_cycle;  // Response: the trigger of that violation
  // The judged part of the trace is cycles [0, judged): every assumption
  // (file and property) held in each of them. A trace whose assumptions fail
  // early is judged on its prefix only; `assumptions_held` says whether they
  // held throughout.
  std::size_t judged = 0;
  bool assumptions_held = true;
  // Whether the antecedent (Response: the trigger; Invariant of `a implies b`
  // and Never of `a and b`: a) held in some judged cycle. A property that holds
  // with an antecedent never met says nothing about this trace.
  bool antecedent_met = false;
};

// The same meaning one cycle at a time, for the runs test generation judges
// (testgen/explore.cpp: seeded simulation's many runs; testgen/generate.cpp:
// every run a test is made of): each past-time operator keeps its memory (a
// previous value, a run length, a distance, a since flag) instead of the
// trace, so judging a run of a million cycles holds one cycle, and a copy
// taken after a prefix judges every run from there without the prefix.
// result() after the steps of a trace is what Evaluator::evaluate says on
// that trace, at every cut (tests/properties/test_stream_evaluator.cpp holds
// the two to each other); like it, it shares no code with the monitor.
class StreamEvaluator {
 public:
  // `p` and `file_assumptions` must outlive the evaluator and its copies.
  StreamEvaluator(const model::Matrix& m, const Property& p, const std::vector<Assumption>& file_assumptions);

  // One more cycle of the trace (TraceCycle's input and observables).
  void step(const model::CycleInput& input, const std::vector<int>& observables);
  // The evaluation of the cycles stepped so far.
  const Evaluation& result() const { return result_; }
  // Whether `holds` and `cycle` are decided whatever cycles follow: a
  // violation or witness found, or an assumption failed.
  bool final() const { return result_.cycle.has_value() || frozen_; }
  // The observables the property and its assumptions read (indices in
  // model::observables order, ascending): step() reads no other entry of its
  // vector, so a caller stepping a runtime copies only these each cycle.
  const std::vector<std::size_t>& observables_read() const { return program_->read; }

  // A compiled expression node; its children come before it.
  struct Node {
    const Expr* expr = nullptr;
    std::size_t observable = 0;       // Observable: index in the snapshot
    std::vector<std::size_t> args;    // node indices
    bool floats = false;              // Compare: in single precision
  };
  struct Program {
    std::vector<Node> nodes;
    std::vector<std::size_t> assumptions;  // roots
    std::size_t antecedent = 0, body = 0, trigger = 0, response = 0;
    bool has_antecedent = false;
    std::vector<std::size_t> read;  // the Observable nodes' indices, distinct, ascending
  };
  struct Value {
    std::int64_t i = 0;
    float f = 0.0f;
  };

 private:
  void evaluate_all(const model::CycleInput& input, const std::vector<int>& observables);

  std::shared_ptr<const Program> program_;  // shared by copies
  std::vector<std::int64_t> memory_;        // per node: what its operator remembers
  std::vector<Value> now_;                  // per node: its value this cycle
  const Property* property_;
  std::optional<std::size_t> pending_;      // Response: the oldest trigger not answered yet
  bool frozen_ = false;                     // an assumption failed: nothing later is judged
  Evaluation result_;
};

class Evaluator {
 public:
  // The matrix fixes the observable order (model::observables) and the input tags.
  explicit Evaluator(const model::Matrix& m);

  Evaluation evaluate(const Property& p, const std::vector<Assumption>& file_assumptions, const Trace& t) const;
  std::vector<Evaluation> evaluate(const PropertyFile& f, const Trace& t) const;

  // The value of a Boolean expression in every cycle of the trace.
  std::vector<bool> values(const Expr& e, const Trace& t) const;

 private:
  std::vector<model::Observable> observables_;
};

}  // namespace cemv::properties
