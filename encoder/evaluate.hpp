// Model evaluation: runs an encoding on concrete inputs, cycle by cycle, by
// evaluating its formulas (the next-state functions and the named terms) on
// concrete values of the state and input variables. This is how the
// differential test checks the encoder against the runtime without a solver
// call per cycle. The formulas are compiled once into a flat program over the
// Z3 terms' DAG; every operator the encoder emits is interpreted with the
// SMT-LIB meaning (Float32 operations in IEEE single precision, round to
// nearest even), and a test checks it against Z3's own simplifier.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "encoder/encode.hpp"
#include "model/vocabulary.hpp"

namespace cemv::encoder {

class Evaluator {
 public:
  explicit Evaluator(const Encoding& enc);

  // Back to the initial state (before the first cycle).
  void reset();
  // One scan cycle on these inputs and commands.
  void step(const model::CycleInput& in);
  std::uint64_t cycles() const { return cycles_; }

  // The value of a named term after the last step: Bool 0/1, Int as is.
  int value(const std::string& key) const;
  // The encoding's observables (Encoding::observables order) after the last step.
  void snapshot(std::vector<int>& out) const;

  // Concrete value of an input for one cycle, by input variable index; used
  // by step() and by tests that drive raw inputs.
  struct Value {
    std::int64_t i = 0;  // Bool 0/1 or Int
    float f = 0.0f;      // Float32
  };
  void step_raw(const std::vector<Value>& inputs);
  // The input variable values step() would use for `in`.
  std::vector<Value> input_values(const model::CycleInput& in) const;
  const std::vector<Value>& state() const { return state_; }

 private:
  struct Instr {
    int op = 0;           // Z3_decl_kind, or one of the pseudo ops
    std::vector<int> args;
    Value constant;
  };
  int compile(const z3::expr& e);
  void run();
  // The operations of program_ (not its variables and constants) in one
  // array, their arguments in another: what run() walks every cycle.
  struct Op {
    int op = 0;
    int slot = 0;
    int first = 0;  // into op_args_
    int count = 0;
  };
  void flatten();

  const Encoding& enc_;
  std::vector<Instr> program_;
  std::vector<Op> ops_;
  std::vector<int> op_args_;
  std::vector<Value> slots_;
  std::vector<int> state_slot_, input_slot_, next_slot_, init_slot_, term_slot_;
  std::vector<int> observable_slot_;
  std::vector<Value> state_;
  std::unordered_map<unsigned, int> memo_;  // Z3 AST id -> slot
  std::unordered_map<unsigned, std::size_t> input_index_;  // Z3 AST id -> input variable index
  std::uint64_t cycles_ = 0;
};

}  // namespace cemv::encoder
