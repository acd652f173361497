// Instantiates a transition system at cycle k: every state and input variable
// `v` becomes `v@k`, every primed state variable `v.next` becomes `v@(k+1)`.
#pragma once

#include <map>
#include <unordered_map>
#include <string>
#include <vector>

#include <z3++.h>

#include "encoder/transition_system.hpp"

namespace cemv::encoder {

class Unroller {
 public:
  explicit Unroller(const TransitionSystem& ts);

  // `e` (over state, input and primed state variables) at cycle k.
  z3::expr at(const z3::expr& e, int k);
  // The copy of one variable at cycle k: a lookup, not a substitution (a
  // trace is read variable by variable, cycle by cycle: a substitution over
  // every variable each time made reading a model of a product of two wide
  // cones quadratic in its variables).
  z3::expr var_at(const z3::expr& var, int k);

  // init@0 and the constraints and transition of cycles 0..depth-1: a path of
  // `depth` cycles (states 0..depth, inputs 0..depth-1).
  z3::expr path(int depth);

 private:
  const std::vector<z3::expr>& vars_at(int k);
  z3::expr at_every_variable(const z3::expr& e, int k);  // `at` for a term with a quantifier

  const TransitionSystem& ts_;
  z3::expr_vector from_;                       // state vars, input vars, next vars
  std::unordered_map<unsigned, std::size_t> position_;  // AST id of a var in from_ -> its index
  std::map<int, std::vector<z3::expr>> copies_;  // k -> copies of state/input vars
};

}  // namespace cemv::encoder
