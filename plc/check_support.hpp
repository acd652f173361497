// Inside the checker (check.cpp, check_expressions.cpp): the names of a POU
// and the types of expressions (P.2.5, P.5, P.7), which the declarations and
// statements build on.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "model/text.hpp"
#include "plc/ast.hpp"
#include "plc/lexer.hpp"

namespace cemv::plc::checking {

inline bool is_integer(Type t) { return t == Type::Int || t == Type::Dint; }
inline bool is_numeric(Type t) { return is_integer(t) || t == Type::Real; }
inline std::string quoted_type(Type t) { return std::string(type_name(t)); }
std::pair<std::int64_t, std::int64_t> range_of(Type t);

class ExpressionChecker {
 public:
  explicit ExpressionChecker(Program& p) : program_(p) {}

 protected:
  Program& program_;
  Pou* pou_ = nullptr;                      // the POU being checked
  std::vector<std::string> loop_variables_;  // of the FOR loops around the statement

  [[noreturn]] void fail(Position at, std::string what) const { refuse(program_.file, at, std::move(what)); }

  // A literal of the type `want` (P.2.5): an integer literal takes a numeric type.
  Literal fit_literal(Literal l, Type want, Position at) const;

  Variable& variable(const std::string& name, Position at);
  Variable& elementary(const std::string& name, Position at);  // not a block instance
  void assignable(const Variable& v, Position at);

  // Resolves and types `e` in the POU; `hint` is the type the context asks for.
  Type check(Expr& e, std::optional<Type> hint);

 private:
  Type member(Expr& e);
  Type unary(Expr& e, std::optional<Type> hint);
  Type unify(std::vector<Expr*> xs, std::optional<Type> hint, Position at, std::string_view what);
  Type binary(Expr& e, std::optional<Type> hint);
  void nonzero_constant(const Expr& d, const std::string& what);
  Type call(Expr& e, std::optional<Type> hint);
};

}  // namespace cemv::plc::checking
