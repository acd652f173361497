// The PLC program executed one scan at a time (docs/plc.md P.8): the
// interpreter that replays a counterexample or an acceptance suite on the
// program. It shares nothing with the SMT encoding of the same program
// (or with the matrix's runtime) but the AST and docs/plc.md.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "plc/ast.hpp"

namespace cemv::plc {

// A value of an elementary type (BOOL and TIME as Literal holds them).
using Value = Literal;

Value default_value(Type t);  // FALSE, 0, 0.0, T#0s (P.3)

class Interpreter {
 public:
  // Runs the PROGRAM `pou` of a checked program (empty: its only PROGRAM),
  // which must outlive the interpreter (it is read, not copied).
  // Throws std::invalid_argument when there is no such PROGRAM, or no name
  // is given and the file has several.
  explicit Interpreter(const Program& program, std::string_view pou = {});
  ~Interpreter();
  Interpreter(Interpreter&&) noexcept;
  Interpreter& operator=(Interpreter&&) noexcept;

  const Pou& pou() const;

  // One scan (P.8): the time base advances by `scan_time_ms` (> 0), the given
  // inputs (VAR_INPUT or VAR_IN_OUT of the PROGRAM, by name, any case, each of
  // its declared type) are copied in, inputs not given keep their values, the
  // body executes once. Throws std::invalid_argument for an unknown name, a
  // variable that is not an input, a value of another type or a scan time
  // that is not positive.
  void step(const std::map<std::string, Value>& inputs, std::int64_t scan_time_ms);

  // A variable of the PROGRAM by name (any case), or an output or internal
  // variable of an instance as `inst.Q` (`outer.inner.Q` for nested user
  // blocks). Throws std::invalid_argument for an unknown name.
  Value value(std::string_view name) const;

  // Where the latest scan last assigned a variable of the PROGRAM (an
  // assignment, a FOR, or a call's `=>`); nullopt when it did not.
  std::optional<Position> last_assignment(std::string_view name) const;

  std::size_t scans() const;  // scans executed since start-up
  std::int64_t now_ms() const;  // the time base: the sum of the scan times
  void reset();               // back to start-up (P.3)

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cemv::plc
