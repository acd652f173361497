#include <algorithm>

#include "plc/parse_support.hpp"

namespace cemv::plc::parse {

// Precedence, lowest first (IEC 61131-3 Table 71): OR, XOR, AND/&,
// = <>, < > <= >=, + -, * / MOD, unary - NOT, primary.
Expr ExpressionParser::expression() { return binary_level(0); }

std::optional<BinaryOp> ExpressionParser::binary_at(int level) {
  const Token& t = peek();
  switch (level) {
    case 0: if (at_word("OR")) return BinaryOp::Or; break;
    case 1: if (at_word("XOR")) return BinaryOp::Xor; break;
    case 2: if (at_word("AND") || t.kind == Tok::Ampersand) return BinaryOp::And; break;
    case 3:
      if (t.kind == Tok::Eq) return BinaryOp::Eq;
      if (t.kind == Tok::Ne) return BinaryOp::Ne;
      break;
    case 4:
      if (t.kind == Tok::Lt) return BinaryOp::Lt;
      if (t.kind == Tok::Le) return BinaryOp::Le;
      if (t.kind == Tok::Gt) return BinaryOp::Gt;
      if (t.kind == Tok::Ge) return BinaryOp::Ge;
      break;
    case 5:
      if (t.kind == Tok::Plus) return BinaryOp::Add;
      if (t.kind == Tok::Minus) return BinaryOp::Sub;
      break;
    case 6:
      if (t.kind == Tok::Star) return BinaryOp::Mul;
      if (t.kind == Tok::Slash) return BinaryOp::Div;
      if (at_word("MOD")) return BinaryOp::Mod;
      break;
    default: break;
  }
  return std::nullopt;
}

Expr ExpressionParser::binary_level(int level) {
  if (level == 7) return unary();
  Expr left = binary_level(level + 1);
  int depth = last_depth_;
  while (auto op = binary_at(level)) {
    Expr e;
    e.kind = Expr::Kind::Binary;
    e.binary = *op;
    e.position = left.position;
    next();
    Expr right = binary_level(level + 1);
    deeper(1 + std::max(depth, last_depth_), e.position);
    depth = last_depth_;
    e.args.push_back(std::move(left));
    e.args.push_back(std::move(right));
    left = std::move(e);
  }
  if (at(Tok::Power)) fail(peek().position, "operator '**' is not in the subset (docs/plc.md P.5)");
  last_depth_ = depth;
  return left;
}

Expr ExpressionParser::unary() {
  const Position pos = peek().position;
  if (at(Tok::Minus) || at_word("NOT")) {
    const bool negate = at(Tok::Minus);
    next();
    Nest nest(*this, pos);
    Expr operand = unary();
    if (negate && operand.kind == Expr::Kind::Literal && operand.literal.type != Type::Bool &&
        operand.position == Position{pos.line, pos.column + 1}) {
      // `-5`, `-1.5`, `-T#5s` written together: a signed literal
      operand.literal.integer = -operand.literal.integer;
      operand.literal.real = -operand.literal.real;
      operand.position = pos;
      return operand;
    }
    Expr e;
    e.kind = Expr::Kind::Unary;
    e.unary = negate ? UnaryOp::Negate : UnaryOp::Not;
    e.position = pos;
    e.args.push_back(std::move(operand));
    deeper(last_depth_ + 1, pos);
    return e;
  }
  if (at(Tok::Plus)) fail(pos, "unary '+' is not in the subset (docs/plc.md P.5)");
  return primary();
}

Expr ExpressionParser::literal(Type type, std::int64_t integer, float real, Position pos) {
  Expr e;
  e.kind = Expr::Kind::Literal;
  e.position = pos;
  e.type = type;
  e.literal = Literal{type, integer, real};
  last_depth_ = 1;
  return e;
}

Expr ExpressionParser::primary() {
  const Token t = peek();
  const Position pos = t.position;
  switch (t.kind) {
    case Tok::Integer: next(); return literal(Type::Dint, t.integer, 0, pos);
    case Tok::Real: next(); return literal(Type::Real, 0, t.real, pos);
    case Tok::Time: next(); return literal(Type::Time, t.integer, 0, pos);
    case Tok::LParen: {
      next();
      Nest nest(*this, pos);
      Expr e = expression();
      expect(Tok::RParen, ")");
      return e;
    }
    case Tok::Identifier: break;
    default: unexpected("an expression");
  }
  if (at_word("TRUE") || at_word("FALSE")) {
    const bool v = at_word("TRUE");
    next();
    return literal(Type::Bool, v ? 1 : 0, 0, pos);
  }
  if (is_keyword(t.text)) unexpected("an expression");
  const std::string name = next().text;
  if (at(Tok::LParen)) return function_call(name, pos);
  Expr e;
  e.position = pos;
  e.name = name;
  e.kind = Expr::Kind::Variable;
  if (at(Tok::Dot)) {
    next();
    e.kind = Expr::Kind::Member;
    e.member = identifier("a block output after '.'");
  }
  if (at(Tok::LBracket)) fail(peek().position, "array indexing is not in the subset (docs/plc.md P.2)");
  if (at(Tok::Caret)) fail(peek().position, "pointer dereference is not in the subset (docs/plc.md P.2)");
  last_depth_ = 1;
  return e;
}

Expr ExpressionParser::function_call(const std::string& name, Position pos) {
  const auto f = function_from_name(name);
  if (!f) {
    if (refused_function(name))
      fail(pos, "function " + model::in_quotes(upper(name)) + " is not in the subset (docs/plc.md P.5)");
    fail(pos, "unknown function " + model::in_quotes(name) +
                  " (the subset has MIN, MAX, ABS, SEL, LIMIT; a block instance is called as a statement; "
                  "docs/plc.md P.5)");
  }
  Expr e;
  e.kind = Expr::Kind::Call;
  e.function = *f;
  e.position = pos;
  next();  // (
  Nest nest(*this, pos);
  int depth = 0;
  if (!at(Tok::RParen)) {
    for (;;) {
      if (at(Tok::Identifier) && (peek(1).kind == Tok::Assign || peek(1).kind == Tok::Arrow))
        fail(peek().position, "named arguments of a function are not in the subset (docs/plc.md P.5)");
      e.args.push_back(expression());
      depth = std::max(depth, last_depth_);
      if (!at(Tok::Comma)) break;
      next();
    }
  }
  expect(Tok::RParen, ")");
  deeper(depth + 1, pos);
  return e;
}

}  // namespace cemv::plc::parse
