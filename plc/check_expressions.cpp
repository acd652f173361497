#include "plc/check_support.hpp"

#include <algorithm>
#include <limits>

namespace cemv::plc::checking {

std::pair<std::int64_t, std::int64_t> range_of(Type t) {
  if (t == Type::Int) return {std::numeric_limits<std::int16_t>::min(), std::numeric_limits<std::int16_t>::max()};
  return {std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()};
}

namespace {

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
      return std::all_of(e.args.begin(), e.args.end(), adaptable);
    default: return false;
  }
}

// Only the field of its type is set: `integer` (0 or 1 for a BOOL) or `real`.
Literal canonical(Literal l) {
  if (l.type == Type::Real) l.integer = 0;
  else l.real = 0;
  if (l.type == Type::Bool) l.integer = l.integer != 0;
  return l;
}

}  // namespace

Literal ExpressionChecker::fit_literal(Literal l, Type want, Position at) const {
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

Variable& ExpressionChecker::variable(const std::string& name, Position at) {
  for (Variable& v : pou_->variables)
    if (same_name(v.name, name)) return v;
  std::vector<std::string> names;
  for (const Variable& v : pou_->variables) names.push_back(v.name);
  fail(at, "undeclared variable " + model::in_quotes(name) + model::did_you_mean(name, names) + " in " +
               model::in_quotes(pou_->name));
}

Variable& ExpressionChecker::elementary(const std::string& name, Position at) {
  Variable& v = variable(name, at);
  if (v.type.kind != VarType::Kind::Elementary)
    fail(at, "block instance " + model::in_quotes(v.name) + " used as a value; read one of its outputs, e.g. " +
                 v.name + ".Q");
  return v;
}

void ExpressionChecker::assignable(const Variable& v, Position at) {
  if (v.section == Section::Input)
    fail(at, "assignment to the input " + model::in_quotes(v.name) + " (VAR_INPUT is read-only; docs/plc.md P.3)");
  if (v.section == Section::Constant)
    fail(at, "assignment to the constant " + model::in_quotes(v.name) + " (docs/plc.md P.3)");
  for (const std::string& l : loop_variables_)
    if (l == v.name) fail(at, "assignment to the FOR variable " + model::in_quotes(v.name) + " inside its loop (docs/plc.md P.4)");
}


Type ExpressionChecker::check(Expr& e, std::optional<Type> hint) {
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

Type ExpressionChecker::member(Expr& e) {
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

Type ExpressionChecker::unary(Expr& e, std::optional<Type> hint) {
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
Type ExpressionChecker::unify(std::vector<Expr*> xs, std::optional<Type> hint, Position at, std::string_view what) {
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

Type ExpressionChecker::binary(Expr& e, std::optional<Type> hint) {
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
void ExpressionChecker::nonzero_constant(const Expr& d, const std::string& what) {
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

Type ExpressionChecker::call(Expr& e, std::optional<Type> hint) {
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
    case Function::Sel: {
      arity(3, 3);
      if (check(e.args[0], Type::Bool) != Type::Bool)
        fail(e.args[0].position, "the selector G of SEL must be a BOOL (docs/plc.md P.5)");
      return ExpressionChecker::unify({&e.args[1], &e.args[2]}, hint, e.position, name);
    }
  }
  return Type::Bool;
}

}  // namespace cemv::plc::checking
