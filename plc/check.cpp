#include "plc/check.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <set>

#include "model/text.hpp"
#include "plc/check_support.hpp"
#include "plc/lexer.hpp"

namespace cemv::plc {

namespace {

using namespace checking;

// Declarations (P.1, P.3) and statements (P.4); expressions in check_expressions.cpp.
class Checker : public ExpressionChecker {
 public:
  using ExpressionChecker::ExpressionChecker;

  void run() {
    check_pous();
    for (Pou& pou : program_.pous) check_declarations(pou);
    check_no_recursion();
    for (Pou& pou : program_.pous) {
      pou_ = &pou;
      loop_variables_.clear();
      check_body(pou.body);
    }
    for (const Pou& pou : program_.pous)
      if (statement_bound(program_, pou) > kMaxStatementsPerScan)
        fail(pou.position, "a call of " + model::in_quotes(pou.name) + " may execute more than " +
                               std::to_string(kMaxStatementsPerScan) +
                               " statements (loop iterations and block bodies counted; docs/plc.md P.4.4)");
  }


 private:
  void check_pous() {
    bool any_program = false;
    for (std::size_t i = 0; i < program_.pous.size(); ++i) {
      const Pou& pou = program_.pous[i];
      any_program = any_program || pou.kind == PouKind::Program;
      for (std::size_t j = 0; j < i; ++j)
        if (same_name(program_.pous[j].name, pou.name))
          fail(pou.position, "POU " + model::in_quotes(pou.name) + " is declared twice");
      if (type_from_name(pou.name) || block_from_name(pou.name))
        fail(pou.position, "POU " + model::in_quotes(pou.name) + " has the name of a standard type or block");
    }
    if (!any_program) fail(program_.pous.empty() ? Position{} : program_.pous[0].position, "no PROGRAM POU");
  }

  void check_declarations(Pou& pou) {
    for (std::size_t i = 0; i < pou.variables.size(); ++i) {
      Variable& v = pou.variables[i];
      for (std::size_t j = 0; j < i; ++j)
        if (same_name(pou.variables[j].name, v.name))
          fail(v.position, "variable " + model::in_quotes(v.name) + " is declared twice in " + model::in_quotes(pou.name));
      if (v.type.kind == VarType::Kind::User) {
        const Pou* block = find_pou(program_, v.type.user);
        if (!block) {
          std::vector<std::string> names;
          for (const Pou& p : program_.pous)
            if (p.kind == PouKind::FunctionBlock) names.push_back(p.name);
          fail(v.position, "unknown type or function block " + model::in_quotes(v.type.user) +
                               model::did_you_mean(v.type.user, names) + " (docs/plc.md P.2, P.6)");
        }
        if (block->kind != PouKind::FunctionBlock)
          fail(v.position, "PROGRAM " + model::in_quotes(block->name) + " cannot be instantiated (docs/plc.md P.1)");
        v.type.user = block->name;
      }
      if (v.type.kind != VarType::Kind::Elementary && v.section != Section::Local)
        fail(v.position, "a block instance is declared in VAR only, not in " + std::string(section_keyword(v.section)) +
                             " (docs/plc.md P.3)");
      if (v.section == Section::Constant && !v.initial)
        fail(v.position, "VAR CONSTANT " + model::in_quotes(v.name) + " needs an initial value");
      if (v.section == Section::InOut && v.initial)
        fail(v.initial_position, "VAR_IN_OUT " + model::in_quotes(v.name) + " cannot have an initial value");
      if (v.initial) v.initial = fit_literal(*v.initial, v.type.type, v.initial_position);
    }
  }

  void check_no_recursion() {
    std::map<std::string, int> state;  // 1 visiting, 2 done
    for (const Pou& pou : program_.pous) visit(pou, state);
  }
  void visit(const Pou& pou, std::map<std::string, int>& state) {
    int& s = state[pou.name];
    if (s == 2) return;
    s = 1;
    for (const Variable& v : pou.variables) {
      if (v.type.kind != VarType::Kind::User) continue;
      const Pou* block = find_pou(program_, v.type.user);
      if (state[block->name] == 1)
        fail(v.position, "function block " + model::in_quotes(block->name) + " contains an instance of itself");
      visit(*block, state);
    }
    state[pou.name] = 2;
  }


  // --- statements

  void check_body(std::vector<Statement>& body) {
    for (Statement& s : body) check_statement(s);
  }

  void check_statement(Statement& s) {
    switch (s.kind) {
      case Statement::Kind::Assign: {
        Variable& v = elementary(s.target, s.position);
        assignable(v, s.position);
        s.target = v.name;
        const Type t = check(s.value, v.type.type);
        if (t != v.type.type)
          fail(s.value.position, "a " + quoted_type(t) + " assigned to " + model::in_quotes(v.name) + " of type " +
                                     quoted_type(v.type.type) + " (no implicit conversion; docs/plc.md P.2)");
        return;
      }
      case Statement::Kind::If:
        for (Branch& b : s.branches) {
          if (check(b.condition, Type::Bool) != Type::Bool)
            fail(b.condition.position, "an IF condition must be a BOOL, found " + quoted_type(b.condition.type));
          check_body(b.body);
        }
        check_body(s.else_body);
        return;
      case Statement::Kind::Case: return check_case(s);
      case Statement::Kind::For: return check_for(s);
      case Statement::Kind::Call: return check_call(s);
    }
  }

  void check_case(Statement& s) {
    const Type t = check(s.value, std::nullopt);
    if (!is_integer(t)) fail(s.value.position, "a CASE selector must be an INT or DINT, found " + quoted_type(t));
    const auto [lo, hi] = range_of(t);
    std::vector<CaseRange> seen;
    for (CaseArm& arm : s.arms) {
      for (const CaseRange& r : arm.labels) {
        if (r.low > r.high) fail(arm.position, "CASE range " + std::to_string(r.low) + ".." + std::to_string(r.high) + " is empty");
        if (r.low < lo || r.high > hi) fail(arm.position, "CASE label out of the range of " + quoted_type(t));
        for (const CaseRange& o : seen)
          if (r.low <= o.high && o.low <= r.high)
            fail(arm.position, "CASE label " + std::to_string(std::max(r.low, o.low)) + " appears twice (docs/plc.md P.4)");
        seen.push_back(r);
      }
      check_body(arm.body);
    }
    check_body(s.else_body);
  }

  std::int64_t bound_value(Expr& e, Type t) {
    const bool negate = e.kind == Expr::Kind::Unary;
    Expr& x = negate ? e.args[0] : e;
    std::int64_t v = 0;
    if (x.kind == Expr::Kind::Literal) {
      if (!is_integer(x.literal.type)) fail(x.position, "a FOR bound must be an integer");
      v = x.literal.integer;
    } else {
      Variable& c = variable(x.name, x.position);
      if (c.section != Section::Constant)
        fail(x.position, "FOR bounds must be constants (a literal or a VAR CONSTANT); " + model::in_quotes(c.name) +
                             " is a variable (docs/plc.md P.4)");
      if (c.type.type != t)
        fail(x.position, "FOR bound " + model::in_quotes(c.name) + " is a " + quoted_type(c.type.type) +
                             ", the loop variable a " + quoted_type(t));
      x.name = c.name;
      v = c.initial->integer;
    }
    check(e, t);
    if (negate) v = -v;
    const auto [lo, hi] = range_of(t);
    if (v < lo || v > hi) fail(e.position, "FOR bound out of the range of " + quoted_type(t));
    return v;
  }

  void check_for(Statement& s) {
    Variable& v = elementary(s.target, s.position);
    assignable(v, s.position);
    s.target = v.name;
    if (!is_integer(v.type.type)) fail(s.position, "a FOR variable must be an INT or DINT");
    s.from = bound_value(s.value, v.type.type);
    s.to = bound_value(s.limit, v.type.type);
    s.by = bound_value(s.step, v.type.type);
    if (s.by == 0) fail(s.step.position, "FOR ... BY 0 never ends (docs/plc.md P.4)");
    const std::int64_t n = for_iterations(s);
    if (n > kMaxForIterations)
      fail(s.position, "FOR loop of " + std::to_string(n) + " iterations; at most " + std::to_string(kMaxForIterations) +
                           " (docs/plc.md P.4)");
    const auto [lo, hi] = range_of(v.type.type);
    const std::int64_t after = s.from + n * s.by;
    if (after < lo || after > hi)
      fail(s.position, "FOR loop's variable leaves the range of " + quoted_type(v.type.type) +
                           " after its last iteration (docs/plc.md P.4)");
    loop_variables_.push_back(v.name);
    check_body(s.body);
    loop_variables_.pop_back();
  }

  void check_call(Statement& s) {
    Variable& inst = variable(s.target, s.position);
    if (inst.type.kind == VarType::Kind::Elementary)
      fail(s.position, model::in_quotes(inst.name) + " is not a block instance (docs/plc.md P.4)");
    s.target = inst.name;
    std::set<std::string> given, bound_vars;
    for (CallArg& a : s.args) {
      Type type;
      bool input = false, inout = false;
      if (inst.type.kind == VarType::Kind::Standard) {
        const PinInfo* pin = nullptr;
        for (const PinInfo& p : block_pins(inst.type.block))
          if (same_name(pin_name(p.pin), a.name)) pin = &p;
        if (!pin) {
          std::vector<std::string> names;
          for (const PinInfo& p : block_pins(inst.type.block)) names.emplace_back(pin_name(p.pin));
          fail(a.position, model::in_quotes(a.name) + " is not a parameter of " +
                               std::string(block_name(inst.type.block)) + model::did_you_mean(a.name, names));
        }
        a.pin = pin->pin;
        a.name = std::string(pin_name(pin->pin));
        type = pin->type;
        input = pin->input;
      } else {
        const Pou& block = *find_pou(program_, inst.type.user);
        const Variable* v = find_variable(block, a.name);
        if (!v || (v->section != Section::Input && v->section != Section::Output && v->section != Section::InOut))
          fail(a.position, model::in_quotes(a.name) + " is not a parameter of " + model::in_quotes(block.name));
        a.name = v->name;
        type = v->type.type;
        input = v->section == Section::Input;
        inout = v->section == Section::InOut;
      }
      if (!given.insert(a.name).second) fail(a.position, "parameter " + model::in_quotes(a.name) + " given twice");
      if (a.output == (input || inout))
        fail(a.position, model::in_quotes(a.name) + (a.output ? " is an input: pass it with ':='" : " is an output: read it with '=>'"));
      if (a.output || inout) {
        if (a.value.kind != Expr::Kind::Variable)
          fail(a.value.position, model::in_quotes(a.name) + " must be bound to a variable");
        Variable& target = elementary(a.value.name, a.value.position);
        assignable(target, a.value.position);
        if (!bound_vars.insert(target.name).second)
          fail(a.value.position, model::in_quotes(target.name) + " is bound twice in one call");
      }
      const Type t = check(a.value, type);
      if (t != type)
        fail(a.value.position, "a " + quoted_type(t) + " given for " + model::in_quotes(a.name) + " of type " +
                                   quoted_type(type) + " (no implicit conversion; docs/plc.md P.2)");
    }
    if (inst.type.kind == VarType::Kind::User)
      for (const Variable& v : find_pou(program_, inst.type.user)->variables)
        if (v.section == Section::InOut && !given.count(v.name))
          fail(s.position, "the call of " + model::in_quotes(inst.name) + " does not bind VAR_IN_OUT " +
                               model::in_quotes(v.name) + " (docs/plc.md P.4)");
  }
};

}  // namespace

std::int64_t for_iterations(const Statement& s) {
  if (s.by > 0) return s.from > s.to ? 0 : (s.to - s.from) / s.by + 1;
  return s.from < s.to ? 0 : (s.from - s.to) / -s.by + 1;
}

void check_program(Program& program) { Checker(program).run(); }

namespace {

constexpr std::uint64_t kSaturated = kMaxStatementsPerScan + 1;

std::uint64_t add(std::uint64_t a, std::uint64_t b) { return std::min(kSaturated, a + b); }
std::uint64_t times(std::uint64_t a, std::uint64_t b) { return b != 0 && a > kSaturated / b ? kSaturated : std::min(kSaturated, a * b); }

std::uint64_t bound(const Program& program, const std::vector<Statement>& body,
                    std::map<std::string, std::uint64_t>& memo, const Pou& pou);

std::uint64_t bound_of_pou(const Program& program, const Pou& pou, std::map<std::string, std::uint64_t>& memo) {
  auto it = memo.find(pou.name);
  if (it != memo.end()) return it->second;
  const std::uint64_t b = bound(program, pou.body, memo, pou);
  memo[pou.name] = b;
  return b;
}

std::uint64_t bound(const Program& program, const std::vector<Statement>& body,
                    std::map<std::string, std::uint64_t>& memo, const Pou& pou) {
  std::uint64_t total = 0;
  for (const Statement& s : body) {
    std::uint64_t b = 1;
    switch (s.kind) {
      case Statement::Kind::Assign: break;
      case Statement::Kind::If:
        for (const Branch& br : s.branches) b = add(b, bound(program, br.body, memo, pou));
        b = add(b, bound(program, s.else_body, memo, pou));
        break;
      case Statement::Kind::Case:
        for (const CaseArm& arm : s.arms) b = add(b, bound(program, arm.body, memo, pou));
        b = add(b, bound(program, s.else_body, memo, pou));
        break;
      case Statement::Kind::For:
        b = add(b, times(static_cast<std::uint64_t>(for_iterations(s)), bound(program, s.body, memo, pou)));
        break;
      case Statement::Kind::Call: {
        const Variable* inst = find_variable(pou, s.target);
        if (inst && inst->type.kind == VarType::Kind::User)
          if (const Pou* block = find_pou(program, inst->type.user)) b = add(b, bound_of_pou(program, *block, memo));
        break;
      }
    }
    total = add(total, b);
  }
  return total;
}

}  // namespace

std::uint64_t statement_bound(const Program& program, const Pou& pou) {
  std::map<std::string, std::uint64_t> memo;
  return bound_of_pou(program, pou, memo);
}

}  // namespace cemv::plc