#include "checker/translate.hpp"

#include <memory>

namespace cemv::checker {

OwnedProblem translate(const SafetyProblem& p, z3::context& to, std::vector<z3::expr>* terms) {
  const encoder::TransitionSystem& from = *p.ts;
  z3::context& src = from.ctx();
  // One vector, translated in one call: the terms share their subterms, and
  // one translation copies each of them once.
  z3::expr_vector all(src);
  for (const auto& s : from.statevars()) {
    all.push_back(s.var);
    all.push_back(s.init);
    all.push_back(s.next);
  }
  for (const auto& i : from.inputvars()) all.push_back(i.var);
  for (const auto& c : from.constraints()) all.push_back(c.term);
  for (const auto& t : from.named_terms()) all.push_back(t.term);
  for (const auto& l : from.lemmas()) all.push_back(l.term);
  all.push_back(p.good);
  all.push_back(p.assumption);
  if (terms)
    for (const auto& t : *terms) all.push_back(t);
  const z3::expr_vector copy(to, Z3_ast_vector_translate(src, all, to));
  auto ts = std::make_shared<encoder::TransitionSystem>(to);
  unsigned n = 0;
  for (const auto& s : from.statevars()) {
    const z3::expr var = ts->make_statevar(s.name, copy[n].get_sort());
    ts->set_init(var, copy[n + 1]);
    ts->assign_next(var, copy[n + 2]);
    n += 3;
  }
  for (const auto& i : from.inputvars()) ts->make_inputvar(i.name, copy[n++].get_sort());
  for (const auto& c : from.constraints()) ts->add_constraint(c.name, copy[n++]);
  for (const auto& t : from.named_terms()) ts->name_term(t.name, copy[n++]);
  for (const auto& l : from.lemmas()) ts->add_lemma(l.name, copy[n++]);
  const z3::expr good = copy[n++];
  const z3::expr assumption = copy[n++];
  if (terms)
    for (auto& t : *terms) t = copy[n++];
  SafetyProblem out{ts.get(), good, assumption};
  return OwnedProblem{ts, out};
}

}  // namespace cemv::checker
