// Inside the ST parser (parser.cpp, parse_statements.cpp, parse_expressions.cpp):
// the token cursor with its nesting guard (P.1.5), the words of the language,
// the expression grammar (P.5) and the statements (P.4) that the POUs and
// their declarations build on.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/text.hpp"
#include "plc/ast.hpp"
#include "plc/lexer.hpp"

namespace cemv::plc::parse {

// How deep expressions and statements may nest: the checker, the printer
// and both implementations walk the tree recursively (P.1.5).
constexpr int kMaxNesting = 128;

bool is_keyword(std::string_view word);
bool refused_function(std::string_view word);  // a standard function outside the subset
bool refused_type(std::string_view word);
bool refused_block(std::string_view word);
std::string upper(std::string_view word);

// The tokens of one text with the parser's questions about them.
class Cursor {
 public:
  Cursor(std::string_view text, const Origin& origin) : tokens_(text, origin), file_(origin.file) {}

 protected:
  TokenStream tokens_;
  std::string file_;
  int nesting_ = 0;     // open parentheses, unary operators, compound statements
  int last_depth_ = 0;  // the depth of the expression parsed last

  struct Nest {
    Cursor& p;
    Nest(Cursor& parser, Position at) : p(parser) {
      if (++p.nesting_ > kMaxNesting)
        p.fail(at, "nested more than " + std::to_string(kMaxNesting) + " levels deep (docs/plc.md P.1.5)");
    }
    ~Nest() { --p.nesting_; }
  };
  void deeper(int depth, Position at) {
    last_depth_ = depth;
    if (depth > kMaxNesting)
      fail(at, "an expression more than " + std::to_string(kMaxNesting) + " operators deep (docs/plc.md P.1.5)");
  }

  const Token& peek(std::size_t ahead = 0) { return tokens_.peek(ahead); }
  bool at(Tok k) { return peek().kind == k; }
  bool at_word(std::string_view w, std::size_t ahead = 0) {
    return peek(ahead).kind == Tok::Identifier && same_name(peek(ahead).text, w);
  }
  Token next() {
    Token t = peek();
    tokens_.advance();
    return t;
  }
  [[noreturn]] void fail(Position at, std::string what) const { refuse(file_, at, std::move(what)); }
  [[noreturn]] void unexpected(std::string_view wanted) {
    const Token& t = peek();
    fail(t.position, "expected " + std::string(wanted) + ", found " +
                         (t.kind == Tok::End ? std::string("the end of the text") : model::in_quotes(t.text)));
  }
  void expect(Tok k, std::string_view text) {
    if (!at(k)) unexpected(model::in_quotes(text));
    next();
  }
  void expect_word(std::string_view w) {
    if (!at_word(w)) unexpected(w);
    next();
  }
  std::string identifier(std::string_view what) {
    if (!at(Tok::Identifier) || is_keyword(peek().text)) unexpected(what);
    return next().text;
  }
};

// Expressions (P.5), precedence climbing over IEC 61131-3 Table 71.
class ExpressionParser : public Cursor {
 public:
  using Cursor::Cursor;

 protected:
  Expr expression();
  Expr unary();

 private:
  std::optional<BinaryOp> binary_at(int level);
  Expr binary_level(int level);
  Expr literal(Type type, std::int64_t integer, float real, Position pos);
  Expr primary();
  Expr function_call(const std::string& name, Position pos);
};

// Statements (P.4), each checked for its nesting (P.1.5).
class StatementParser : public ExpressionParser {
 public:
  using ExpressionParser::ExpressionParser;

 protected:
  std::vector<Statement> statement_list();

 private:
  Statement statement();
  void call_args(Statement& s);
  Statement if_statement();
  Statement case_statement();
  std::int64_t case_value();
  bool label_ahead();
  std::vector<Statement> case_body();
  Statement for_statement();
  Expr bound();
};

}  // namespace cemv::plc::parse
