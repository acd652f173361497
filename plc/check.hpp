// Name resolution and type checking of a parsed program (docs/plc.md P.2-P.7):
// every name declared once and resolved (references rewritten to the declared
// spelling), block instances of known blocks without recursion, no implicit
// conversion between types, no assignment to an input or a constant, FOR
// bounds constant with the loop's values computed, division only by a
// non-zero constant. Throws formats::LoadError at the first problem, at its
// place in Program::file.
#pragma once

#include <cstdint>

#include "plc/ast.hpp"

namespace cemv::plc {

// Most iterations a FOR loop may run per execution (P.4): a loop is unrolled
// by the SMT encoding, so its size is bounded where it is read.
inline constexpr std::int64_t kMaxForIterations = 4096;

// Most statements one scan may execute, counting every FOR iteration and the
// body of every user block call (P.4.4): bounds the work of a scan for the
// interpreter and the size of the SMT encoding's unrolling.
inline constexpr std::uint64_t kMaxStatementsPerScan = 1'000'000;

void check_program(Program& program);

// The statements a call of `pou` executes at most (saturating just above
// kMaxStatementsPerScan), for a checked program.
std::uint64_t statement_bound(const Program& program, const Pou& pou);

// The number of iterations of a checked FOR statement.
std::int64_t for_iterations(const Statement& s);

}  // namespace cemv::plc
