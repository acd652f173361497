// Cones of a product's outputs and their groups (cones.hpp).
#include "plc_check/cones.hpp"

#include <algorithm>
#include <bit>
#include <map>
#include <set>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include "checker/engines/solving.hpp"

namespace cemv::plc_check {

TermReads::TermReads(const encoder::TransitionSystem& ts, bool inputs) {
  if (inputs)
    for (std::size_t i = 0; i < ts.inputvars().size(); ++i) index_.emplace(ts.inputvars()[i].var.id(), i);
  else
    for (std::size_t i = 0; i < ts.statevars().size(); ++i) index_.emplace(ts.statevars()[i].var.id(), i);
}

std::vector<std::size_t> TermReads::of(const z3::expr& e) {
  seen_.clear();
  std::vector<std::size_t> out;
  std::vector<z3::expr> todo{e};
  while (!todo.empty()) {
    const z3::expr t = todo.back();
    todo.pop_back();
    if (!seen_.insert(t.id()).second) continue;
    if (const auto it = index_.find(t.id()); it != index_.end()) out.push_back(it->second);
    if (t.is_app())
      for (unsigned i = 0; i < t.num_args(); ++i) todo.push_back(t.arg(i));
  }
  return out;
}

namespace {

// A closed term: no variable (an initial value that is a constant).
bool variables_free(const z3::expr& e) {
  if (e.is_const() && !e.is_numeral() && !e.is_true() && !e.is_false()) return false;
  for (unsigned i = 0; e.is_app() && i < e.num_args(); ++i)
    if (!variables_free(e.arg(i))) return false;
  return true;
}

// What each state variable's next-state and initial functions read; with
// `constants`, after each of those is replaced by its initial value.
std::vector<std::vector<std::size_t>> direct_reads(const encoder::TransitionSystem& ts, bool inputs,
                                                   const std::vector<std::size_t>& constants = {}) {
  TermReads reads(ts, inputs);
  z3::expr_vector from(ts.ctx()), to(ts.ctx());
  for (std::size_t c : constants) {
    from.push_back(ts.statevars()[c].var);
    to.push_back(ts.statevars()[c].init);
  }
  std::vector<std::vector<std::size_t>> out(ts.statevars().size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    z3::expr next = ts.statevars()[i].next;
    if (!from.empty()) next = next.substitute(from, to).simplify();
    out[i] = reads.of(next);
    const auto init = reads.of(ts.statevars()[i].init);
    out[i].insert(out[i].end(), init.begin(), init.end());
  }
  return out;
}

// The state variables `todo` holds and those they reach through what each
// reads (`reads`, by state variable).
std::set<std::size_t> reached(const std::vector<std::vector<std::size_t>>& reads, std::vector<std::size_t> todo) {
  std::set<std::size_t> out;
  while (!todo.empty()) {
    const std::size_t v = todo.back();
    todo.pop_back();
    if (!out.insert(v).second) continue;
    for (std::size_t w : reads[v])
      if (!out.count(w)) todo.push_back(w);
  }
  return out;
}

}  // namespace

std::vector<std::vector<std::size_t>> cones_of(const encoder::TransitionSystem& ts, const std::vector<z3::expr>& terms) {
  TermReads reads(ts);
  const std::vector<std::vector<std::size_t>> next_reads = direct_reads(ts, false);
  std::vector<std::vector<std::size_t>> out;
  for (const auto& t : terms) {
    const std::set<std::size_t> cone = reached(next_reads, reads.of(t));
    out.emplace_back(cone.begin(), cone.end());
  }
  return out;
}

std::vector<Layer> layers_of(const encoder::TransitionSystem& ts, const std::vector<std::vector<std::size_t>>& cones,
                             const Supports& supports) {
  const std::vector<std::vector<std::size_t>> reads = direct_reads(ts, false);
  // The variables that depend on no input (the first scan's flags) may guard
  // a relation of any layer (Supports::may_guard): each layer holds them.
  std::set<std::size_t> inputless;
  for (const auto& cone : cones)
    for (std::size_t v : cone) {
      const auto in = supports.inputs_of(v);
      if (std::all_of(in.begin(), in.end(), [](std::uint64_t w) { return w == 0; })) inputless.insert(v);
    }
  std::map<std::vector<std::size_t>, std::pair<std::size_t, Layer>> distinct;  // by top: inputs, layer
  for (const auto& cone : cones) {
    std::map<std::vector<std::uint64_t>, std::vector<std::size_t>> by_inputs;
    for (std::size_t v : cone) by_inputs[supports.inputs_of(v)].push_back(v);
    for (const auto& [inputs, top] : by_inputs) {
      std::set<std::size_t> vars = reached(reads, top), near(top.begin(), top.end());
      for (std::size_t v : top) near.insert(reads[v].begin(), reads[v].end());
      near.insert(inputless.begin(), inputless.end());
      vars.insert(inputless.begin(), inputless.end());
      std::size_t n = 0;
      for (std::uint64_t w : inputs) n += static_cast<std::size_t>(std::popcount(w));
      distinct.emplace(top, std::make_pair(n, Layer{top, {vars.begin(), vars.end()}, {near.begin(), near.end()}}));
    }
  }
  std::vector<std::pair<std::size_t, Layer>> order;
  for (auto& [top, nl] : distinct) order.push_back(std::move(nl));
  std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first < b.first : a.second.vars.size() < b.second.vars.size();
  });
  std::vector<Layer> out;
  for (auto& [n, l] : order) out.push_back(std::move(l));
  return out;
}

std::vector<std::vector<std::size_t>> overlapping(const std::vector<std::vector<std::size_t>>& cones) {
  std::vector<std::size_t> parent(cones.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::unordered_map<std::size_t, std::size_t> owner;  // state variable -> the first cone holding it
  for (std::size_t c = 0; c < cones.size(); ++c)
    for (std::size_t v : cones[c]) {
      const auto [it, fresh] = owner.emplace(v, c);
      if (fresh) continue;
      const std::size_t a = root(it->second), b = root(c);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  std::vector<std::vector<std::size_t>> groups;
  std::unordered_map<std::size_t, std::size_t> group_of_root;
  for (std::size_t c = 0; c < cones.size(); ++c) {
    const auto [it, fresh] = group_of_root.emplace(root(c), groups.size());
    if (fresh) groups.emplace_back();
    groups[it->second].push_back(c);
  }
  return groups;
}

std::vector<std::size_t> constant_states(const checker::SafetyProblem& p, const Samples& samples,
                                         const checker::Limits& limits, checker::WorkMeter& meter) {
  const auto& ts = *p.ts;
  std::vector<std::size_t> out;
  std::vector<char> unchanged = samples.unchanged;
  if (unchanged.empty() && !samples.states.empty()) {
    const auto& first = samples.states.front();  // the initial state
    unchanged.assign(ts.statevars().size(), 1);
    for (const auto& s : samples.states)
      for (std::size_t v = 0; v < s.size(); ++v)
        if (s[v].i != first[v].i) unchanged[v] = 0;
  }
  if (unchanged.empty()) return out;
  // One solver holds the constraints; each variable's question is pushed and
  // popped (a big product's constraints asserted once, not once a variable).
  z3::solver s(ts.ctx());
  s.add(ts.constraint_formula() && p.assumption);
  for (std::size_t v = 0; v < ts.statevars().size(); ++v) {
    const auto& sv = ts.statevars()[v];
    if (sv.var.is_fpa() || !variables_free(sv.init) || !unchanged[v]) continue;
    s.push();
    s.add(sv.next != sv.init);
    const z3::check_result r = checker::check_within(s, meter);
    if (r == z3::unknown) throw checker::Stopped{checker::unknown_reason(s.reason_unknown(), limits, meter)};
    s.pop();
    if (r == z3::unsat) out.push_back(v);
  }
  return out;
}

Supports::Supports(const encoder::TransitionSystem& ts, const std::vector<std::size_t>& constants) {
  const std::size_t n = ts.statevars().size();
  words_ = (ts.inputvars().size() + 63) / 64;
  bits_.assign(n * words_, 0);
  const auto inputs = direct_reads(ts, true, constants), states = direct_reads(ts, false, constants);
  for (std::size_t v = 0; v < n; ++v)
    for (std::size_t i : inputs[v]) bits_[v * words_ + i / 64] |= std::uint64_t{1} << (i % 64);
  // The closure over the state variables read, to a fixed point.
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t v = 0; v < n; ++v)
      for (std::size_t w : states[v])
        for (std::size_t k = 0; k < words_; ++k) {
          const std::uint64_t before = bits_[v * words_ + k];
          bits_[v * words_ + k] |= bits_[w * words_ + k];
          changed = changed || bits_[v * words_ + k] != before;
        }
  }
}

bool Supports::related(std::size_t x, std::size_t y, bool same) const {
  const std::uint64_t *a = of(x), *b = of(y);
  bool a_in_b = true, b_in_a = true;
  for (std::size_t k = 0; k < words_; ++k) {
    a_in_b = a_in_b && (a[k] & ~b[k]) == 0;
    b_in_a = b_in_a && (b[k] & ~a[k]) == 0;
  }
  return same ? a_in_b && b_in_a : a_in_b || b_in_a;
}

bool Supports::may_guard(std::size_t g, std::size_t x, std::size_t y) const {
  const std::uint64_t *s = of(g), *a = of(x), *b = y == SIZE_MAX ? nullptr : of(y);
  bool none = true, same = true;
  for (std::size_t k = 0; k < words_; ++k) {
    none = none && s[k] == 0;
    same = same && s[k] == (a[k] | (b ? b[k] : 0));
  }
  return none || same;
}

std::vector<z3::expr> conjuncts_of(const z3::expr& e) {
  std::vector<z3::expr> out;
  std::vector<z3::expr> todo{e};
  while (!todo.empty()) {
    const z3::expr t = todo.back();
    todo.pop_back();
    if (t.is_app() && t.decl().decl_kind() == Z3_OP_AND) {
      for (unsigned i = t.num_args(); i-- > 0;) todo.push_back(t.arg(i));
    } else {
      out.push_back(t);
    }
  }
  return out;
}

}  // namespace cemv::plc_check
