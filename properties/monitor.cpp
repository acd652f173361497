// The symbolic monitor (docs/properties.md, "The symbolic monitor"): every
// operator below cites the cycle semantics of properties/ast.hpp it encodes.
#include "properties/monitor.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

#include "model/node.hpp"
#include "properties/monitor_commands.hpp"
#include "model/vocabulary.hpp"

namespace cemv::properties {

namespace {

using z3::expr;
using monitor_commands::add_free_command;
using monitor_commands::candidate_commands;
using monitor_commands::matches;

class MonitorBuilder {
 public:
  explicit MonitorBuilder(encoder::Encoding& enc)
      : enc_(enc), ts_(enc.ts), c_(enc.ts.ctx()) {
    for (const auto& s : ts_.statevars())
      if (s.name.rfind("monitor.", 0) == 0) ++serial_;
  }

  expr compile(const Expr& e);
  expr response_violation(const expr& trigger, const expr& response, int n);
  const std::vector<std::string>& added() const { return added_; }

 private:
  expr B(bool b) { return c_.bool_val(b); }
  expr I(std::int64_t v) { return c_.int_val(v); }

  // A monitor state variable `monitor.<serial>.<what>`; serials count the
  // monitor variables already in the system, so several properties compiled
  // into one encoding never clash.
  expr state(const std::string& what, const z3::sort& sort, const expr& init) {
    std::string name = "monitor." + std::to_string(serial_++) + "." + what;
    expr v = ts_.make_statevar(name, sort);
    ts_.set_init(v, init);
    added_.push_back(name);
    return v;
  }
  // Saturating increment: exact up to `bound`, then stays there (the
  // encoder's timer pattern, docs/encoding.md T.2), so the state space is
  // finite and the counter can be related to the matrix's `*.elapsed`.
  expr sat_inc(const expr& v, int bound) { return z3::ite(v >= bound, I(bound), v + 1); }

  expr observable(const Expr& e);
  expr input_value(std::size_t index);
  expr input_bad(std::size_t index);
  expr issued(const CommandPattern& p);
  expr compare(const Expr& e);
  expr prev(const expr& a);
  expr held(const expr& a, int n);
  expr within(const expr& a, int n);
  expr since(const expr& a, const expr& b);

  encoder::Encoding& enc_;
  encoder::TransitionSystem& ts_;
  z3::context& c_;
  int serial_ = 0;
  std::vector<std::string> added_;
  // One state machine per (operator, bound, operand terms): a subformula
  // used twice (e.g. by rose and fell, or in an assumption and the body)
  // costs one set of state variables.
  std::map<std::string, expr> memo_;
};

std::string memo_key(const char* op, int n, std::initializer_list<expr> args) {
  std::string k = op;
  k += ":" + std::to_string(n);
  for (const auto& a : args) k += ":" + std::to_string(a.id());
  return k;
}

expr MonitorBuilder::observable(const Expr& e) {
  auto t = ts_.term(e.observable.key);
  if (!t)
    throw std::logic_error("monitor: the encoding has no term " + e.observable.key +
                           " (encode the cone of property_roots)");
  return *t;
}

expr MonitorBuilder::input_value(std::size_t index) {
  if (index >= enc_.tag_value.size()) throw std::logic_error("monitor: input index out of range");
  if (!enc_.tag_value[index]) {
    // Not read by the encoded cone: a free input is exact (nothing encoded
    // depends on it). The same name and NaN rule as the encoder's inputs.
    const auto& tag = enc_.inputs.tags()[index];
    bool analog = tag.kind == model::TagKind::Analog;
    expr v = ts_.make_inputvar("input." + tag.name, analog ? c_.fpa_sort(8, 24) : c_.bool_sort());
    if (analog) ts_.add_constraint("input." + tag.name + ".not_nan", !expr(c_, Z3_mk_fpa_is_nan(c_, v)));
    enc_.tag_value[index] = v;
  }
  return *enc_.tag_value[index];
}

expr MonitorBuilder::input_bad(std::size_t index) {
  if (index >= enc_.tag_bad.size()) throw std::logic_error("monitor: input index out of range");
  if (!enc_.tag_bad[index]) {
    // The encoder reads quality only of cause input tags (I.2); any other
    // tag's quality is a free input here.
    const auto& tag = enc_.inputs.tags()[index];
    enc_.tag_bad[index] = ts_.make_inputvar("input." + tag.name + ".bad", c_.bool_sort());
  }
  return *enc_.tag_bad[index];
}

// Issued = some matching command input is set: the raw input, before the
// secure-write gate (M.3), since a command counts as issued whether or not it
// is accepted (docs/properties.md "The symbolic monitor").
expr MonitorBuilder::issued(const CommandPattern& p) {
  for (const auto& c : candidate_commands(enc_, p))
    if (!enc_.find_command(c)) add_free_command(enc_, c);
  z3::expr_vector any(c_);
  for (const auto& ci : enc_.commands)
    if (matches(ci, p)) any.push_back(ci.var);
  if (any.empty()) return B(false);
  return any.size() == 1 ? any[0] : z3::mk_or(any);
}

expr MonitorBuilder::compare(const Expr& e) {
  expr a = compile(e.args.at(0));
  expr b = compile(e.args.at(1));
  if (a.is_fpa() != b.is_fpa() || a.is_bool() != b.is_bool())
    throw std::logic_error("monitor: comparison of different types");
  if (a.is_fpa()) {
    // IEEE single-precision comparisons, as the runtime compares floats.
    switch (e.cmp) {
      case CompareOp::Eq: return expr(c_, Z3_mk_fpa_eq(c_, a, b));
      case CompareOp::Ne: return !expr(c_, Z3_mk_fpa_eq(c_, a, b));
      case CompareOp::Lt: return expr(c_, Z3_mk_fpa_lt(c_, a, b));
      case CompareOp::Le: return expr(c_, Z3_mk_fpa_leq(c_, a, b));
      case CompareOp::Gt: return expr(c_, Z3_mk_fpa_gt(c_, a, b));
      case CompareOp::Ge: return expr(c_, Z3_mk_fpa_geq(c_, a, b));
    }
  }
  if (a.is_bool() && e.cmp != CompareOp::Eq && e.cmp != CompareOp::Ne)
    throw std::logic_error("monitor: ordering of Boolean values");
  // `!(a == b)`, not `a != b`: Z3's distinct is not an operator the encoder's
  // Evaluator interprets.
  switch (e.cmp) {
    case CompareOp::Eq: return a == b;
    case CompareOp::Ne: return !(a == b);
    case CompareOp::Lt: return a < b;
    case CompareOp::Le: return a <= b;
    case CompareOp::Gt: return a > b;
    case CompareOp::Ge: return a >= b;
  }
  throw std::logic_error("monitor: unknown comparison");
}

// Prev: a at k-1; false at k = 0. State: the value of `a` in the previous
// cycle (init false).
expr MonitorBuilder::prev(const expr& a) {
  std::string key = memo_key("prev", 0, {a});
  if (auto it = memo_.find(key); it != memo_.end()) return it->second;
  expr p = state("prev", c_.bool_sort(), B(false));
  ts_.assign_next(p, a);
  return memo_.emplace(key, p).first->second;
}

// Held(a, N): a at every cycle of [k-N, k]; false when k < N. State: the
// number of consecutive cycles before this one in which `a` held, saturating
// at N (init 0). Held now iff `a` now and that count reached N.
expr MonitorBuilder::held(const expr& a, int n) {
  std::string key = memo_key("held", n, {a});
  if (auto it = memo_.find(key); it != memo_.end()) return it->second;
  expr count = state("held", c_.int_sort(), I(0));
  ts_.assign_next(count, z3::ite(a, sat_inc(count, n), I(0)));
  ts_.add_lemma(added_.back() + ".range", count >= 0 && count <= n);
  return memo_.emplace(key, a && count >= n).first->second;
}

// Within(a, N): a at some cycle of [max(0, k-N), k]. State: cycles since `a`
// last held before this cycle, minus one (0: it held in the previous cycle),
// saturating at N, which also stands for "never" (init N). Within now iff `a`
// now or that age is below N (the last occurrence is at most N cycles back).
expr MonitorBuilder::within(const expr& a, int n) {
  std::string key = memo_key("within", n, {a});
  if (auto it = memo_.find(key); it != memo_.end()) return it->second;
  expr age = state("within", c_.int_sort(), I(n));
  ts_.assign_next(age, z3::ite(a, I(0), sat_inc(age, n)));
  ts_.add_lemma(added_.back() + ".range", age >= 0 && age <= n);
  return memo_.emplace(key, a || age < n).first->second;
}

// Since(a, b): exists j <= k with b at j and a at every cycle of (j, k].
// Recursively: b now, or a now and Since held in the previous cycle.
expr MonitorBuilder::since(const expr& a, const expr& b) {
  std::string key = memo_key("since", 0, {a, b});
  if (auto it = memo_.find(key); it != memo_.end()) return it->second;
  expr was = state("since", c_.bool_sort(), B(false));
  expr now = b || (a && was);
  ts_.assign_next(was, now);
  return memo_.emplace(key, now).first->second;
}

// Response "whenever T then R within N": every cycle k with T needs R at some
// cycle of [k, k+N]. It is violated at the first cycle k+N that closes such a
// window without R. Every pending trigger is answered by the same R, and the
// oldest one's window closes first, so one age suffices: `pending` (an
// unanswered trigger from an earlier cycle) and `age` (that trigger's age in
// the previous cycle, saturating at N; 0 when none). Exact up to and
// including the first violation; afterwards it stays violated until an R.
expr MonitorBuilder::response_violation(const expr& trigger, const expr& response, int n) {
  expr pending = state("response.pending", c_.bool_sort(), B(false));
  expr age = state("response.age", c_.int_sort(), I(0));
  ts_.add_lemma(added_.back() + ".range", age >= 0 && age <= n && (pending || age == 0));
  expr open = pending || trigger;                    // some trigger of [k-N', k] unanswered so far
  expr age_now = z3::ite(pending, age + 1, I(0));    // age of the oldest one in this cycle
  expr unanswered = open && !response;
  ts_.assign_next(pending, unanswered);
  ts_.assign_next(age, z3::ite(unanswered, z3::ite(age_now >= n, I(n), age_now), I(0)));
  return unanswered && age_now >= n;
}

expr MonitorBuilder::compile(const Expr& e) {
  auto args = [&](expr (*join)(const z3::expr_vector&), bool empty) {
    if (e.args.empty()) return B(empty);
    if (e.args.size() == 1) return compile(e.args[0]);
    z3::expr_vector v(c_);
    for (const auto& a : e.args) v.push_back(compile(a));
    return join(v);
  };
  switch (e.kind) {
    case Expr::Kind::BoolConst: return B(e.bool_value);
    case Expr::Kind::IntConst: return I(e.int_value);
    case Expr::Kind::FloatConst: return ts_.float_const(e.float_value);
    case Expr::Kind::Observable: return observable(e);
    case Expr::Kind::InputValue: return input_value(e.input);
    case Expr::Kind::InputBad: return input_bad(e.input);
    case Expr::Kind::CommandIssued: return issued(e.command);
    case Expr::Kind::Compare: return compare(e);
    case Expr::Kind::Not: return !compile(e.args.at(0));
    case Expr::Kind::And: return args(z3::mk_and, true);
    case Expr::Kind::Or: return args(z3::mk_or, false);
    case Expr::Kind::Implies: return z3::implies(compile(e.args.at(0)), compile(e.args.at(1)));
    case Expr::Kind::Iff: return compile(e.args.at(0)) == compile(e.args.at(1));
    case Expr::Kind::Count: {
      // One n-ary sum of 0/1 terms (the encoder's Evaluator interprets + and
      // ite): a chain of binary sums over a large aggregate would be as deep
      // as it is long, and everything that walks terms recursively would
      // pay for that depth.
      if (e.args.empty()) return I(0);
      z3::expr_vector terms(c_);
      for (const auto& a : e.args) terms.push_back(z3::ite(compile(a), I(1), I(0)));
      return terms.size() == 1 ? terms[0] : z3::sum(terms);
    }
    case Expr::Kind::Prev: return prev(compile(e.args.at(0)));
    case Expr::Kind::Rose: {
      expr a = compile(e.args.at(0));
      return a && !prev(a);
    }
    case Expr::Kind::Fell: {
      expr a = compile(e.args.at(0));
      return !a && prev(a);
    }
    case Expr::Kind::Held: return held(compile(e.args.at(0)), e.cycles);
    case Expr::Kind::Within: return within(compile(e.args.at(0)), e.cycles);
    case Expr::Kind::Since: return since(compile(e.args.at(0)), compile(e.args.at(1)));
  }
  throw std::logic_error("monitor: unknown expression kind");
}

// ---- Cone of influence ----------------------------------------------------------

// Polarity of a subexpression inside an assumption: whether making it truer
// can only make the assumption truer (Positive), only falser (Negative), or
// either (Both).
enum class Polarity { Positive, Negative, Both };
Polarity flip(Polarity p) {
  return p == Polarity::Positive ? Polarity::Negative
         : p == Polarity::Negative ? Polarity::Positive : Polarity::Both;
}

class RootCollector {
 public:
  explicit RootCollector(const model::Matrix& m) : m_(m), inputs_(m) {}

  // Assumed: an assumption; Judged: the body, trigger or response, whose
  // every atom must be exact.
  enum class Role { Assumed, Judged };
  void visit(const Expr& e, Role role, Polarity pol);
  std::vector<model::Node> roots() const { return {roots_.begin(), roots_.end()}; }

 private:
  void add_cause(int id) {
    const auto* c = m_.find_cause(id);
    if (c && c->function != model::CauseFunction::Comment) roots_.insert({model::Node::Kind::Cause, id});
  }
  void add_effect(int id) {
    const auto* e = m_.find_effect(id);
    if (e && e->function != model::EffectFunction::Comment)
      roots_.insert({model::Node::Kind::Effect, id});
  }
  void readers_of_input(std::size_t index);
  void command_targets(const CommandPattern& p);

  const model::Matrix& m_;
  model::InputTable inputs_;
  std::set<model::Node> roots_;
};

bool names(const std::optional<std::string>& slot, const std::string& key) {
  return slot && model::tag_key(*slot) == key;
}

// Every element that reads the tag, in any role (the encoder creates the
// input variable of a tag only where an encoded element reads it).
void RootCollector::readers_of_input(std::size_t index) {
  if (index >= inputs_.size()) return;
  std::string key = model::tag_key(inputs_.tags()[index].name);
  for (const auto& c : m_.causes) {
    bool reads = names(c.bypass_tag, key) || names(c.inhibit_tag, key);
    for (const auto& t : c.tags) reads = reads || model::tag_key(t.name) == key;
    if (reads) add_cause(c.id);
  }
  for (const auto& e : m_.effects) {
    bool reads = names(e.bypass_tag, key) || names(e.reset_tag, key);
    if (e.process_data) reads = reads || names(e.process_data->tag, key) || names(e.process_data->mask_tag, key);
    if (reads) add_effect(e.id);
  }
}

// The elements a command matching the pattern can name. An open target means
// every element such a command can name, so that no acceptable command is
// left out of the cone (docs/properties.md "The symbolic monitor").
void RootCollector::command_targets(const CommandPattern& p) {
  using Op = model::CommandOp;
  bool cause_op = p.op == Op::AckCause || p.op == Op::SoftBypassCause || p.op == Op::SoftBypassTag;
  bool effect_op = p.op == Op::ResetEffect || p.op == Op::OverrideEffect ||
                   p.op == Op::StopOverride || p.op == Op::SoftBypassEffect;
  if (p.op == Op::ClearAlarms) {
    if (p.cause) add_cause(*p.cause);
    if (p.effect) add_effect(*p.effect);
    if (!p.cause && !p.effect) {
      for (const auto& c : m_.causes) add_cause(c.id);
      for (const auto& e : m_.effects) add_effect(e.id);
    }
  } else if (cause_op) {
    if (p.cause) add_cause(*p.cause);
    else for (const auto& c : m_.causes) add_cause(c.id);
  } else if (effect_op) {
    if (p.effect) add_effect(*p.effect);
    else for (const auto& e : m_.effects) add_effect(e.id);
  } else if (p.op == Op::ClearFirstOut) {
    for (const auto& c : m_.causes)
      if (c.first_out_group != 0 && (!p.group || c.first_out_group == *p.group)) add_cause(c.id);
  } else {
    // simulate_tag / stop_simulation: the causes reading the tag and the
    // effects writing it (O.8); every one of them when no tag is named.
    std::optional<std::string> key;
    if (p.tag_name && !p.tag_name->empty()) key = model::tag_key(*p.tag_name);
    for (const auto& c : m_.causes)
      for (const auto& t : c.tags)
        if (!model::parse_internal_ref(t.name) && (!key || model::tag_key(t.name) == *key)) add_cause(c.id);
    for (const auto& e : m_.effects)
      for (const auto& t : e.tags)
        if (!key || model::tag_key(t.name) == *key) add_effect(e.id);
  }
}

void RootCollector::visit(const Expr& e, Role role, Polarity pol) {
  switch (e.kind) {
    case Expr::Kind::Observable:
      if (e.observable.kind == model::Node::Kind::Cause) add_cause(e.observable.id);
      else add_effect(e.observable.id);
      break;
    case Expr::Kind::InputValue:
    case Expr::Kind::InputBad:
      readers_of_input(e.input);
      break;
    case Expr::Kind::CommandIssued:
      // A command that occurs only negatively in an assumption (`assume not
      // issued(simulate_tag)`) needs no targets in the cone: a run without
      // the commands outside the cone meets the assumption as well, and acts
      // the same on the cone ("The symbolic monitor", "Cone of influence").
      if (role == Role::Judged || pol != Polarity::Negative) command_targets(e.command);
      break;
    default:
      break;
  }
  switch (e.kind) {
    case Expr::Kind::Not:
      visit(e.args.at(0), role, flip(pol));
      return;
    case Expr::Kind::Implies:
      visit(e.args.at(0), role, flip(pol));
      visit(e.args.at(1), role, pol);
      return;
    // Monotone in every argument.
    case Expr::Kind::And:
    case Expr::Kind::Or:
    case Expr::Kind::Prev:
    case Expr::Kind::Held:
    case Expr::Kind::Within:
    case Expr::Kind::Since:
      for (const auto& a : e.args) visit(a, role, pol);
      return;
    // Iff, comparisons, counts, rose and fell: either direction.
    default:
      for (const auto& a : e.args) visit(a, role, Polarity::Both);
      return;
  }
}

}  // namespace

Monitor compile_monitor(encoder::Encoding& enc, const Property& p,
                        const std::vector<Assumption>& file_assumptions) {
  MonitorBuilder b(enc);
  z3::context& c = enc.ts.ctx();
  z3::expr_vector assumed(c);
  for (const auto& a : file_assumptions) assumed.push_back(b.compile(a.expr));
  for (const auto& a : p.assumptions) assumed.push_back(b.compile(a.expr));
  z3::expr assumption = assumed.empty() ? c.bool_val(true)
                        : assumed.size() == 1 ? assumed[0] : z3::mk_and(assumed);

  std::optional<z3::expr> antecedent;
  std::optional<z3::expr> good;
  switch (p.kind) {
    case PropertyKind::Invariant:
      good = b.compile(p.body);
      if (p.body.kind == Expr::Kind::Implies) antecedent = b.compile(p.body.args.at(0));
      break;
    case PropertyKind::Never:
      good = !b.compile(p.body);
      // docs/properties.md "Vacuity": the first conjunct of `never a and b`.
      if (p.body.kind == Expr::Kind::And && p.body.args.size() >= 2) antecedent = b.compile(p.body.args[0]);
      break;
    case PropertyKind::Reachable:
      good = !b.compile(p.body);
      break;
    case PropertyKind::Response: {
      z3::expr trigger = b.compile(p.trigger);
      antecedent = trigger;
      good = !b.response_violation(trigger, b.compile(p.response), p.within_cycles);
      break;
    }
  }
  if (!good) throw std::logic_error("monitor: unknown property kind");
  // Every monitor variable has its initial value and next-state function.
  enc.ts.check_complete();
  return Monitor{*good, assumption, antecedent, b.added()};
}

std::vector<model::Node> property_roots(const Property& p,
                                        const std::vector<Assumption>& file_assumptions,
                                        const model::Matrix& m) {
  using Role = RootCollector::Role;
  RootCollector r(m);
  for (const auto& a : file_assumptions) r.visit(a.expr, Role::Assumed, Polarity::Positive);
  for (const auto& a : p.assumptions) r.visit(a.expr, Role::Assumed, Polarity::Positive);
  r.visit(p.body, Role::Judged, Polarity::Positive);
  r.visit(p.trigger, Role::Judged, Polarity::Positive);
  r.visit(p.response, Role::Judged, Polarity::Positive);
  return r.roots();
}

}  // namespace cemv::properties
