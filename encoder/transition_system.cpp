#include "encoder/transition_system.hpp"

#include <stdexcept>

namespace cemv::encoder {

z3::expr TransitionSystem::make_statevar(const std::string& name, const z3::sort& sort) {
  z3::expr v = ctx_->constant(name.c_str(), sort);
  z3::expr nv = ctx_->constant((name + ".next").c_str(), sort);
  if (state_index_.count(v.id()) || input_index_.count(v.id()))
    throw std::logic_error("duplicate variable " + name);
  state_index_.emplace(v.id(), states_.size());
  states_.push_back(StateVar{name, v, nv, v, v});
  return v;
}

z3::expr TransitionSystem::make_inputvar(const std::string& name, const z3::sort& sort) {
  z3::expr v = ctx_->constant(name.c_str(), sort);
  if (state_index_.count(v.id()) || input_index_.count(v.id()))
    throw std::logic_error("duplicate variable " + name);
  input_index_.emplace(v.id(), inputs_.size());
  inputs_.push_back(InputVar{name, v});
  return v;
}

TransitionSystem::StateVar& TransitionSystem::state_of(const z3::expr& var) {
  auto it = state_index_.find(var.id());
  if (it == state_index_.end()) throw std::logic_error("not a state variable: " + var.to_string());
  return states_[it->second];
}

void TransitionSystem::set_init(const z3::expr& statevar, const z3::expr& value) {
  StateVar& s = state_of(statevar);
  s.init = value;
  s.has_init = true;
}

void TransitionSystem::assign_next(const z3::expr& statevar, const z3::expr& next) {
  StateVar& s = state_of(statevar);
  s.next = next;
  s.has_next = true;
}

void TransitionSystem::check_complete() const {
  std::string no_init, no_next;
  for (const auto& s : states_) {
    if (!s.has_init) no_init += (no_init.empty() ? "" : ", ") + s.name;
    if (!s.has_next) no_next += (no_next.empty() ? "" : ", ") + s.name;
  }
  if (no_init.empty() && no_next.empty()) return;
  std::string what = "incomplete transition system:";
  if (!no_init.empty()) what += " state variables without an initial value: " + no_init + ";";
  if (!no_next.empty()) what += " state variables without a next-state function: " + no_next + ";";
  what.pop_back();
  throw std::logic_error(what);
}

void TransitionSystem::add_constraint(const std::string& name, const z3::expr& c) {
  constraints_.push_back(Named{name, c});
}

void TransitionSystem::name_term(const std::string& name, const z3::expr& term) {
  auto it = term_index_.find(name);
  if (it != term_index_.end()) {
    terms_[it->second].term = term;
    return;
  }
  term_index_.emplace(name, terms_.size());
  terms_.push_back(Named{name, term});
}

void TransitionSystem::add_lemma(const std::string& name, const z3::expr& lemma) {
  lemmas_.push_back(Named{name, lemma});
}

std::optional<z3::expr> TransitionSystem::term(const std::string& name) const {
  auto it = term_index_.find(name);
  if (it == term_index_.end()) return std::nullopt;
  return terms_[it->second].term;
}

std::optional<z3::expr> TransitionSystem::statevar(const std::string& name) const {
  for (const auto& s : states_)
    if (s.name == name) return s.var;
  return std::nullopt;
}

std::optional<z3::expr> TransitionSystem::inputvar(const std::string& name) const {
  for (const auto& i : inputs_)
    if (i.name == name) return i.var;
  return std::nullopt;
}

bool TransitionSystem::is_statevar(const z3::expr& e) const { return state_index_.count(e.id()) > 0; }
bool TransitionSystem::is_inputvar(const z3::expr& e) const { return input_index_.count(e.id()) > 0; }

z3::expr TransitionSystem::init_formula() const {
  z3::expr_vector parts(*ctx_);
  for (const auto& s : states_) parts.push_back(s.var == s.init);
  return parts.empty() ? ctx_->bool_val(true) : z3::mk_and(parts);
}

z3::expr TransitionSystem::trans_formula() const {
  z3::expr_vector parts(*ctx_);
  for (const auto& s : states_) parts.push_back(s.next_var == s.next);
  return parts.empty() ? ctx_->bool_val(true) : z3::mk_and(parts);
}

z3::expr TransitionSystem::constraint_formula() const {
  z3::expr_vector parts(*ctx_);
  for (const auto& c : constraints_) parts.push_back(c.term);
  return parts.empty() ? ctx_->bool_val(true) : z3::mk_and(parts);
}

z3::expr TransitionSystem::float_const(float v) const {
  z3::expr e = ctx_->fpa_val(v);
  if (float_values_.emplace(e.id(), v).second) float_terms_.push_back(e);
  return e;
}

std::optional<float> TransitionSystem::float_value(unsigned ast_id) const {
  auto it = float_values_.find(ast_id);
  if (it == float_values_.end()) return std::nullopt;
  return it->second;
}

z3::expr TransitionSystem::rne() const {
  return z3::expr(*ctx_, Z3_mk_fpa_rne(*ctx_));
}

}  // namespace cemv::encoder
