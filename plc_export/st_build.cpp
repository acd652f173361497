#include "plc_export/st_build.hpp"

namespace cemv::plc_export::st {

using plc::Expr;

Expr var(const std::string& name, plc::Type type) {
  Expr e;
  e.kind = Expr::Kind::Variable;
  e.name = name;
  e.type = type;
  return e;
}

Expr member(const std::string& instance, plc::Pin pin, plc::Type type) {
  Expr e;
  e.kind = Expr::Kind::Member;
  e.name = instance;
  e.member = std::string(plc::pin_name(pin));
  e.pin = pin;
  e.type = type;
  return e;
}

namespace {
Expr literal(plc::Literal l) {
  Expr e;
  e.kind = Expr::Kind::Literal;
  e.type = l.type;
  e.literal = l;
  return e;
}
}  // namespace

Expr boolean(bool value) { return literal({plc::Type::Bool, value ? 1 : 0, 0.0f}); }
Expr real(float value) { return literal({plc::Type::Real, 0, value}); }
Expr integer(std::int64_t value, plc::Type type) { return literal({type, value, 0.0f}); }
Expr time_ms(std::int64_t ms) { return literal({plc::Type::Time, ms, 0.0f}); }

bool is_true(const Expr& e) { return e.kind == Expr::Kind::Literal && e.type == plc::Type::Bool && e.literal.integer; }
bool is_false(const Expr& e) {
  return e.kind == Expr::Kind::Literal && e.type == plc::Type::Bool && !e.literal.integer;
}

Expr not_(Expr a) {
  if (a.kind == Expr::Kind::Literal && a.type == plc::Type::Bool) return boolean(!a.literal.integer);
  if (a.kind == Expr::Kind::Unary && a.unary == plc::UnaryOp::Not) return std::move(a.args[0]);
  Expr e;
  e.kind = Expr::Kind::Unary;
  e.unary = plc::UnaryOp::Not;
  e.type = plc::Type::Bool;
  e.args.push_back(std::move(a));
  return e;
}

Expr binary(plc::BinaryOp op, Expr a, Expr b, plc::Type result) {
  Expr e;
  e.kind = Expr::Kind::Binary;
  e.binary = op;
  e.type = result;
  e.args.push_back(std::move(a));
  e.args.push_back(std::move(b));
  return e;
}

Expr and_(Expr a, Expr b) {
  if (is_false(a) || is_false(b)) return boolean(false);
  if (is_true(a)) return b;
  if (is_true(b)) return a;
  return binary(plc::BinaryOp::And, std::move(a), std::move(b), plc::Type::Bool);
}

Expr or_(Expr a, Expr b) {
  if (is_true(a) || is_true(b)) return boolean(true);
  if (is_false(a)) return b;
  if (is_false(b)) return a;
  return binary(plc::BinaryOp::Or, std::move(a), std::move(b), plc::Type::Bool);
}

Expr all(std::vector<Expr> terms) {
  Expr out = boolean(true);
  for (Expr& t : terms) out = and_(std::move(out), std::move(t));
  return out;
}

Expr any(std::vector<Expr> terms) {
  Expr out = boolean(false);
  for (Expr& t : terms) out = or_(std::move(out), std::move(t));
  return out;
}

Expr sel(Expr g, Expr in0, Expr in1, plc::Type type) {
  Expr e;
  e.kind = Expr::Kind::Call;
  e.function = plc::Function::Sel;
  e.type = type;
  e.args.push_back(std::move(g));
  e.args.push_back(std::move(in0));
  e.args.push_back(std::move(in1));
  return e;
}

plc::Statement assign(const std::string& target, Expr value, std::string comment) {
  plc::Statement s;
  s.kind = plc::Statement::Kind::Assign;
  s.target = target;
  s.value = std::move(value);
  s.comment = std::move(comment);
  return s;
}

plc::Statement if_chain(std::vector<plc::Branch> branches, std::vector<plc::Statement> else_body,
                        std::string comment) {
  plc::Statement s;
  s.kind = plc::Statement::Kind::If;
  s.branches = std::move(branches);
  s.has_else = !else_body.empty();
  s.else_body = std::move(else_body);
  s.comment = std::move(comment);
  return s;
}

plc::Statement if_(Expr condition, std::vector<plc::Statement> then_body, std::string comment) {
  return if_chain({plc::Branch{std::move(condition), std::move(then_body)}}, {}, std::move(comment));
}

plc::Statement if_else(Expr condition, std::vector<plc::Statement> then_body, std::vector<plc::Statement> else_body,
                       std::string comment) {
  return if_chain({plc::Branch{std::move(condition), std::move(then_body)}}, std::move(else_body),
                  std::move(comment));
}

plc::Statement call(const std::string& instance, std::vector<std::pair<plc::Pin, Expr>> inputs, std::string comment) {
  plc::Statement s;
  s.kind = plc::Statement::Kind::Call;
  s.target = instance;
  for (auto& [pin, value] : inputs) {
    plc::CallArg a;
    a.name = std::string(plc::pin_name(pin));
    a.pin = pin;
    a.value = std::move(value);
    s.args.push_back(std::move(a));
  }
  s.comment = std::move(comment);
  return s;
}

plc::Variable variable(const std::string& name, plc::Section section, plc::Type type, std::string comment) {
  plc::Variable v;
  v.name = name;
  v.section = section;
  v.type.kind = plc::VarType::Kind::Elementary;
  v.type.type = type;
  v.comment = std::move(comment);
  return v;
}

plc::Variable block(const std::string& name, plc::StandardBlock b, std::string comment) {
  plc::Variable v;
  v.name = name;
  v.section = plc::Section::Local;
  v.type.kind = plc::VarType::Kind::Standard;
  v.type.block = b;
  v.comment = std::move(comment);
  return v;
}

}  // namespace cemv::plc_export::st
