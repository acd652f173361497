// A PLC program as a symbolic transition system over Z3 (docs/plc.md "The
// program as a transition system"): one scan reads the inputs, executes the
// body of the checked PROGRAM, and leaves its variables, the state of every
// block instance and every timer's elapsed time (on the scan's time base) for
// the next scan. The second implementation of the scan semantics, written
// apart from plc/'s interpreter (no shared semantic code) and kept in
// agreement with it by the differential test in tests/plc_check/. It uses
// plc/'s AST and model/ only; plc_check/ puts its terms into the matrix's
// transition system.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <z3++.h>

#include "plc/ast.hpp"

namespace cemv::plc_encoder {

// Timing convention as the matrix encoder's (docs/encoding.md): a state
// variable holds what the previous scan left; `next` and the output terms are
// functions of (state, inputs) of the current scan.
struct StateVar {
  std::string name;  // prefix + "LT100_HH_DELAY.et"
  z3::expr var;      // a Z3 constant named `name`
  z3::expr init;
  z3::expr next;
};

// A VAR_INPUT (or VAR_IN_OUT) of the checked POU: a Z3 constant named
// prefix + "in." + its name, to be replaced by what the map binds to it.
struct InputVar {
  std::string variable;  // the declared spelling
  plc::Type type = plc::Type::Bool;
  z3::expr var;
};

// A VAR_OUTPUT (or VAR_IN_OUT) of the checked POU: its value at the end of the scan.
struct OutputTerm {
  std::string variable;
  plc::Type type = plc::Type::Bool;
  z3::expr term;
};

struct ProgramSystem {
  std::vector<StateVar> states;
  std::vector<InputVar> inputs;
  std::vector<OutputTerm> outputs;
  // Every REAL constant in the terms above, so that a consumer that reads
  // floats back from terms by their constants (the checker's evaluator) can
  // register them.
  std::vector<float> real_literals;
};

// The Z3 sort of a value of `t`: Bool; INT, DINT and TIME Int, every result
// of arithmetic reduced to the type's range (16 or 32 bits, two's complement
// wrapping); REAL Float32.
z3::sort sort_of(z3::context& ctx, plc::Type t);

// What the encoding does not cover (a timer called other than once per
// scan, a FOR of too many iterations), at its place in the program.
class Unsupported : public std::runtime_error {
 public:
  Unsupported(plc::Position at, const std::string& what) : std::runtime_error(what), at(at) {}
  plc::Position at;
};

// Encodes POU `pou` of a checked program. Every name the system creates
// starts with `prefix` ("plc."). Throws Unsupported.
ProgramSystem encode(z3::context& ctx, const plc::Program& program, const plc::Pou& pou, std::uint32_t scan_ms,
                     const std::string& prefix);

}  // namespace cemv::plc_encoder
