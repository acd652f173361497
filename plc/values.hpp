// The arithmetic of the interpreter (docs/plc.md P.5): two's complement
// wrap-around at the width of INT, DINT and TIME, IEEE single precision for
// REAL, integer division truncating toward zero.
#pragma once

#include <vector>

#include "plc/ast.hpp"

namespace cemv::plc {

Literal negate(const Literal& a);
Literal binary(BinaryOp op, const Literal& a, const Literal& b);
Literal call(Function f, const std::vector<Literal>& args);
// The value wrapped to the width of its integer type (P.5.1).
std::int64_t wrap(Type t, std::int64_t v);

}  // namespace cemv::plc
