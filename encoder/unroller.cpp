#include "encoder/unroller.hpp"

#include <unordered_set>

namespace cemv::encoder {

Unroller::Unroller(const TransitionSystem& ts) : ts_(ts), from_(ts.ctx()) {
  for (const auto& s : ts.statevars()) from_.push_back(s.var);
  for (const auto& i : ts.inputvars()) from_.push_back(i.var);
  for (const auto& s : ts.statevars()) from_.push_back(s.next_var);
  for (unsigned i = 0; i < from_.size(); ++i) position_.emplace(from_[i].id(), i);
}

const std::vector<z3::expr>& Unroller::vars_at(int k) {
  auto it = copies_.find(k);
  if (it != copies_.end()) return it->second;
  std::vector<z3::expr> copy;
  std::string suffix(1, '@');
  suffix.append(std::to_string(k));
  auto named = [&](const std::string& base) {
    std::string n;
    n.reserve(base.size() + suffix.size());
    n.append(base).append(suffix);
    return n;
  };
  for (const auto& s : ts_.statevars())
    copy.push_back(ts_.ctx().constant(named(s.name).c_str(), s.var.get_sort()));
  for (const auto& i : ts_.inputvars())
    copy.push_back(ts_.ctx().constant(named(i.name).c_str(), i.var.get_sort()));
  return copies_.emplace(k, std::move(copy)).first->second;
}

z3::expr Unroller::at(const z3::expr& e, int k) {
  const auto& now = vars_at(k);
  const auto& later = vars_at(k + 1);
  const std::size_t n_states = ts_.statevars().size();
  const std::size_t current = n_states + ts_.inputvars().size();
  // Only the variables `e` contains are substituted: a substitution builds
  // its map from every pair it is given, so an invariant candidate over two
  // variables of a wide cone cost as much as the whole transition relation.
  z3::expr_vector from(ts_.ctx()), to(ts_.ctx());
  std::unordered_set<unsigned> seen;
  std::vector<z3::expr> todo{e};
  while (!todo.empty()) {
    const z3::expr x = todo.back();
    todo.pop_back();
    if (!seen.insert(x.id()).second) continue;
    if (x.is_quantifier()) return at_every_variable(e, k);
    if (!x.is_app()) continue;
    const unsigned n = x.num_args();
    if (n == 0) {
      auto it = position_.find(x.id());
      if (it == position_.end()) continue;
      from.push_back(x);
      to.push_back(it->second < current ? now[it->second] : later[it->second - current]);
      continue;
    }
    for (unsigned i = 0; i < n; ++i) todo.push_back(x.arg(i));
  }
  // Substituted even when `e` has no variable: Z3 keeps the last term an
  // API call made, so skipping the call changes when terms are freed, which
  // term ids are reused, and with them the solvers' work counts in reports.
  z3::expr copy = e;
  return copy.substitute(from, to);
}

z3::expr Unroller::at_every_variable(const z3::expr& e, int k) {
  const auto& now = vars_at(k);
  const auto& later = vars_at(k + 1);
  z3::expr_vector to(ts_.ctx());
  for (const auto& v : now) to.push_back(v);
  std::size_t n_states = ts_.statevars().size();
  for (std::size_t i = 0; i < n_states; ++i) to.push_back(later[i]);
  z3::expr copy = e;
  return copy.substitute(from_, to);
}

z3::expr Unroller::var_at(const z3::expr& var, int k) {
  auto it = var.is_const() ? position_.find(var.id()) : position_.end();
  if (it == position_.end()) return at(var, k);
  // from_ holds the state vars, the input vars, then the next vars: a next
  // var at k is its state var at k + 1.
  const std::size_t current = ts_.statevars().size() + ts_.inputvars().size();
  if (it->second < current) return vars_at(k)[it->second];
  return vars_at(k + 1)[it->second - current];
}

z3::expr Unroller::path(int depth) {
  z3::expr_vector parts(ts_.ctx());
  parts.push_back(at(ts_.init_formula(), 0));
  z3::expr trans = ts_.trans_formula() && ts_.constraint_formula();
  for (int k = 0; k < depth; ++k) parts.push_back(at(trans, k));
  return z3::mk_and(parts);
}

}  // namespace cemv::encoder
