// A symbolic transition system over Z3, in the spirit of Pono's
// TransitionSystem: state variables with an initial value and a next-state
// function, free input variables, per-cycle constraints on the inputs, named
// terms (the observables) and named lemmas (invariants for induction).
//
// Timing convention (docs/encoding.md): a state variable holds what the
// previous scan cycle left behind; named terms and next-state functions are
// functions of (state, inputs) of the current cycle. Cycle k reads state@k and
// inputs@k and produces observables@k and state@(k+1).
#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <z3++.h>

namespace cemv::encoder {

class TransitionSystem {
 public:
  struct StateVar {
    std::string name;
    z3::expr var;
    z3::expr next_var;   // the primed copy, "name.next", used by trans_formula()
    z3::expr init;
    z3::expr next;
    bool has_init = false;  // set_init was called
    bool has_next = false;  // assign_next was called
  };
  struct InputVar {
    std::string name;
    z3::expr var;
  };
  struct Named {
    std::string name;
    z3::expr term;
  };

  explicit TransitionSystem(z3::context& ctx) : ctx_(&ctx) {}

  z3::context& ctx() const { return *ctx_; }

  // A state variable; its initial value and next-state function must be set
  // (set_init / assign_next) before the system is used: check_complete() says
  // which are not (a variable without them would silently keep a free
  // initial value or stay constant, as Pono's TransitionSystem also reports).
  z3::expr make_statevar(const std::string& name, const z3::sort& sort);
  z3::expr make_inputvar(const std::string& name, const z3::sort& sort);
  void set_init(const z3::expr& statevar, const z3::expr& value);
  void assign_next(const z3::expr& statevar, const z3::expr& next);
  // A condition the inputs (and state) of every cycle satisfy (e.g. no NaN).
  void add_constraint(const std::string& name, const z3::expr& c);
  // An observable (or helper) term over the state and inputs of one cycle.
  void name_term(const std::string& name, const z3::expr& term);
  // An invariant over the state variables, claimed to hold in every reachable
  // state (e.g. counter ranges); the checker proves it before using it.
  void add_lemma(const std::string& name, const z3::expr& lemma);

  // Throws std::logic_error naming every state variable that has no initial
  // value or no next-state function. encode() calls it on what it built;
  // whoever adds state variables afterwards (a property monitor) calls it again.
  void check_complete() const;

  const std::vector<StateVar>& statevars() const { return states_; }
  const std::vector<InputVar>& inputvars() const { return inputs_; }
  const std::vector<Named>& constraints() const { return constraints_; }
  const std::vector<Named>& named_terms() const { return terms_; }
  const std::vector<Named>& lemmas() const { return lemmas_; }

  std::optional<z3::expr> term(const std::string& name) const;
  std::optional<z3::expr> statevar(const std::string& name) const;
  std::optional<z3::expr> inputvar(const std::string& name) const;
  bool is_statevar(const z3::expr& e) const;
  bool is_inputvar(const z3::expr& e) const;

  // Conjunction of var == init over all state variables.
  z3::expr init_formula() const;
  // Conjunction of next_var == next over all state variables (relational form).
  z3::expr trans_formula() const;
  // Conjunction of all constraints.
  z3::expr constraint_formula() const;

  // Float constants of the encoding, by value (hash-consed by Z3 as well).
  z3::expr float_const(float v) const;
  // The value of a constant made by float_const, by Z3 AST id.
  std::optional<float> float_value(unsigned ast_id) const;
  // Rounding mode of every floating-point operation: round to nearest, ties to
  // even, the IEEE 754 default the runtime's float arithmetic uses.
  z3::expr rne() const;

 private:
  StateVar& state_of(const z3::expr& var);

  z3::context* ctx_;
  std::vector<StateVar> states_;
  std::vector<InputVar> inputs_;
  std::vector<Named> constraints_;
  std::vector<Named> terms_;
  std::vector<Named> lemmas_;
  std::unordered_map<unsigned, std::size_t> state_index_;  // by Z3 AST id
  std::unordered_map<unsigned, std::size_t> input_index_;
  std::unordered_map<std::string, std::size_t> term_index_;
  mutable std::unordered_map<unsigned, float> float_values_;
  mutable std::vector<z3::expr> float_terms_;  // keeps float_values_'s keys alive: Z3 reuses a freed term's id
};

}  // namespace cemv::encoder
