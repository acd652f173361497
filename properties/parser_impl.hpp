// Private to properties/: the recursive-descent parser behind parse_properties.
// Property-level rules are in parser.cpp, expressions in expressions.cpp.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "properties/ast.hpp"
#include "properties/lexer.hpp"
#include "properties/names.hpp"

namespace cemv::properties {

class Parser {
 public:
  Parser(std::string_view text, const model::Matrix& m, const std::string& file);
  PropertyFile parse_file();

 private:
  // ---- tokens
  const Token& peek(std::size_t ahead = 0) const;
  const Token& next();
  bool symbol(const char* s, std::size_t ahead = 0) const;
  bool keyword(const char* k, std::size_t ahead = 0) const;
  bool accept_symbol(const char* s);
  void expect_symbol(const char* s);
  void expect_keyword(const char* k);
  [[noreturn]] void fail_expected(const std::string& expected) const;
  [[noreturn]] void fail_at(SourceLoc loc, const std::string& what) const;

  // ---- properties (parser.cpp)
  Property property();
  std::string property_name();
  Assumption assumption();
  void attach_expect(Property& p, int first_line, int last_line);
  // A duration in cycles: "500 ms", "2 s", "2.5s", "3 cycles".
  int duration();

  // ---- expressions (expressions.cpp)
  Expr bool_expression();  // an expression that must be Boolean
  Expr expression();
  Expr implies_level();
  Expr or_level();
  Expr and_level();
  Expr unary_level();
  Expr comparison();
  struct Operand {
    Expr expr;
    const Token* literal = nullptr;  // a number, or a word/identifier that may be a voting name
  };
  Operand operand();
  Expr require_bool(Expr e, SourceLoc loc, const std::string& found);
  Expr combine(const Operand& a, const Token& op, const Operand& b);
  Expr call(const Token& name);
  Expr issued();
  Expr aggregate(const Token& name);
  std::vector<Expr> expand(const std::vector<Element>& set, const std::string& var);
  std::vector<Element> element_set();
  Element element_ref();          // cause[X], effect[X] or a bound variable
  Expr element_member(const Element& e, SourceLoc loc);
  TagRef tag_operand();
  Expr tag_value(const TagRef& t, SourceLoc loc);
  const Element* variable(const std::string& name) const;
  static bool is_reserved(const std::string& word);

  std::string file_;
  MatrixNames names_;
  LexResult lex_;
  std::size_t pos_ = 0;
  std::vector<std::pair<std::string, Element>> scope_;  // aggregate variables, innermost last
  std::vector<std::string>* notes_ = nullptr;          // where duration notes go
  std::size_t expanded_ = 0;                           // aggregate bodies parsed so far
};

}  // namespace cemv::properties
