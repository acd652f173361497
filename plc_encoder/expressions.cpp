// Expressions of one scan as Z3 terms (docs/plc.md "The program as a
// transition system": types, operators, standard functions).
#include <algorithm>
#include <cctype>
#include <optional>
#include <utility>

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
  return is_real(a) ? fp(c, Z3_mk_fpa_lt(c, a, b)) : a < b;
}
z3::expr less_eq(z3::context& c, const z3::expr& a, const z3::expr& b) {
  return is_real(a) ? fp(c, Z3_mk_fpa_leq(c, a, b)) : a <= b;
}

// Integer division truncated toward zero, as C's / (Z3's div is Euclidean).
z3::expr truncated_div(const z3::expr& a, const z3::expr& b) {
  const z3::expr q = z3::ite(a >= 0, a / z3::abs(b), -((-a) / z3::abs(b)));
  return z3::ite(b >= 0, q, -q);
}
z3::expr equal(z3::context& c, const z3::expr& a, const z3::expr& b) {
  return is_real(a) ? fp(c, Z3_mk_fpa_eq(c, a, b)) : a == b;  // IEEE: NaN equals nothing
}

// Bounds of an integer term built from numerals by +, -, negation and ITE
// (the counts of C&E code: `N := 0; IF a THEN N := N + 1; END_IF; ...`);
// nullopt for anything else (a variable of the last scan, a product).
std::optional<std::pair<std::int64_t, std::int64_t>> bounds(const z3::expr& e, int depth = 0) {
  std::int64_t v = 0;
  if (e.is_numeral() && e.is_numeral_i64(v)) return std::make_pair(v, v);
  if (!e.is_app() || depth > 64) return std::nullopt;
  const Z3_decl_kind k = e.decl().decl_kind();
  if (k == Z3_OP_ITE) {
    const auto a = bounds(e.arg(1), depth + 1), b = bounds(e.arg(2), depth + 1);
    if (!a || !b) return std::nullopt;
    return std::make_pair(std::min(a->first, b->first), std::max(a->second, b->second));
  }
  if (k == Z3_OP_UMINUS) {
    const auto a = bounds(e.arg(0), depth + 1);
    if (!a) return std::nullopt;
    return std::make_pair(-a->second, -a->first);
  }
  if ((k == Z3_OP_ADD || k == Z3_OP_SUB) && e.num_args() == 2) {
    const auto a = bounds(e.arg(0), depth + 1), b = bounds(e.arg(1), depth + 1);
    if (!a || !b) return std::nullopt;
    if (k == Z3_OP_ADD) return std::make_pair(a->first + b->first, a->second + b->second);
    return std::make_pair(a->first - b->second, a->second - b->first);
  }
  return std::nullopt;
}

}  // namespace

Scan::Scan(z3::context& ctx, const plc::Program& program, std::uint32_t scan_ms)
    : ctx_(ctx), program_(program), scan_ms_(scan_ms) {}

z3::expr Scan::literal(const plc::Literal& l) {
  switch (l.type) {
    case plc::Type::Bool: return ctx_.bool_val(l.integer != 0);
    case plc::Type::Int:
    case plc::Type::Dint:
    case plc::Type::Time: return ctx_.int_val(static_cast<std::int64_t>(l.integer));
    case plc::Type::Real:
      real_literals_.insert(l.real);
      return ctx_.fpa_val(l.real);
  }
  return ctx_.bool_val(false);
}

z3::expr Scan::wrap(plc::Type t, const z3::expr& x) {
  if (t != plc::Type::Int && t != plc::Type::Dint && t != plc::Type::Time) return x;
  if (x.is_numeral()) {  // folded at once: most arithmetic of C&E code is on constants
    std::int64_t v = 0;
    if (x.is_numeral_i64(v)) {
      if (t == plc::Type::Int) return ctx_.int_val(static_cast<std::int64_t>(static_cast<std::int16_t>(static_cast<std::uint16_t>(v))));
      return ctx_.int_val(static_cast<std::int64_t>(static_cast<std::int32_t>(static_cast<std::uint32_t>(v))));
    }
  }
  const std::int64_t half = t == plc::Type::Int ? 32768 : 2147483648LL;
  // In range whatever the run: no correction, so no case split for the solver.
  if (const auto b = bounds(x); b && b->first >= -half && b->second < half) return x;
  const z3::expr h = ctx_.int_val(half), m = ctx_.int_val(2 * half);
  // A sum, difference, negation or quotient of values in range is at most one
  // range away: one correction, no `mod` (which the checker's concrete
  // evaluator does not take). A product may be further away.
  if (x.is_app() && x.decl().decl_kind() == Z3_OP_MUL) return z3::ite(x >= -h && x < h, x, z3::mod(x + h, m) - h);
  return z3::ite(x >= h, x - m, z3::ite(x < -h, x + m, x));
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
      if (e.unary == plc::UnaryOp::Not) return !a;
      return is_real(a) ? fp(ctx_, Z3_mk_fpa_neg(ctx_, a)) : wrap(e.type, -a);
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
    case Op::Or: return a || b;
    case Op::Xor: return a != b;
    case Op::And: return a && b;
    case Op::Eq: return equal(ctx_, a, b);
    case Op::Ne: return !equal(ctx_, a, b);
    case Op::Lt: return less(ctx_, a, b);
    case Op::Le: return less_eq(ctx_, a, b);
    case Op::Gt: return less(ctx_, b, a);
    case Op::Ge: return less_eq(ctx_, b, a);
    case Op::Add: return is_real(a) ? fp(ctx_, Z3_mk_fpa_add(ctx_, rne(), a, b)) : wrap(e.type, a + b);
    case Op::Sub: return is_real(a) ? fp(ctx_, Z3_mk_fpa_sub(ctx_, rne(), a, b)) : wrap(e.type, a - b);
    case Op::Mul: return is_real(a) ? fp(ctx_, Z3_mk_fpa_mul(ctx_, rne(), a, b)) : wrap(e.type, a * b);
    // The checker admits only constant divisors other than zero (P.5.3).
    case Op::Div: return is_real(a) ? fp(ctx_, Z3_mk_fpa_div(ctx_, rne(), a, b)) : wrap(e.type, truncated_div(a, b));
    case Op::Mod: return a - b * truncated_div(a, b);  // the sign of the dividend, as C's %
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
      return wrap(e.type, z3::ite(v[0] < 0, -v[0], v[0]));
    case plc::Function::Sel: return z3::ite(v.at(0), v.at(2), v.at(1));
    case plc::Function::Limit: return min(max(v.at(1), v.at(0)), v.at(2));
  }
  throw Unsupported(e.position, "function not encoded");
}

}  // namespace cemv::plc_encoder
