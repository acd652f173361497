#include "plc/check.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <set>

#include "model/text.hpp"
#include "plc/lexer.hpp"

namespace cemv::plc {

namespace {

bool is_integer(Type t) { return t == Type::Int || t == Type::Dint; }
bool is_numeric(Type t) { return is_integer(t) || t == Type::Real; }

std::pair<std::int64_t, std::int64_t> range_of(Type t) {
  if (t == Type::Int) return {std::numeric_limits<std::int16_t>::min(), std::numeric_limits<std::int16_t>::max()};
  return {std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()};
}

// An expression of integer literals only (`5`, `-(2 * 3)`): it takes the type
// its context asks for, as an untyped IEC literal does.
bool adaptable(const Expr& e) {
  switch (e.kind) {
    case Expr::Kind::Literal: return is_integer(e.literal.type);
    case Expr::Kind::Unary: return e.unary == UnaryOp::Negate && adaptable(e.args[0]);
    case Expr::Kind::Binary:
      return (e.binary == BinaryOp::Add || e.binary == BinaryOp::Sub || e.binary == BinaryOp::Mul ||
              e.binary == BinaryOp::Div || e.binary == BinaryOp::Mod) &&
             adaptable(e.args[0]) && adaptable(e.args[1]);
    case Expr::Kind::Call:
      if (e.function == Function::Sel) return e.args.size() == 3 && adaptable(e.args[1]) && adaptable(e.args[2]);
      if (e.function != Function::Min && e.function != Function::Max && e.function != Function::Abs &&
          e.function != Function::Limit)
        return false;
      return std::all_of(e.args.begin(), e.args.end(), adaptable);
    default: return false;
  }
}

std::string quoted_type(Type t) { return std::string(type_name(t)); }

// The argument and result types of a conversion function (P.5.7).
std::pair<Type, Type> conversion(Function f) {
  switch (f) {
    case Function::BoolToInt: return {Type::Bool, Type::Int};
    case Function::BoolToDint: return {Type::Bool, Type::Dint};
    case Function::IntToDint: return {Type::Int, Type::Dint};
    case Function::DintToInt: return {Type::Dint, Type::Int};
    case Function::IntToReal: return {Type::Int, Type::Real};
    case Function::DintToReal: return {Type::Dint, Type::Real};
    default: return {Type::Bool, Type::Bool};
  }
}

class Checker {
 public:
  explicit Checker(Program& p) : program_(p) {}

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
  Program& program_;
  Pou* pou_ = nullptr;
  std::vector<std::string> loop_variables_;

  [[noreturn]] void fail(Position at, std::string what) const { refuse(program_.file, at, std::move(what)); }

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

  // Only the field of its type is set: `integer` (0 or 1 for a BOOL) or `real`.
  static Literal canonical(Literal l) {
    if (l.type == Type::Real) l.integer = 0;
    else l.real = 0;
    if (l.type == Type::Bool) l.integer = l.integer != 0;
    return l;
  }

  Literal fit_literal(Literal l, Type want, Position at) const {
    l = canonical(l);
    if (is_integer(l.type) && is_numeric(want)) {
      if (want == Type::Real) return Literal{Type::Real, 0, static_cast<float>(l.integer)};
      const auto [lo, hi] = range_of(want);
      if (l.integer < lo || l.integer > hi)
        fail(at, "literal " + std::to_string(l.integer) + " is out of the range of " + quoted_type(want));
      l.type = want;
      return l;
    }
    if (l.type != want)
      fail(at, "a " + quoted_type(l.type == Type::Dint ? Type::Int : l.type) + " literal given for " + quoted_type(want) +
                   " (no implicit conversion; docs/plc.md P.2)");
    return l;
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

  // --- names

  Variable& variable(const std::string& name, Position at) {
    for (Variable& v : pou_->variables)
      if (same_name(v.name, name)) return v;
    std::vector<std::string> names;
    for (const Variable& v : pou_->variables) names.push_back(v.name);
    fail(at, "undeclared variable " + model::in_quotes(name) + model::did_you_mean(name, names) + " in " +
                 model::in_quotes(pou_->name));
  }

  Variable& elementary(const std::string& name, Position at) {
    Variable& v = variable(name, at);
    if (v.type.kind != VarType::Kind::Elementary)
      fail(at, "block instance " + model::in_quotes(v.name) + " used as a value; read one of its outputs, e.g. " +
                   v.name + ".Q");
    return v;
  }

  void assignable(const Variable& v, Position at) {
    if (v.section == Section::Input)
      fail(at, "assignment to the input " + model::in_quotes(v.name) + " (VAR_INPUT is read-only; docs/plc.md P.3)");
    if (v.section == Section::Constant)
      fail(at, "assignment to the constant " + model::in_quotes(v.name) + " (docs/plc.md P.3)");
    for (const std::string& l : loop_variables_)
      if (l == v.name) fail(at, "assignment to the FOR variable " + model::in_quotes(v.name) + " inside its loop (docs/plc.md P.4)");
  }

  // --- expressions

  Type check(Expr& e, std::optional<Type> hint) {
    switch (e.kind) {
      case Expr::Kind::Literal: {
        std::optional<Type> want;
        if (is_integer(e.literal.type)) want = hint && is_numeric(*hint) ? *hint : Type::Dint;
        e.literal = want ? fit_literal(e.literal, *want, e.position) : canonical(e.literal);
        return e.type = e.literal.type;
      }
      case Expr::Kind::Variable: {
        Variable& v = elementary(e.name, e.position);
        e.name = v.name;
        return e.type = v.type.type;
      }
      case Expr::Kind::Member: return e.type = member(e);
      case Expr::Kind::Unary: return e.type = unary(e, hint);
      case Expr::Kind::Binary: return e.type = binary(e, hint);
      case Expr::Kind::Call: return e.type = call(e, hint);
    }
    return e.type;
  }

  Type member(Expr& e) {
    Variable& inst = variable(e.name, e.position);
    e.name = inst.name;
    if (inst.type.kind == VarType::Kind::Elementary)
      fail(e.position, model::in_quotes(inst.name) + " is not a block instance; '.' reads a block's output (docs/plc.md P.6)");
    if (inst.type.kind == VarType::Kind::Standard) {
      for (const PinInfo& p : block_pins(inst.type.block)) {
        if (!same_name(pin_name(p.pin), e.member)) continue;
        if (p.input) break;
        e.pin = p.pin;
        e.member = std::string(pin_name(p.pin));
        return p.type;
      }
      std::vector<std::string> outs;
      for (const PinInfo& p : block_pins(inst.type.block))
        if (!p.input) outs.emplace_back(pin_name(p.pin));
      fail(e.position, model::in_quotes(e.member) + " is not an output of " + std::string(block_name(inst.type.block)) +
                           model::did_you_mean(e.member, outs));
    }
    const Pou& block = *find_pou(program_, inst.type.user);
    const Variable* v = find_variable(block, e.member);
    if (!v || v->section != Section::Output)
      fail(e.position, model::in_quotes(e.member) + " is not a VAR_OUTPUT of " + model::in_quotes(block.name));
    e.member = v->name;
    return v->type.type;
  }

  Type unary(Expr& e, std::optional<Type> hint) {
    if (e.unary == UnaryOp::Not) {
      const Type t = check(e.args[0], Type::Bool);
      if (t != Type::Bool) fail(e.position, "NOT of a " + quoted_type(t) + " (NOT takes a BOOL; docs/plc.md P.5)");
      return t;
    }
    const Type t = check(e.args[0], hint);
    if (t == Type::Bool) fail(e.position, "'-' of a BOOL (docs/plc.md P.5)");
    return t;
  }

  // The one type of several operands: the first that is not an integer
  // literal sets it; all literals: the context's numeric type, else DINT.
  Type unify(std::vector<Expr*> xs, std::optional<Type> hint, Position at, std::string_view what) {
    std::optional<Type> t;
    for (Expr* x : xs)
      if (!adaptable(*x)) {
        t = check(*x, hint);
        break;
      }
    if (!t) t = hint && is_numeric(*hint) ? *hint : Type::Dint;
    for (Expr* x : xs) {
      const Type tx = check(*x, t);
      if (tx != *t)
        fail(at, "operands of " + std::string(what) + " have different types " + quoted_type(*t) + " and " +
                     quoted_type(tx) + " (no implicit conversion; docs/plc.md P.2)");
    }
    return *t;
  }

  Type binary(Expr& e, std::optional<Type> hint) {
    const BinaryOp op = e.binary;
    const std::string what = model::in_quotes(binary_text(op));
    if (op == BinaryOp::Or || op == BinaryOp::Xor || op == BinaryOp::And) {
      for (Expr& a : e.args)
        if (check(a, Type::Bool) != Type::Bool)
          fail(a.position, what + " takes BOOL operands, found " + quoted_type(a.type) + " (docs/plc.md P.5)");
      return Type::Bool;
    }
    const bool comparison = op == BinaryOp::Eq || op == BinaryOp::Ne || op == BinaryOp::Lt || op == BinaryOp::Le ||
                            op == BinaryOp::Gt || op == BinaryOp::Ge;
    const Type t = unify({&e.args[0], &e.args[1]}, comparison ? std::nullopt : hint, e.position, what);
    if (comparison) {
      if (t == Type::Bool && op != BinaryOp::Eq && op != BinaryOp::Ne)
        fail(e.position, what + " of BOOL values (compare BOOLs with = or <>; docs/plc.md P.5)");
      return Type::Bool;
    }
    const bool ok = op == BinaryOp::Add || op == BinaryOp::Sub ? is_numeric(t) || t == Type::Time
                    : op == BinaryOp::Mod                      ? is_integer(t)
                                                               : is_numeric(t);
    if (!ok) fail(e.position, what + " of " + quoted_type(t) + " values is not in the subset (docs/plc.md P.5)");
    if (op == BinaryOp::Div || op == BinaryOp::Mod) nonzero_constant(e.args[1], what);
    return t;
  }

  // Division only by a constant other than zero (P.5): the scan never divides by zero.
  void nonzero_constant(const Expr& d, const std::string& what) {
    const Expr* x = &d;
    bool is_zero = false;
    if (x->kind == Expr::Kind::Unary && x->unary == UnaryOp::Negate) x = &x->args[0];
    if (x->kind == Expr::Kind::Literal) {
      is_zero = x->literal.type == Type::Real ? x->literal.real == 0 : x->literal.integer == 0;
    } else if (x->kind == Expr::Kind::Variable && variable(x->name, x->position).section == Section::Constant) {
      const Literal& l = *variable(x->name, x->position).initial;
      is_zero = l.type == Type::Real ? l.real == 0 : l.integer == 0;
    } else {
      fail(d.position, "the divisor of " + what +
                           " must be a literal or a VAR CONSTANT (division by a variable is not in the subset; "
                           "docs/plc.md P.5)");
    }
    if (is_zero) fail(d.position, "division by zero (docs/plc.md P.5)");
  }

  Type call(Expr& e, std::optional<Type> hint) {
    const std::string name = std::string(function_name(e.function));
    auto arity = [&](std::size_t lo, std::size_t hi) {
      if (e.args.size() < lo || e.args.size() > hi)
        fail(e.position, name + " takes " + (lo == hi ? std::to_string(lo) : "at least " + std::to_string(lo)) +
                             " arguments, found " + std::to_string(e.args.size()));
    };
    std::vector<Expr*> xs;
    switch (e.function) {
      case Function::Min:
      case Function::Max:
      case Function::Limit: {
        if (e.function == Function::Limit) arity(3, 3);
        else arity(2, 64);
        for (Expr& a : e.args) xs.push_back(&a);
        const Type t = unify(xs, hint, e.position, name);
        if (!is_numeric(t) && t != Type::Time) fail(e.position, name + " of " + quoted_type(t) + " values (docs/plc.md P.5)");
        return t;
      }
      case Function::Abs: {
        arity(1, 1);
        const Type t = check(e.args[0], hint);
        if (!is_numeric(t)) fail(e.position, "ABS of a " + quoted_type(t) + " (docs/plc.md P.5)");
        return t;
      }
      case Function::BoolToInt:
      case Function::BoolToDint:
      case Function::IntToDint:
      case Function::DintToInt:
      case Function::IntToReal:
      case Function::DintToReal: {
        arity(1, 1);
        const auto [from, to] = conversion(e.function);
        const Type t = check(e.args[0], from);
        if (t != from) fail(e.args[0].position, name + " takes a " + quoted_type(from) + ", found " + quoted_type(t));
        return to;
      }
      case Function::Sel: {
        arity(3, 3);
        if (check(e.args[0], Type::Bool) != Type::Bool)
          fail(e.args[0].position, "the selector G of SEL must be a BOOL (docs/plc.md P.5)");
        return unify({&e.args[1], &e.args[2]}, hint, e.position, name);
      }
    }
    return Type::Bool;
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
