// Expressions of the property language (docs/properties.md, "Expressions"):
// precedence from loosest to tightest  iff/<->,  implies/-> (right-assoc.),
// or, and, not, comparisons, operands.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "properties/parser_impl.hpp"

namespace cemv::properties {

namespace {

using Kind = Expr::Kind;

// Nesting guard: a hostile file must not overflow the stack.
constexpr int kMaxDepth = 200;

std::string type_text(ExprType t) {
  switch (t) {
    case ExprType::Bool: return "a Boolean";
    case ExprType::Int: return "an integer";
    case ExprType::Float: return "an analog value";
    case ExprType::Voting: return "a voting";
  }
  return "?";
}

bool is_integer_text(const std::string& s) { return s.find_first_of(".eE") == std::string::npos; }

struct DepthGuard {
  explicit DepthGuard(int& d) : d_(d) { ++d_; }
  ~DepthGuard() { --d_; }
  int& d_;
};
thread_local int depth = 0;

}  // namespace

bool Parser::is_reserved(const std::string& w) {
  static const char* const kWords[] = {
      "not",   "and",    "or",     "implies", "iff",   "true",      "false",    "prev",  "rose",
      "fell",  "held",   "within", "since",   "bad",   "good",      "issued",   "count", "any",
      "all",   "in",     "cause",  "effect",  "sif",   "causes",    "effects",  "property",
      "assume", "always", "never", "reachable", "whenever", "then"};
  for (const char* k : kWords)
    if (w == k) return true;
  return false;
}

const Element* Parser::variable(const std::string& name) const {
  for (auto it = scope_.rbegin(); it != scope_.rend(); ++it)
    if (it->first == name) return &it->second;
  return nullptr;
}

Expr Parser::require_bool(Expr e, SourceLoc loc, const std::string& found) {
  if (e.type != ExprType::Bool) fail_at(loc, "expected a Boolean expression, found " + found);
  return e;
}

Expr Parser::bool_expression() {
  SourceLoc loc = peek().loc;
  Expr e = expression();
  return require_bool(std::move(e), loc, type_text(e.type) + " expression");
}

Expr Parser::expression() {
  DepthGuard guard(depth);
  if (depth > kMaxDepth) fail_at(peek().loc, "expression nested deeper than " + std::to_string(kMaxDepth) + " levels");
  SourceLoc loc = peek().loc;
  Expr left = implies_level();
  while (keyword("iff") || symbol("<->")) {
    std::string op = next().text;
    require_bool(left, loc, type_text(left.type) + " on the left of '" + op + "'");
    SourceLoc rloc = peek().loc;
    Expr right = implies_level();
    require_bool(right, rloc, type_text(right.type) + " on the right of '" + op + "'");
    left = Expr::binary(Kind::Iff, std::move(left), std::move(right));
    left.loc = loc;
  }
  return left;
}

Expr Parser::implies_level() {
  SourceLoc loc = peek().loc;
  Expr left = or_level();
  if (!keyword("implies") && !symbol("->")) return left;
  std::string op = next().text;
  require_bool(left, loc, type_text(left.type) + " on the left of '" + op + "'");
  SourceLoc rloc = peek().loc;
  Expr right = implies_level();  // right-associative: a -> b -> c = a -> (b -> c)
  require_bool(right, rloc, type_text(right.type) + " on the right of '" + op + "'");
  Expr e = Expr::binary(Kind::Implies, std::move(left), std::move(right));
  e.loc = loc;
  return e;
}

Expr Parser::or_level() {
  SourceLoc loc = peek().loc;
  Expr first = and_level();
  if (!keyword("or")) return first;
  require_bool(first, loc, type_text(first.type) + " on the left of 'or'");
  std::vector<Expr> args;
  args.push_back(std::move(first));
  while (keyword("or")) {
    next();
    SourceLoc aloc = peek().loc;
    Expr a = and_level();
    args.push_back(require_bool(std::move(a), aloc, type_text(a.type) + " on the right of 'or'"));
  }
  Expr e = Expr::nary(Kind::Or, std::move(args));
  e.loc = loc;
  return e;
}

Expr Parser::and_level() {
  SourceLoc loc = peek().loc;
  Expr first = unary_level();
  if (!keyword("and")) return first;
  require_bool(first, loc, type_text(first.type) + " on the left of 'and'");
  std::vector<Expr> args;
  args.push_back(std::move(first));
  while (keyword("and")) {
    next();
    SourceLoc aloc = peek().loc;
    Expr a = unary_level();
    args.push_back(require_bool(std::move(a), aloc, type_text(a.type) + " on the right of 'and'"));
  }
  Expr e = Expr::nary(Kind::And, std::move(args));
  e.loc = loc;
  return e;
}

Expr Parser::unary_level() {
  if (!keyword("not")) return comparison();
  SourceLoc loc = next().loc;
  DepthGuard guard(depth);
  if (depth > kMaxDepth) fail_at(loc, "expression nested deeper than " + std::to_string(kMaxDepth) + " levels");
  SourceLoc aloc = peek().loc;
  Expr a = unary_level();
  Expr e = Expr::unary(Kind::Not, require_bool(std::move(a), aloc, type_text(a.type) + " after 'not'"));
  e.loc = loc;
  return e;
}

Expr Parser::comparison() {
  SourceLoc loc = peek().loc;
  Operand left = operand();
  static const char* const kOps[] = {"==", "!=", "<=", ">=", "<", ">"};
  for (const char* op : kOps) {
    if (!symbol(op)) continue;
    const Token& op_token = next();
    Operand right = operand();
    Expr e = combine(left, op_token, right);
    e.loc = loc;
    return e;
  }
  if (left.literal && left.literal->kind == Token::Kind::Number)
    fail_at(loc, "expected a Boolean expression, found number " + left.literal->text);
  if (left.literal && left.literal->kind == Token::Kind::Word)
    fail_at(loc, "expected an expression, found " + describe(*left.literal));
  left.expr.loc = loc;
  return left.expr;
}

// Comparisons, typed by their operands (docs/properties.md, "Comparisons").
Expr Parser::combine(const Operand& a, const Token& op_token, const Operand& b) {
  const std::string& op = op_token.text;
  CompareOp cmp = op == "==" ? CompareOp::Eq : op == "!=" ? CompareOp::Ne : op == "<" ? CompareOp::Lt
                  : op == "<=" ? CompareOp::Le : op == ">" ? CompareOp::Gt : CompareOp::Ge;
  auto number = [](const Operand& o) { return o.literal && o.literal->kind == Token::Kind::Number; };
  auto as_float = [&](const Token& t) {
    float v = std::strtof(t.text.c_str(), nullptr);  // round to nearest, as the scenario format stores REALs
    if (!std::isfinite(v)) fail_at(t.loc, "number " + t.text + " is outside the single-precision range");
    return Expr::real(v);
  };
  auto as_int = [&](const Token& t) {
    std::int64_t v = 0;
    auto [p, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
    if (!is_integer_text(t.text) || ec != std::errc() || p != t.text.data() + t.text.size())
      fail_at(t.loc, "expected an integer, found number " + t.text);
    return Expr::integer(v);
  };
  auto as_voting = [&](const Operand& o) {
    std::optional<model::Voting> v;
    if (o.literal) v = model::voting_from_string(o.literal->text);
    if (!v) {
      SourceLoc loc = o.literal ? o.literal->loc : o.expr.loc;
      std::string found = o.literal ? describe(*o.literal) : type_text(o.expr.type);
      fail_at(loc, "expected a voting (1oo1, 1oo2, 2oo2, 1oo3, 2oo3, 3oo3, bypass), found " + found);
    }
    if (cmp != CompareOp::Eq && cmp != CompareOp::Ne)
      fail_at(op_token.loc, "votings compare only with '==' and '!=', found '" + op + "'");
    return Expr::voting(*v);
  };
  if (number(a) && number(b)) fail_at(op_token.loc, "comparison of two numbers (one side must be a signal)");
  if (a.expr.type == ExprType::Voting && !a.literal) return Expr::compare(cmp, a.expr, as_voting(b));
  if (b.expr.type == ExprType::Voting && !b.literal) return Expr::compare(cmp, as_voting(a), b.expr);
  if (number(b) && a.expr.type == ExprType::Float) return Expr::compare(cmp, a.expr, as_float(*b.literal));
  if (number(a) && b.expr.type == ExprType::Float) return Expr::compare(cmp, as_float(*a.literal), b.expr);
  if (number(b) && a.expr.type == ExprType::Int) return Expr::compare(cmp, a.expr, as_int(*b.literal));
  if (number(a) && b.expr.type == ExprType::Int) return Expr::compare(cmp, as_int(*a.literal), b.expr);
  bool a_signal = !a.literal || a.literal->kind == Token::Kind::Identifier || a.literal->kind == Token::Kind::String;
  bool b_signal = !b.literal || b.literal->kind == Token::Kind::Identifier || b.literal->kind == Token::Kind::String;
  if (a_signal && b_signal && a.expr.type == ExprType::Int && b.expr.type == ExprType::Int)
    return Expr::compare(cmp, a.expr, b.expr);
  if (a_signal && b_signal && a.expr.type == ExprType::Bool && b.expr.type == ExprType::Bool &&
      (cmp == CompareOp::Eq || cmp == CompareOp::Ne)) {
    Expr iff = Expr::binary(Kind::Iff, a.expr, b.expr);
    return cmp == CompareOp::Eq ? iff : Expr::unary(Kind::Not, std::move(iff));
  }
  auto what = [&](const Operand& o) {
    return o.literal && !(o.literal->kind == Token::Kind::Identifier || o.literal->kind == Token::Kind::String)
               ? describe(*o.literal) : type_text(o.expr.type);
  };
  if (a.expr.type == ExprType::Float && b.expr.type == ExprType::Float && a_signal && b_signal)
    fail_at(op_token.loc, "two analog values cannot be compared with each other (compare each with a number)");
  fail_at(op_token.loc, "cannot compare " + what(a) + " with " + what(b) + " using '" + op + "'");
}

Parser::Operand Parser::operand() {
  const Token& t = peek();
  Operand o;
  o.expr.loc = t.loc;
  switch (t.kind) {
    case Token::Kind::Number:
    case Token::Kind::Word:
      o.literal = &next();
      o.expr.type = ExprType::Int;  // placeholder; combine() decides
      return o;
    case Token::Kind::String: {
      o.literal = &t;
      TagRef ref = tag_operand();
      o.expr = tag_value(ref, t.loc);
      return o;
    }
    case Token::Kind::Symbol:
      if (accept_symbol("(")) {
        o.expr = expression();
        expect_symbol(")");
        return o;
      }
      fail_expected("an expression");
    case Token::Kind::End:
      fail_expected("an expression");
    case Token::Kind::Identifier:
      break;
  }
  if (t.text == "true" || t.text == "false") {
    next();
    o.expr = Expr::boolean(t.text == "true");
    o.expr.loc = t.loc;
    return o;
  }
  if (symbol("(", 1) && (t.text == "prev" || t.text == "rose" || t.text == "fell" || t.text == "held" ||
                         t.text == "within" || t.text == "since" || t.text == "bad" || t.text == "good" ||
                         t.text == "issued" || t.text == "count" || t.text == "any" || t.text == "all")) {
    const Token& name = next();
    o.expr = call(name);
    o.expr.loc = name.loc;
    return o;
  }
  if (t.text == "cause" || t.text == "effect" || (variable(t.text) && variable(t.text)->kind != Element::Kind::Tag)) {
    Element e = element_ref();
    o.expr = element_member(e, t.loc);
    return o;
  }
  if (is_reserved(t.text)) fail_expected("an expression");
  // A voting name such as `bypass` is only meaningful against a voting field: keep the token.
  o.literal = &t;
  if (model::voting_from_string(t.text) && !names_.inputs().find(t.text)) {
    next();
    o.expr.type = ExprType::Voting;
    return o;
  }
  TagRef ref = tag_operand();
  o.expr = tag_value(ref, t.loc);
  return o;
}

}  // namespace cemv::properties
