// The cones of a product's outputs and the groups they fall into (docs/plc.md
// "How an equality is proved"). An output's cone is the set of state
// variables its relation reaches through next-state and initial functions,
// on the matrix's side and the program's alike: a closed system of its own,
// so what is inductive on it is inductive on any product that holds it.
// Outputs whose cones share a state variable are proved together (one
// sampling, one Houdini, one re-check), each with the candidates of its own
// cone, so that the candidates grow with the cones, not with their union.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <z3++.h>

#include "checker/limits.hpp"
#include "checker/prover.hpp"
#include "encoder/transition_system.hpp"
#include "plc_check/sampling.hpp"

namespace cemv::plc_check {

// The state variables (indices into ts.statevars()) a term reads, each DAG
// node visited once; with `inputs`, the input variables (indices into
// ts.inputvars()) instead.
class TermReads {
 public:
  explicit TermReads(const encoder::TransitionSystem& ts, bool inputs = false);
  std::vector<std::size_t> of(const z3::expr& e);

 private:
  std::unordered_map<unsigned, std::size_t> index_;
  std::unordered_set<unsigned> seen_;
};

// The conjuncts of `e`, in order (a conjunction's arguments, flattened).
std::vector<z3::expr> conjuncts_of(const z3::expr& e);

// For each term, the indices (into ts.statevars(), ascending) of the state
// variables it reaches.
std::vector<std::vector<std::size_t>> cones_of(const encoder::TransitionSystem& ts, const std::vector<z3::expr>& terms);

// The indices of `cones` in groups: two cones share a group when a chain of
// cones, each sharing a state variable with the next, links them. Groups in
// the order of their first member, members ascending.
std::vector<std::vector<std::size_t>> overlapping(const std::vector<std::vector<std::size_t>>& cones);

// The state variables (indices, ascending) whose next-state function gives
// back their initial value whatever the state and the inputs, among those
// every sampled state holds at it: what an encoding computes as `x and not
// x` (the matrix's output delay of an effect without one, E.7, read by its
// override, E.3) reads every input of x and yet is constant. Each is asked
// of a solver charged to `meter` (throws checker::Stopped when it ends).
std::vector<std::size_t> constant_states(const checker::SafetyProblem& p, const Samples& samples,
                                         const checker::Limits& limits, checker::WorkMeter& meter);

// The inputs each state variable depends on (through every state variable
// it reads, transitively): which pairs of a cone's variables are worth a
// candidate relation. A program variable and the matrix variable it stands
// for are computed from the same inputs; a guard worth stating a relation
// under depends on no input its variables do not (a timer's running flag
// for its elapsed time; not the latch of an effect downstream, under which
// many of a cause's values are constant by chance in the samples). With
// these, a group's candidates grow with its cones' sizes, not their squares.
class Supports {
 public:
  // `constants`: state variables (indices) that never leave their initial
  // value; what reads them reads no input through them.
  explicit Supports(const encoder::TransitionSystem& ts, const std::vector<std::size_t>& constants = {});
  // The inputs of one include the other's (`same`: are the other's).
  bool related(std::size_t x, std::size_t y, bool same = false) const;
  // `g` reads no input, or exactly those of x and y together (y = SIZE_MAX:
  // x alone).
  bool may_guard(std::size_t g, std::size_t x, std::size_t y) const;
  // The inputs x depends on, as bits over ts.inputvars().
  std::vector<std::uint64_t> inputs_of(std::size_t x) const { return {of(x), of(x) + words_}; }

 private:
  std::size_t words_ = 0;
  std::vector<std::uint64_t> bits_;  // words_ per state variable
  const std::uint64_t* of(std::size_t v) const { return bits_.data() + v * words_; }
};

// The layers of a group's cones (docs/plc.md "A cone group's Houdini"): in
// each cone, the variables that depend on exactly the same inputs (a cause's
// state on both sides, an effect's), `top`, with every state variable they
// read, transitively, and those that depend on no input (which may guard a
// relation of any layer), `vars`; its top, what the top reads directly and
// those of no input, `near` (what a layer's candidates may read). A variable reads only variables of fewer
// or the same inputs, so the layers by the number of their inputs (then by
// size) put a cause's before the effects' that read it: a Houdini over the
// layers in this order proves each cause's correspondence once, on its own
// state, and each effect's given its causes' (product_houdini_by_layers).
struct Layer {
  std::vector<std::size_t> top;   // ascending
  std::vector<std::size_t> vars;  // ascending, top included
  std::vector<std::size_t> near;  // top, what it reads directly, the inputless: ascending
};
std::vector<Layer> layers_of(const encoder::TransitionSystem& ts, const std::vector<std::vector<std::size_t>>& cones,
                             const Supports& supports);

}  // namespace cemv::plc_check
