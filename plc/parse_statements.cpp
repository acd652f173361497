// Statements (P.4): assignments, block calls, IF, CASE and FOR with constant
// bounds; every other statement refused at its keyword.
#include "model/text.hpp"
#include "plc/parse_support.hpp"

namespace cemv::plc::parse {

std::vector<Statement> StatementParser::statement_list() {
  std::vector<Statement> out;
  for (;;) {
    if (at(Tok::Semicolon)) {  // the empty statement
      next();
      continue;
    }
    if (!at(Tok::Identifier) || at_word("END_IF") || at_word("ELSIF") || at_word("ELSE") ||
        at_word("END_CASE") || at_word("END_FOR") || at_word("END_PROGRAM") || at_word("END_FUNCTION_BLOCK"))
      return out;
    if (is_keyword(peek().text) && !at_word("IF") && !at_word("CASE") && !at_word("FOR")) {
      if (at_word("WHILE") || at_word("REPEAT") || at_word("RETURN") || at_word("EXIT") || at_word("CONTINUE") ||
          at_word("JMP"))
        fail(peek().position, "statement " + upper(peek().text) + " is not in the subset (docs/plc.md P.4)");
      return out;
    }
    out.push_back(statement());
  }
}

Statement StatementParser::statement() {
  Nest nest(*this, peek().position);
  if (at_word("IF")) return if_statement();
  if (at_word("CASE")) return case_statement();
  if (at_word("FOR")) return for_statement();
  Statement s;
  s.position = peek().position;
  s.target = identifier("a statement");
  if (at(Tok::Dot)) {
    next();
    const std::string member = at(Tok::Identifier) ? peek().text : "";
    fail(s.position, "assignment to " + model::in_quotes(s.target + "." + member) +
                         " is not in the subset: pass a block's inputs in its call (docs/plc.md P.4)");
  }
  if (at(Tok::LBracket)) fail(peek().position, "array indexing is not in the subset (docs/plc.md P.2)");
  if (at(Tok::Caret)) fail(peek().position, "pointer dereference is not in the subset (docs/plc.md P.2)");
  if (at(Tok::Assign)) {
    next();
    s.kind = Statement::Kind::Assign;
    s.value = expression();
  } else if (at(Tok::LParen)) {
    if (function_from_name(s.target) || refused_function(s.target))
      fail(s.position, "a function call is not a statement; assign its result (docs/plc.md P.4)");
    s.kind = Statement::Kind::Call;
    call_args(s);
  } else {
    unexpected("':=' or '(' after " + model::in_quotes(s.target));
  }
  expect(Tok::Semicolon, ";");
  return s;
}

void StatementParser::call_args(Statement& s) {
  next();  // (
  if (!at(Tok::RParen)) {
    for (;;) {
      CallArg a;
      a.position = peek().position;
      if (!(at(Tok::Identifier) && (peek(1).kind == Tok::Assign || peek(1).kind == Tok::Arrow)))
        fail(a.position, "a block call names each parameter (`IN := x`, `Q => y`); positional arguments are not in "
                         "the subset (docs/plc.md P.4)");
      if (at_word("NOT") || is_keyword(peek().text)) unexpected("a parameter name");
      a.name = next().text;
      a.output = next().kind == Tok::Arrow;
      if (a.output) {
        a.value.position = peek().position;
        a.value.kind = Expr::Kind::Variable;
        a.value.name = identifier("a variable");
      } else {
        a.value = expression();
      }
      s.args.push_back(std::move(a));
      if (!at(Tok::Comma)) break;
      next();
    }
  }
  expect(Tok::RParen, ")");
}

Statement StatementParser::if_statement() {
  Statement s;
  s.kind = Statement::Kind::If;
  s.position = next().position;  // IF
  for (;;) {
    Branch b;
    b.condition = expression();
    expect_word("THEN");
    b.body = statement_list();
    s.branches.push_back(std::move(b));
    if (at_word("ELSIF")) {
      next();
      continue;
    }
    break;
  }
  if (at_word("ELSE")) {
    next();
    s.has_else = true;
    s.else_body = statement_list();
  }
  expect_word("END_IF");
  expect(Tok::Semicolon, ";");
  return s;
}

std::int64_t StatementParser::case_value() {
  bool negative = false;
  const Position pos = peek().position;
  if (at(Tok::Minus)) {
    next();
    negative = true;
  }
  if (!at(Tok::Integer))
    fail(pos, "a CASE label must be an integer literal or a range `a..b` (docs/plc.md P.4)");
  const std::int64_t v = next().integer;
  return negative ? -v : v;
}

bool StatementParser::label_ahead() {  // `1:`, `-1:`, `1,`, `1..`
  std::size_t k = at(Tok::Minus) ? 1 : 0;
  if (peek(k).kind != Tok::Integer) return false;
  const Tok after = peek(k + 1).kind;
  return after == Tok::Colon || after == Tok::Comma || after == Tok::DotDot;
}

Statement StatementParser::case_statement() {
  Statement s;
  s.kind = Statement::Kind::Case;
  s.position = next().position;  // CASE
  s.value = expression();
  expect_word("OF");
  while (label_ahead()) {
    CaseArm arm;
    arm.position = peek().position;
    for (;;) {
      CaseRange r;
      r.low = r.high = case_value();
      if (at(Tok::DotDot)) {
        next();
        r.high = case_value();
      }
      arm.labels.push_back(r);
      if (!at(Tok::Comma)) break;
      next();
    }
    expect(Tok::Colon, ":");
    arm.body = case_body();
    s.arms.push_back(std::move(arm));
  }
  if (s.arms.empty() && !at_word("ELSE")) {
    if (at(Tok::Identifier) && !is_keyword(peek().text))
      fail(peek().position, "a CASE label must be an integer literal or a range `a..b` (docs/plc.md P.4)");
    unexpected("a CASE label");
  }
  if (at_word("ELSE")) {
    next();
    s.has_else = true;
    s.else_body = case_body();
  }
  if (!at_word("END_CASE") && at(Tok::Identifier) && peek(1).kind == Tok::Colon)
    fail(peek().position, "a CASE label must be an integer literal or a range `a..b` (docs/plc.md P.4)");
  expect_word("END_CASE");
  expect(Tok::Semicolon, ";");
  return s;
}

std::vector<Statement> StatementParser::case_body() {
  std::vector<Statement> out;
  for (;;) {
    if (at(Tok::Semicolon)) {
      next();
      continue;
    }
    if (label_ahead() || !at(Tok::Identifier) || at_word("ELSE") || at_word("END_CASE")) return out;
    if (is_keyword(peek().text) && !at_word("IF") && !at_word("CASE") && !at_word("FOR")) {
      auto rest = statement_list();  // refuses WHILE etc., else returns empty
      if (rest.empty()) return out;
    }
    out.push_back(statement());
  }
}

Expr StatementParser::bound() {
  const Position pos = peek().position;
  Expr e = unary();
  const bool constant = e.kind == Expr::Kind::Literal || e.kind == Expr::Kind::Variable ||
                        (e.kind == Expr::Kind::Unary && e.unary == UnaryOp::Negate &&
                         e.args[0].kind == Expr::Kind::Variable);
  if (!constant || at(Tok::Plus) || at(Tok::Minus) || at(Tok::Star) || at(Tok::Slash) || at_word("MOD"))
    fail(pos, "FOR bounds must be constants (a literal or a VAR CONSTANT) (docs/plc.md P.4)");
  return e;
}

Statement StatementParser::for_statement() {
  Statement s;
  s.kind = Statement::Kind::For;
  s.position = next().position;  // FOR
  s.target = identifier("the FOR variable");
  expect(Tok::Assign, ":=");
  s.value = bound();
  expect_word("TO");
  s.limit = bound();
  if (at_word("BY")) {
    next();
    s.step = bound();
  } else {
    s.step.kind = Expr::Kind::Literal;
    s.step.literal = Literal{Type::Dint, 1, 0};
    s.step.type = Type::Dint;
    s.step.position = s.position;
  }
  expect_word("DO");
  s.body = statement_list();
  expect_word("END_FOR");
  expect(Tok::Semicolon, ";");
  return s;
}

}  // namespace cemv::plc::parse
