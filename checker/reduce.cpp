#include "checker/reduce.hpp"
#include "checker/reduce_terms.hpp"

#include <bit>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"

namespace cemv::checker {

std::int64_t float_key(float f) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
  const std::int64_t magnitude = bits & 0x7fffffffu;
  return (bits & 0x80000000u) ? -magnitude : magnitude;
}

float key_float(std::int64_t key) {
  const std::uint32_t magnitude = static_cast<std::uint32_t>(key < 0 ? -key : key);
  return std::bit_cast<float>(key < 0 ? (0x80000000u | magnitude) : magnitude);
}

namespace {

using z3::expr;
using namespace reduce_terms;

// What the reduced problem owns: the original (whose context and encoding
// the terms live in) and the new transition system.
struct Reduced {
  std::shared_ptr<void> original;
  encoder::TransitionSystem ts;
};

// The problem's parts as the reductions rewrite them.
struct Parts {
  struct State {
    std::string name;
    expr var, init, next;
  };
  struct Fact {
    std::string name;  // "" for a conjunct of the assumption, else a constraint's name
    expr term;
  };
  std::vector<State> states;
  std::vector<expr> inputs;
  std::vector<std::string> input_names;
  std::vector<Fact> facts;
  std::vector<std::pair<std::string, expr>> lemmas;
  expr good;
  // Further terms the caller asks about (the goods and antecedents of a cone
  // group's members), reduced with `good` and kept in the cone.
  std::vector<expr> extra;
};

Parts parts_of(const SafetyProblem& p) {
  const auto& ts = *p.ts;
  Parts w{{}, {}, {}, {}, {}, p.good, {}};
  for (const auto& sv : ts.statevars()) w.states.push_back({sv.name, sv.var, sv.init, sv.next});
  for (const auto& in : ts.inputvars()) {
    w.inputs.push_back(in.var);
    w.input_names.push_back(in.name);
  }
  std::vector<expr> parts;
  conjuncts(p.assumption, parts);
  for (auto& a : parts) w.facts.push_back({"", a});
  for (const auto& c : ts.constraints()) w.facts.push_back({c.name, c.term});
  for (const auto& l : ts.lemmas()) w.lemmas.emplace_back(l.name, l.term);
  return w;
}

// The terms as the arguments of one application of a fresh function: one
// substitute() or simplify() over it shares Z3's cache across all of them.
// The terms of a cone share most of their DAG, so a call per term was
// quadratic in the cone.
expr bundle(z3::context& c, const char* name, const z3::expr_vector& terms) {
  z3::sort_vector domain(c);
  for (unsigned i = 0; i < terms.size(); ++i) domain.push_back(terms[i].get_sort());
  return c.function(name, domain, c.bool_sort())(terms);
}

void substitute(Parts& w, const z3::expr_vector& from, const z3::expr_vector& to) {
  if (from.empty()) return;
  std::vector<expr*> terms;
  for (auto& s : w.states) terms.push_back(&s.init), terms.push_back(&s.next);
  for (auto& f : w.facts) terms.push_back(&f.term);
  for (auto& l : w.lemmas) terms.push_back(&l.second);
  terms.push_back(&w.good);
  for (auto& e : w.extra) terms.push_back(&e);
  z3::context& c = w.good.ctx();
  z3::expr_vector args(c);
  for (expr* t : terms) args.push_back(*t);
  const expr replaced = bundle(c, "cemv.reduce.terms", args).substitute(from, to);
  FoldBooleans fold;
  for (std::size_t i = 0; i < terms.size(); ++i) *terms[i] = fold(replaced.arg(static_cast<unsigned>(i)));
}

// The literals of Boolean inputs that the assumption fixes in every cycle
// (`assume not issued(simulate_tag)` fixes each simulate command to FALSE).
void forced_literals(const expr& e, bool positive, const std::unordered_set<unsigned>& inputs,
                     std::vector<std::pair<expr, bool>>& out) {
  if (!e.is_app()) return;
  const Z3_decl_kind k = e.decl().decl_kind();
  if (is_variable(e) && e.is_bool() && inputs.count(e.id())) out.emplace_back(e, positive);
  else if (k == Z3_OP_NOT) forced_literals(e.arg(0), !positive, inputs, out);
  else if ((k == Z3_OP_AND && positive) || (k == Z3_OP_OR && !positive))
    for (unsigned i = 0; i < e.num_args(); ++i) forced_literals(e.arg(i), positive, inputs, out);
}

}  // namespace

std::vector<std::pair<std::string, bool>> forced_inputs(const SafetyProblem& p) {
  std::unordered_set<unsigned> inputs;
  for (const auto& in : p.ts->inputvars()) inputs.insert(in.var.id());
  std::vector<std::pair<expr, bool>> literals;
  forced_literals(p.assumption, true, inputs, literals);
  std::vector<std::pair<std::string, bool>> out;
  std::unordered_map<unsigned, bool> seen;
  for (auto& [var, value] : literals) {
    auto [it, fresh] = seen.emplace(var.id(), value);
    if (!fresh) {
      if (it->second != value) return {};  // contradictory: leave the problem as it is
      continue;
    }
    out.emplace_back(var.decl().name().str(), value);
  }
  return out;
}

namespace {

// Reduction 0 (propagation): inputs the assumption fixes become constants,
// and so does every state variable whose next-state function, with those
// constants, gives back its initial value: by induction it never changes. The
// greatest such set is found by dropping the variables that do change until
// none does (sequential constant propagation).
void propagate_constants(Parts& w, const SafetyProblem& p) {
  z3::context& c = p.ts->ctx();
  z3::expr_vector from(c), to(c);
  // The inputs by name, once: a name compared per (forced input, input) pair
  // was quadratic, 450,000 name reads for one big_matrix probe.
  std::unordered_map<std::string, std::vector<std::size_t>> by_name;
  for (std::size_t i = 0; i < w.inputs.size(); ++i) by_name[w.inputs[i].decl().name().str()].push_back(i);
  for (auto& [name, value] : forced_inputs(p))
    if (auto it = by_name.find(name); it != by_name.end())
      for (std::size_t i : it->second) {
        from.push_back(w.inputs[i]);
        to.push_back(c.bool_val(value));
      }
  substitute(w, from, to);
  std::vector<bool> constant(w.states.size());
  for (std::size_t i = 0; i < w.states.size(); ++i) constant[i] = variables_of(w.states[i].init).empty();
  // Simplified once: each simplify() sets up Z3's rewriter anew.
  std::vector<expr> inits;
  for (std::size_t i = 0; i < w.states.size(); ++i) inits.push_back(constant[i] ? w.states[i].init.simplify() : w.states[i].init);
  for (bool changed = true; changed;) {
    changed = false;
    z3::expr_vector sf(c), st(c);
    for (std::size_t i = 0; i < w.states.size(); ++i)
      if (constant[i]) sf.push_back(w.states[i].var), st.push_back(w.states[i].init);
    // The candidates' next-state functions, substituted in one call.
    std::vector<std::size_t> candidates;
    z3::expr_vector nexts(c);
    for (std::size_t i = 0; i < w.states.size(); ++i)
      if (constant[i]) candidates.push_back(i), nexts.push_back(w.states[i].next);
    if (candidates.empty()) break;
    expr all = bundle(c, "cemv.reduce.next", nexts);
    if (!sf.empty()) all = all.substitute(sf, st).simplify();
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      const std::size_t i = candidates[k];
      expr n = sf.empty() ? w.states[i].next : all.arg(static_cast<unsigned>(k));
      if (!z3::eq(n, inits[i])) {
        constant[i] = false;
        changed = true;
      }
    }
  }
  z3::expr_vector sf(c), st(c);
  std::vector<Parts::State> kept;
  for (std::size_t i = 0; i < w.states.size(); ++i) {
    if (constant[i]) sf.push_back(w.states[i].var), st.push_back(w.states[i].init);
    else kept.push_back(w.states[i]);
  }
  w.states = std::move(kept);
  substitute(w, sf, st);
}

// Reduction 1: the variables `good` reaches through next-state and initial
// functions, and through every fact (assumption conjunct or constraint) that
// reads one of them or any state variable. What is left out are input-only
// facts over inputs nothing kept reads: they are dropped when, together, they
// are satisfiable (each cycle can then meet them independently); otherwise
// nothing is dropped.
// Whether every term is true when every variable is zero, FALSE or +0.0
// (what model completion gives an empty model).
bool hold_at_zero(const std::vector<expr>& terms, z3::context& c) {
  z3::model zero(c);
  for (const auto& t : terms)
    if (!zero.eval(t, true).is_true()) return false;
  return true;
}

void cone_of_influence(Parts& w, z3::context& c) {
  std::unordered_map<unsigned, std::size_t> state_of, input_of;
  for (std::size_t i = 0; i < w.states.size(); ++i) state_of[w.states[i].var.id()] = i;
  for (std::size_t i = 0; i < w.inputs.size(); ++i) input_of[w.inputs[i].id()] = i;
  std::vector<std::unordered_set<unsigned>> fact_vars;
  for (const auto& f : w.facts) fact_vars.push_back(variables_of(f.term));
  std::vector<bool> state(w.states.size()), input(w.inputs.size()), fact(w.facts.size());
  std::vector<unsigned> work;
  auto add = [&](unsigned var) {
    if (auto s = state_of.find(var); s != state_of.end() && !state[s->second]) {
      state[s->second] = true;
      work.push_back(var);
    } else if (auto i = input_of.find(var); i != input_of.end() && !input[i->second]) {
      input[i->second] = true;
    }
  };
  auto kept = [&](unsigned v) {
    auto s = state_of.find(v);
    if (s != state_of.end()) return true;  // any state variable keeps its fact
    auto i = input_of.find(v);
    return i != input_of.end() && input[i->second];
  };
  // One walk over the term DAG for the whole cone: next-state functions share
  // most of their terms (an effect reads every cause linked to it), and a walk
  // per state variable was quadratic in the cone (a third of a cemv response
  // probe's CPU on big_matrix).
  std::unordered_set<unsigned> seen_terms;
  auto reach = [&](const expr& t) {
    std::unordered_set<unsigned> vars;
    collect_variables(t, vars, seen_terms);
    for (unsigned v : vars) add(v);
  };
  reach(w.good);
  for (const auto& e : w.extra) reach(e);
  for (bool more = true; more;) {
    while (!work.empty()) {
      unsigned v = work.back();
      work.pop_back();
      const auto& sv = w.states[state_of[v]];
      reach(sv.next);
      reach(sv.init);
    }
    more = false;
    for (std::size_t f = 0; f < w.facts.size(); ++f) {
      if (fact[f]) continue;
      for (unsigned v : fact_vars[f]) fact[f] = fact[f] || kept(v);
      if (fact[f]) {
        more = true;
        for (unsigned v : fact_vars[f]) add(v);
      }
    }
  }
  // Dropping facts is exact only if they can all hold (over inputs alone, in
  // any cycle). They are mostly ranges that the plant at rest meets: try the
  // all-zero assignment first, and ask a solver only when it fails them.
  std::vector<expr> dropped_facts;
  for (std::size_t f = 0; f < w.facts.size(); ++f)
    if (!fact[f]) dropped_facts.push_back(w.facts[f].term);
  if (!hold_at_zero(dropped_facts, c)) {
    z3::solver dropped(c);
    for (const auto& f : dropped_facts) dropped.add(f);
    if (dropped.check() != z3::sat) return;
  }
  Parts out{{}, {}, {}, {}, {}, w.good, w.extra};
  for (std::size_t i = 0; i < w.states.size(); ++i)
    if (state[i]) out.states.push_back(w.states[i]);
  for (std::size_t i = 0; i < w.inputs.size(); ++i)
    if (input[i]) out.inputs.push_back(w.inputs[i]), out.input_names.push_back(w.input_names[i]);
  for (std::size_t f = 0; f < w.facts.size(); ++f)
    if (fact[f]) out.facts.push_back(w.facts[f]);
  std::unordered_set<unsigned> kept_states;
  for (const auto& s : out.states) kept_states.insert(s.var.id());
  for (const auto& l : w.lemmas) {
    bool inside = true;
    for (unsigned v : variables_of(l.second)) inside = inside && kept_states.count(v);
    if (inside) out.lemmas.push_back(l);
  }
  w = std::move(out);
}

// The transition system of what is left, floats as integers or as they are.
OwnedProblem build(const Parts& w, const std::shared_ptr<void>& original, z3::context& c, bool as_integers,
                   std::vector<expr>& extra) {
  auto owner = std::make_shared<Reduced>(Reduced{original, encoder::TransitionSystem(c)});
  encoder::TransitionSystem& r = owner->ts;
  FloatsAsIntegers rewrite(c);
  FloatConstants constants(r);
  auto map = [&](const expr& e) { return as_integers ? rewrite(e) : constants(e); };
  const expr max_key = c.int_val(float_key(std::numeric_limits<float>::max()));
  for (std::size_t i = 0; i < w.inputs.size(); ++i) {
    const bool to_int = as_integers && w.inputs[i].is_fpa();
    expr v = r.make_inputvar(w.input_names[i], to_int ? c.int_sort() : w.inputs[i].get_sort());
    if (to_int) {
      rewrite.map_variable(w.inputs[i], v);
      r.add_constraint(w.input_names[i] + ".finite", v >= -max_key && v <= max_key);
    }
  }
  std::vector<expr> vars;
  for (const auto& s : w.states) {
    const bool to_int = as_integers && s.var.is_fpa();
    expr v = r.make_statevar(s.name, to_int ? c.int_sort() : s.var.get_sort());
    if (to_int) rewrite.map_variable(s.var, v);
    vars.push_back(v);
  }
  for (std::size_t i = 0; i < w.states.size(); ++i) {
    r.set_init(vars[i], map(w.states[i].init));
    r.assign_next(vars[i], map(w.states[i].next));
    if (as_integers && w.states[i].var.is_fpa())
      r.add_lemma(w.states[i].name + ".finite", vars[i] >= -max_key && vars[i] <= max_key);
  }
  expr assumption = c.bool_val(true);
  for (const auto& f : w.facts) {
    expr t = map(f.term);
    if (t.simplify().is_true()) continue;  // a float's not-NaN: no integer is NaN
    if (f.name.empty()) assumption = assumption && t;
    else r.add_constraint(f.name, t);
  }
  for (const auto& [name, term] : w.lemmas) {
    try {
      r.add_lemma(name, map(term));
    } catch (const Unsupported&) {
      // A lemma the integers cannot state is left out: lemmas only help.
    }
  }
  expr good = map(w.good);
  extra.clear();
  for (const auto& e : w.extra) extra.push_back(map(e));
  r.check_complete();
  return OwnedProblem{owner, SafetyProblem{&owner->ts, good, assumption}};
}

}  // namespace

OwnedProblem reduce(const OwnedProblem& original, Reduction* what) {
  std::vector<expr> none;
  return reduce_with(original, none, what);
}

OwnedProblem reduce_with(const OwnedProblem& original, std::vector<z3::expr>& terms, Reduction* what) {
  const SafetyProblem& p = original.problem;
  z3::context& c = p.ts->ctx();
  Parts w = parts_of(p);
  w.extra = terms;
  propagate_constants(w, p);
  cone_of_influence(w, c);
  bool as_integers = true;
  std::optional<OwnedProblem> built;
  try {
    built = build(w, original.owner, c, true, terms);
  } catch (const Unsupported&) {
    as_integers = false;
    built = build(w, original.owner, c, false, terms);
  }
  OwnedProblem out = std::move(*built);
  if (what) {
    what->state_vars_before = p.ts->statevars().size();
    what->inputs_before = p.ts->inputvars().size();
    what->state_vars_after = out.problem.ts->statevars().size();
    what->inputs_after = out.problem.ts->inputvars().size();
    what->floats_as_integers = as_integers;
  }
  return out;
}

ProblemFactory reducing(ProblemFactory make) {
  return [make = std::move(make)](z3::context& ctx) { return reduce(make(ctx)); };
}

Trace lift_trace(const SafetyProblem& original, const Trace& reduced) {
  const auto& ts = *original.ts;
  std::unordered_map<std::string, std::size_t> position;
  for (std::size_t i = 0; i < reduced.input_names.size(); ++i) position[reduced.input_names[i]] = i;
  std::unordered_map<std::string, bool> forced;
  for (auto& [name, value] : forced_inputs(original)) forced[name] = value;
  Trace out;
  for (const auto& in : ts.inputvars()) out.input_names.push_back(in.name);
  const bool states = static_cast<std::int64_t>(reduced.cycles.size()) <= kMaxTraceStateCycles;
  if (states)
    for (const auto& sv : ts.statevars()) out.state_names.push_back(sv.name);
  encoder::Encoding enc(ts.ctx());
  enc.ts = ts;
  encoder::Evaluator ev(enc);
  out.cycles.reserve(reduced.cycles.size());
  for (const auto& cycle : reduced.cycles) {
    Trace::Cycle lifted;
    std::vector<encoder::Evaluator::Value> raw;
    for (const auto& in : ts.inputvars()) {
      Value v;
      v.is_float = in.var.is_fpa();
      if (auto it = position.find(in.name); it != position.end()) {
        const Value& r = cycle.inputs[it->second];
        if (v.is_float) v.f = r.is_float ? r.f : key_float(r.i);
        else v.i = r.i;
      } else if (auto f = forced.find(in.name); f != forced.end()) {
        v.i = f->second ? 1 : 0;
      }
      lifted.inputs.push_back(v);
      raw.push_back(encoder::Evaluator::Value{v.i, v.f});
    }
    if (states)
      for (std::size_t s = 0; s < ts.statevars().size(); ++s)
        lifted.state.push_back(Value{ts.statevars()[s].var.is_fpa(), ev.state()[s].i, ev.state()[s].f});
    ev.step_raw(raw);
    out.cycles.push_back(std::move(lifted));
  }
  return out;
}

}  // namespace cemv::checker
