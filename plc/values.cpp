#include "plc/values.hpp"

#include <cmath>
#include <cstdint>

namespace cemv::plc {

std::int64_t wrap(Type t, std::int64_t v) {
  if (t == Type::Int) return static_cast<std::int16_t>(static_cast<std::uint16_t>(static_cast<std::uint64_t>(v)));
  if (t == Type::Dint || t == Type::Time)
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<std::uint64_t>(v)));
  return v;
}

namespace {

Literal integer(Type t, std::int64_t v) { return Literal{t, wrap(t, v), 0}; }
Literal real(float v) { return Literal{Type::Real, 0, v}; }
Literal boolean(bool v) { return Literal{Type::Bool, v ? 1 : 0, 0}; }

// a < b on one type (REAL by IEEE: nothing is less than NaN)
bool less(const Literal& a, const Literal& b) {
  return a.type == Type::Real ? a.real < b.real : a.integer < b.integer;
}
bool equal(const Literal& a, const Literal& b) {
  return a.type == Type::Real ? a.real == b.real : a.integer == b.integer;
}

}  // namespace

Literal negate(const Literal& a) {
  return a.type == Type::Real ? real(-a.real) : integer(a.type, -a.integer);
}

Literal binary(BinaryOp op, const Literal& a, const Literal& b) {
  const bool r = a.type == Type::Real;
  switch (op) {
    case BinaryOp::Or: return boolean(a.integer || b.integer);
    case BinaryOp::Xor: return boolean((a.integer != 0) != (b.integer != 0));
    case BinaryOp::And: return boolean(a.integer && b.integer);
    case BinaryOp::Eq: return boolean(equal(a, b));
    case BinaryOp::Ne: return boolean(!equal(a, b));
    case BinaryOp::Lt: return boolean(less(a, b));
    case BinaryOp::Le: return boolean(less(a, b) || equal(a, b));
    case BinaryOp::Gt: return boolean(less(b, a));
    case BinaryOp::Ge: return boolean(less(b, a) || equal(a, b));
    case BinaryOp::Add: return r ? real(a.real + b.real) : integer(a.type, a.integer + b.integer);
    case BinaryOp::Sub: return r ? real(a.real - b.real) : integer(a.type, a.integer - b.integer);
    case BinaryOp::Mul: return r ? real(a.real * b.real) : integer(a.type, a.integer * b.integer);
    // the checker admits only constant divisors other than zero (P.5.3)
    case BinaryOp::Div: return r ? real(a.real / b.real) : integer(a.type, a.integer / b.integer);
    case BinaryOp::Mod: return integer(a.type, a.integer % b.integer);
  }
  return {};
}

Literal call(Function f, const std::vector<Literal>& args) {
  switch (f) {
    case Function::Min: {  // P.5.4: the first of the least
      Literal m = args[0];
      for (const Literal& x : args)
        if (less(x, m)) m = x;
      return m;
    }
    case Function::Max: {
      Literal m = args[0];
      for (const Literal& x : args)
        if (less(m, x)) m = x;
      return m;
    }
    case Function::Abs:
      return args[0].type == Type::Real ? real(std::fabs(args[0].real))
                                        : integer(args[0].type, args[0].integer < 0 ? -args[0].integer : args[0].integer);
    case Function::Sel: return args[0].integer ? args[2] : args[1];
    case Function::Limit: {  // LIMIT(MN, IN, MX) = MIN(MAX(IN, MN), MX)
      Literal v = less(args[1], args[0]) ? args[0] : args[1];
      return less(args[2], v) ? args[2] : v;
    }
  }
  return {};
}

}  // namespace cemv::plc
