// Every expression is evaluated to one column of values over the whole trace,
// children first; past-time operators look back over the columns of their
// operands exactly as their definitions read (docs/properties.md, "Semantics").
// Deliberately no state machines: the symbolic monitor uses those, and so
// does the evaluator's streamed form (evaluator_stream.cpp), which is held
// to this one by tests/properties/test_stream_evaluator.cpp.
#include "properties/evaluator.hpp"

#include <algorithm>
#include <stdexcept>

#include "properties/evaluator_atoms.hpp"

namespace cemv::properties {

namespace {

using Kind = Expr::Kind;

// One value of any expression type: Bool as 0/1 and Int/Voting in `i`, Float in `f`.
struct Value {
  std::int64_t i = 0;
  float f = 0.0f;
};
using Column = std::vector<Value>;

using detail::compare;
using detail::matches;

class ColumnEvaluator {
 public:
  ColumnEvaluator(const std::vector<model::Observable>& observables, const Trace& t)
      : observables_(observables), t_(t), n_(t.size()) {}

  Column eval(const Expr& e) const {
    Column out(n_);
    switch (e.kind) {
      case Kind::BoolConst:
        for (auto& v : out) v.i = e.bool_value;
        return out;
      case Kind::IntConst:
        for (auto& v : out) v.i = e.int_value;
        return out;
      case Kind::FloatConst:
        for (auto& v : out) v.f = e.float_value;
        return out;
      case Kind::Observable: {
        std::size_t index = observable_index(e.observable.key);
        for (std::size_t k = 0; k < n_; ++k) out[k].i = t_[k].observables.at(index);
        return out;
      }
      case Kind::InputValue:
        for (std::size_t k = 0; k < n_; ++k) {
          float v = t_[k].input.tags.at(e.input).value;
          if (e.type == ExprType::Float) out[k].f = v;
          else out[k].i = v != 0.0f;
        }
        return out;
      case Kind::InputBad:
        for (std::size_t k = 0; k < n_; ++k) out[k].i = t_[k].input.tags.at(e.input).bad_quality;
        return out;
      case Kind::CommandIssued:
        for (std::size_t k = 0; k < n_; ++k)
          out[k].i = std::any_of(t_[k].input.commands.begin(), t_[k].input.commands.end(),
                                 [&](const model::Command& c) { return matches(e.command, c); });
        return out;
      case Kind::Compare: {
        Column a = eval(e.args.at(0)), b = eval(e.args.at(1));
        bool floats = e.args[0].type == ExprType::Float || e.args[1].type == ExprType::Float;
        for (std::size_t k = 0; k < n_; ++k)
          out[k].i = floats ? compare(e.cmp, a[k].f, b[k].f) : compare(e.cmp, a[k].i, b[k].i);
        return out;
      }
      case Kind::Not: {
        Column a = eval(e.args.at(0));
        for (std::size_t k = 0; k < n_; ++k) out[k].i = !a[k].i;
        return out;
      }
      case Kind::And:
      case Kind::Or:
      case Kind::Count: {
        for (auto& v : out) v.i = e.kind == Kind::And ? 1 : 0;
        for (const auto& arg : e.args) {
          Column a = eval(arg);
          for (std::size_t k = 0; k < n_; ++k) {
            if (e.kind == Kind::And) out[k].i = out[k].i && a[k].i;
            else if (e.kind == Kind::Or) out[k].i = out[k].i || a[k].i;
            else out[k].i += a[k].i ? 1 : 0;
          }
        }
        return out;
      }
      case Kind::Implies:
      case Kind::Iff: {
        Column a = eval(e.args.at(0)), b = eval(e.args.at(1));
        for (std::size_t k = 0; k < n_; ++k)
          out[k].i = e.kind == Kind::Implies ? (!a[k].i || b[k].i) : (!a[k].i == !b[k].i);
        return out;
      }
      case Kind::Prev:
      case Kind::Rose:
      case Kind::Fell: {
        Column a = eval(e.args.at(0));
        for (std::size_t k = 0; k < n_; ++k) {
          bool now = a[k].i, before = k > 0 && a[k - 1].i;  // prev is false in the first cycle
          out[k].i = e.kind == Kind::Prev ? before : e.kind == Kind::Rose ? (now && !before) : (!now && before);
        }
        return out;
      }
      case Kind::Held:
      case Kind::Within: {
        Column a = eval(e.args.at(0));
        std::size_t span = static_cast<std::size_t>(e.cycles);
        for (std::size_t k = 0; k < n_; ++k) {
          if (e.kind == Kind::Held) {
            // every cycle of [k-N, k]; false while fewer than N cycles precede k
            bool all = k >= span;
            for (std::size_t j = k >= span ? k - span : 0; all && j <= k; ++j) all = a[j].i;
            out[k].i = all;
          } else {
            // some cycle of [max(0, k-N), k]
            bool any = false;
            for (std::size_t j = k >= span ? k - span : 0; !any && j <= k; ++j) any = a[j].i;
            out[k].i = any;
          }
        }
        return out;
      }
      case Kind::Since: {
        Column a = eval(e.args.at(0)), b = eval(e.args.at(1));
        for (std::size_t k = 0; k < n_; ++k) {
          // exists j <= k: b at j and a at every cycle of (j, k]
          bool found = false;
          for (std::size_t j = k + 1; j-- > 0;) {
            if (b[j].i) {
              found = true;
              break;
            }
            if (!a[j].i) break;  // a fails at j, so every earlier j' has j in (j', k]
          }
          out[k].i = found;
        }
        return out;
      }
    }
    throw std::logic_error("evaluator: unknown expression kind");
  }

 private:
  std::size_t observable_index(const std::string& key) const {
    for (std::size_t i = 0; i < observables_.size(); ++i)
      if (observables_[i].key == key) return i;
    throw std::invalid_argument("evaluator: the matrix has no observable " + key);
  }

  const std::vector<model::Observable>& observables_;
  const Trace& t_;
  std::size_t n_;
};

std::vector<bool> to_bools(const Column& c) {
  std::vector<bool> out(c.size());
  for (std::size_t k = 0; k < c.size(); ++k) out[k] = c[k].i != 0;
  return out;
}

using detail::antecedent;

}  // namespace

Evaluator::Evaluator(const model::Matrix& m) : observables_(model::observables(m)) {}

std::vector<bool> Evaluator::values(const Expr& e, const Trace& t) const {
  return to_bools(ColumnEvaluator(observables_, t).eval(e));
}

Evaluation Evaluator::evaluate(const Property& p, const std::vector<Assumption>& file_assumptions,
                               const Trace& t) const {
  ColumnEvaluator columns(observables_, t);
  Evaluation r;
  r.name = p.name;
  r.kind = p.kind;
  r.judged = t.size();
  auto cut = [&](const Assumption& a) {
    std::vector<bool> v = to_bools(columns.eval(a.expr));
    for (std::size_t k = 0; k < r.judged; ++k)
      if (!v[k]) r.judged = k;
  };
  for (const auto& a : file_assumptions) cut(a);
  for (const auto& a : p.assumptions) cut(a);
  r.assumptions_held = r.judged == t.size();
  if (const Expr* ante = antecedent(p)) {
    std::vector<bool> v = to_bools(columns.eval(*ante));
    for (std::size_t k = 0; k < r.judged && !r.antecedent_met; ++k) r.antecedent_met = v[k];
  }
  switch (p.kind) {
    case PropertyKind::Invariant:
    case PropertyKind::Never:
    case PropertyKind::Reachable: {
      std::vector<bool> body = to_bools(columns.eval(p.body));
      // Invariant: a cycle where the body is false; Never and Reachable: one where it is true.
      bool looking_for = p.kind != PropertyKind::Invariant;
      for (std::size_t k = 0; k < r.judged; ++k)
        if (body[k] == looking_for) {
          r.cycle = k;
          break;
        }
      r.holds = p.kind == PropertyKind::Reachable ? r.cycle.has_value() : !r.cycle.has_value();
      return r;
    }
    case PropertyKind::Response: {
      std::vector<bool> trigger = to_bools(columns.eval(p.trigger));
      std::vector<bool> response = to_bools(columns.eval(p.response));
      std::size_t n = static_cast<std::size_t>(p.within_cycles);
      // A trigger at k is violated when its whole window [k, k+N] lies in the
      // judged part and the response holds in none of its cycles. Violations are
      // ordered by the cycle where they become definite, k + N.
      for (std::size_t k = 0; k + n < r.judged; ++k) {
        if (!trigger[k]) continue;
        bool answered = false;
        for (std::size_t j = k; j <= k + n && !answered; ++j) answered = response[j];
        if (!answered) {
          r.cycle = k + n;
          r.trigger_cycle = k;
          break;
        }
      }
      r.holds = !r.cycle.has_value();
      return r;
    }
  }
  return r;
}

std::vector<Evaluation> Evaluator::evaluate(const PropertyFile& f, const Trace& t) const {
  std::vector<Evaluation> out;
  for (const auto& p : f.properties) out.push_back(evaluate(p, f.assumptions, t));
  return out;
}

}  // namespace cemv::properties
