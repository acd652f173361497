// The concrete evaluator one cycle at a time (evaluator.hpp, StreamEvaluator):
// each past-time operator keeps what its definition looks back at, in one
// number per node. Prev, Rose, Fell: the operand's previous value. Held N:
// how many cycles the operand has held up to now (enough at N + 1). Within N:
// the cycles since the operand last held (N + 1: not in the window). Since:
// its own previous value, since(a, b) at k being b at k, or a at k and
// since(a, b) at k - 1.
#include <algorithm>
#include <stdexcept>

#include "properties/evaluator.hpp"
#include "properties/evaluator_atoms.hpp"

namespace cemv::properties {

namespace {

using Kind = Expr::Kind;

std::size_t observable_index(const std::vector<model::Observable>& all, const std::string& key) {
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all[i].key == key) return i;
  throw std::invalid_argument("evaluator: the matrix has no observable " + key);
}

class Compiler {
 public:
  Compiler(const std::vector<model::Observable>& observables, StreamEvaluator::Program& p)
      : observables_(observables), p_(p) {}

  std::size_t compile(const Expr& e) {
    StreamEvaluator::Node n;
    n.expr = &e;
    for (const auto& a : e.args) n.args.push_back(compile(a));
    if (e.kind == Kind::Observable) n.observable = observable_index(observables_, e.observable.key);
    if (e.kind == Kind::Compare)
      n.floats = e.args.at(0).type == ExprType::Float || e.args.at(1).type == ExprType::Float;
    p_.nodes.push_back(std::move(n));
    return p_.nodes.size() - 1;
  }

 private:
  const std::vector<model::Observable>& observables_;
  StreamEvaluator::Program& p_;
};

// What an operator remembers before the first cycle.
std::int64_t initial_memory(const Expr& e) {
  return e.kind == Kind::Within ? static_cast<std::int64_t>(e.cycles) + 1 : 0;
}

}  // namespace

StreamEvaluator::StreamEvaluator(const model::Matrix& m, const Property& p,
                                 const std::vector<Assumption>& file_assumptions)
    : property_(&p) {
  auto program = std::make_shared<Program>();
  const std::vector<model::Observable> observables = model::observables(m);
  Compiler c(observables, *program);
  for (const auto& a : file_assumptions) program->assumptions.push_back(c.compile(a.expr));
  for (const auto& a : p.assumptions) program->assumptions.push_back(c.compile(a.expr));
  if (const Expr* ante = detail::antecedent(p)) {
    program->antecedent = c.compile(*ante);
    program->has_antecedent = true;
  }
  if (p.kind == PropertyKind::Response) {
    program->trigger = c.compile(p.trigger);
    program->response = c.compile(p.response);
  } else {
    program->body = c.compile(p.body);
  }
  for (const Node& n : program->nodes)
    if (n.expr->kind == Kind::Observable) program->read.push_back(n.observable);
  std::sort(program->read.begin(), program->read.end());
  program->read.erase(std::unique(program->read.begin(), program->read.end()), program->read.end());
  memory_.resize(program->nodes.size());
  for (std::size_t i = 0; i < program->nodes.size(); ++i) memory_[i] = initial_memory(*program->nodes[i].expr);
  now_.resize(program->nodes.size());
  program_ = std::move(program);
  result_.name = p.name;
  result_.kind = p.kind;
  result_.holds = p.kind != PropertyKind::Reachable;
}

void StreamEvaluator::evaluate_all(const model::CycleInput& in, const std::vector<int>& obs) {
  const std::vector<Node>& nodes = program_->nodes;
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const Node& node = nodes[n];
    const Expr& e = *node.expr;
    Value& out = now_[n];
    out = Value{};
    auto arg = [&](std::size_t k) -> const Value& { return now_[node.args[k]]; };
    std::int64_t& mem = memory_[n];
    switch (e.kind) {
      case Kind::BoolConst: out.i = e.bool_value; break;
      case Kind::IntConst: out.i = e.int_value; break;
      case Kind::FloatConst: out.f = e.float_value; break;
      case Kind::Observable: out.i = obs.at(node.observable); break;
      case Kind::InputValue: {
        const float v = in.tags.at(e.input).value;
        if (e.type == ExprType::Float) out.f = v;
        else out.i = v != 0.0f;
        break;
      }
      case Kind::InputBad: out.i = in.tags.at(e.input).bad_quality; break;
      case Kind::CommandIssued:
        out.i = std::any_of(in.commands.begin(), in.commands.end(),
                            [&](const model::Command& c) { return detail::matches(e.command, c); });
        break;
      case Kind::Compare:
        out.i = node.floats ? detail::compare(e.cmp, arg(0).f, arg(1).f) : detail::compare(e.cmp, arg(0).i, arg(1).i);
        break;
      case Kind::Not: out.i = !arg(0).i; break;
      case Kind::And:
        out.i = 1;
        for (std::size_t k = 0; k < node.args.size(); ++k) out.i = out.i && arg(k).i;
        break;
      case Kind::Or:
        for (std::size_t k = 0; k < node.args.size(); ++k) out.i = out.i || arg(k).i;
        break;
      case Kind::Count:
        for (std::size_t k = 0; k < node.args.size(); ++k) out.i += arg(k).i ? 1 : 0;
        break;
      case Kind::Implies: out.i = !arg(0).i || arg(1).i; break;
      case Kind::Iff: out.i = !arg(0).i == !arg(1).i; break;
      case Kind::Prev:
      case Kind::Rose:
      case Kind::Fell: {
        const bool now = arg(0).i != 0, before = mem != 0;
        out.i = e.kind == Kind::Prev ? before : e.kind == Kind::Rose ? (now && !before) : (!now && before);
        mem = now;
        break;
      }
      case Kind::Held: {
        const std::int64_t span = e.cycles;
        mem = arg(0).i ? std::min(mem + 1, span + 1) : 0;
        out.i = mem >= span + 1;
        break;
      }
      case Kind::Within: {
        const std::int64_t span = e.cycles;
        mem = arg(0).i ? 0 : std::min(mem + 1, span + 1);
        out.i = mem <= span;
        break;
      }
      case Kind::Since:
        mem = arg(1).i || (arg(0).i && mem);
        out.i = mem;
        break;
    }
  }
}

void StreamEvaluator::step(const model::CycleInput& in, const std::vector<int>& obs) {
  if (frozen_) return;
  const std::size_t k = result_.judged;
  evaluate_all(in, obs);
  const Program& p = *program_;
  for (std::size_t a : p.assumptions)
    if (!now_[a].i) {
      frozen_ = true;
      result_.assumptions_held = false;
      return;
    }
  result_.judged = k + 1;
  if (p.has_antecedent && now_[p.antecedent].i) result_.antecedent_met = true;
  if (result_.cycle) return;
  switch (property_->kind) {
    case PropertyKind::Invariant:
    case PropertyKind::Never:
    case PropertyKind::Reachable: {
      const bool looking_for = property_->kind != PropertyKind::Invariant;
      if ((now_[p.body].i != 0) == looking_for) {
        result_.cycle = k;
        result_.holds = property_->kind == PropertyKind::Reachable;
      }
      return;
    }
    case PropertyKind::Response: {
      // Every trigger still waiting is answered by a response now; the
      // oldest one left unanswered for N cycles is the first violation.
      if (now_[p.trigger].i && !pending_) pending_ = k;
      if (now_[p.response].i) pending_.reset();
      if (pending_ && *pending_ + static_cast<std::size_t>(property_->within_cycles) == k) {
        result_.cycle = k;
        result_.trigger_cycle = *pending_;
        result_.holds = false;
      }
      return;
    }
  }
}

}  // namespace cemv::properties
