// Expressions of one scan as Z3 terms (docs/plc.md "The program as a
// transition system": types, operators, standard functions).
#include <cctype>

#include "plc_encoder/symbolic.hpp"

namespace cemv::plc_encoder {

namespace {

std::string upper(std::string s) {
  for (auto& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return s;
}

bool is_real(const z3::expr& e) { return e.is_fpa(); }

z3::expr fp(z3::context& c, Z3_ast a) { return z3::expr(c, a); }

z3::expr less(z3::context& c, const z3::expr& a, const z3::expr& b) {
  return is_real(a) ? fp(c, Z3_mk_fpa_lt(c, a, b)) : z3::slt(a, b);
}
z3::expr less_eq(z3::context& c, const z3::expr& a, const z3::expr& b) {
  return is_real(a) ? fp(c, Z3_mk_fpa_leq(c, a, b)) : z3::sle(a, b);
}
z3::expr equal(z3::context& c, const z3::expr& a, const z3::expr& b) {
  return is_real(a) ? fp(c, Z3_mk_fpa_eq(c, a, b)) : a == b;  // IEEE: NaN equals nothing
}

}  // namespace

Scan::Scan(z3::context& ctx, const plc::Program& program, std::uint32_t scan_ms)
    : ctx_(ctx), program_(program), scan_ms_(scan_ms) {}

z3::expr Scan::literal(const plc::Literal& l) {
  switch (l.type) {
    case plc::Type::Bool: return ctx_.bool_val(l.integer != 0);
    case plc::Type::Int: return ctx_.bv_val(static_cast<int>(l.integer), 16);
    case plc::Type::Dint:
    case plc::Type::Time: return ctx_.bv_val(static_cast<std::int64_t>(static_cast<std::int32_t>(l.integer)), 32);
    case plc::Type::Real: return ctx_.fpa_val(l.real);
  }
  return ctx_.bool_val(false);
}

z3::expr Scan::zero(plc::Type t) {
  plc::Literal l;
  l.type = t;
  return literal(l);
}

std::string Scan::key(const Scope& scope, const std::string& name) const {
  auto it = scope.alias.find(upper(name));
  return it != scope.alias.end() ? it->second : scope.path + upper(name);
}

z3::expr& Scan::at(Env& env, const std::string& k, plc::Position where) {
  auto it = env.find(k);
  if (it == env.end()) throw Unsupported(where, "no value for " + k + " in the encoding (a checked program has one)");
  return it->second;
}

z3::expr Scan::eval(const plc::Expr& e, const Scope& scope, Env& env) {
  using K = plc::Expr::Kind;
  switch (e.kind) {
    case K::Literal: return literal(e.literal);
    case K::Variable: return at(env, key(scope, e.name), e.position);
    case K::Member: return at(env, key(scope, e.name) + "." + upper(e.member), e.position);
    case K::Unary: {
      z3::expr a = eval(e.args.at(0), scope, env);
      if (e.unary == plc::UnaryOp::Not) return a.is_bool() ? !a : ~a;
      return is_real(a) ? fp(ctx_, Z3_mk_fpa_neg(ctx_, a)) : -a;
    }
    case K::Binary: return binary(e, scope, env);
    case K::Call: return call(e, scope, env);
  }
  throw Unsupported(e.position, "expression kind not encoded");
}

z3::expr Scan::binary(const plc::Expr& e, const Scope& scope, Env& env) {
  z3::expr a = eval(e.args.at(0), scope, env);
  z3::expr b = eval(e.args.at(1), scope, env);
  using Op = plc::BinaryOp;
  switch (e.binary) {
    case Op::Or: return a.is_bool() ? a || b : a | b;
    case Op::Xor: return a.is_bool() ? a != b : a ^ b;
    case Op::And: return a.is_bool() ? a && b : a & b;
    case Op::Eq: return equal(ctx_, a, b);
    case Op::Ne: return !equal(ctx_, a, b);
    case Op::Lt: return less(ctx_, a, b);
    case Op::Le: return less_eq(ctx_, a, b);
    case Op::Gt: return less(ctx_, b, a);
    case Op::Ge: return less_eq(ctx_, b, a);
    case Op::Add: return is_real(a) ? fp(ctx_, Z3_mk_fpa_add(ctx_, rne(), a, b)) : a + b;
    case Op::Sub: return is_real(a) ? fp(ctx_, Z3_mk_fpa_sub(ctx_, rne(), a, b)) : a - b;
    case Op::Mul: return is_real(a) ? fp(ctx_, Z3_mk_fpa_mul(ctx_, rne(), a, b)) : a * b;
    case Op::Div: {
      if (is_real(a)) return fp(ctx_, Z3_mk_fpa_div(ctx_, rne(), a, b));
      const z3::expr z = ctx_.bv_val(0, a.get_sort().bv_size());
      return z3::ite(b == z, z, fp(ctx_, Z3_mk_bvsdiv(ctx_, a, b)));  // integer division by 0 gives 0
    }
    case Op::Mod: {
      const z3::expr z = ctx_.bv_val(0, a.get_sort().bv_size());
      return z3::ite(b == z, z, fp(ctx_, Z3_mk_bvsrem(ctx_, a, b)));  // the sign of the dividend, as C's %
    }
  }
  throw Unsupported(e.position, "operator not encoded");
}

z3::expr Scan::call(const plc::Expr& e, const Scope& scope, Env& env) {
  std::vector<z3::expr> v;
  for (const auto& a : e.args) v.push_back(eval(a, scope, env));
  auto min = [&](const z3::expr& a, const z3::expr& b) { return z3::ite(less(ctx_, b, a), b, a); };
  auto max = [&](const z3::expr& a, const z3::expr& b) { return z3::ite(less(ctx_, a, b), b, a); };
  switch (e.function) {
    case plc::Function::Min: {
      z3::expr r = v.at(0);
      for (std::size_t i = 1; i < v.size(); ++i) r = min(r, v[i]);
      return r;
    }
    case plc::Function::Max: {
      z3::expr r = v.at(0);
      for (std::size_t i = 1; i < v.size(); ++i) r = max(r, v[i]);
      return r;
    }
    case plc::Function::Abs:
      if (is_real(v.at(0))) return fp(ctx_, Z3_mk_fpa_abs(ctx_, v[0]));
      return z3::ite(z3::slt(v[0], ctx_.bv_val(0, v[0].get_sort().bv_size())), -v[0], v[0]);
    case plc::Function::Sel: return z3::ite(v.at(0), v.at(2), v.at(1));
    case plc::Function::Limit: return min(max(v.at(1), v.at(0)), v.at(2));
  }
  throw Unsupported(e.position, "function not encoded");
}

}  // namespace cemv::plc_encoder
