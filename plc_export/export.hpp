// `cemv export-st` (docs/plc.md "Generated programs"): a matrix written as an
// IEC 61131-3 Structured Text PROGRAM of the subset plc/ reads, with the map
// (`cemv-plc-map/1`) that binds its variables to the matrix's tags and
// commands. The program is built as a plc/ AST from docs/semantics.md,
// paragraph by paragraph, named after the matrix's elements and commented
// with the rules it implements; every output tag is assigned in one
// statement. It shares no code with runtime/ or encoder/: `cemv plc-check`
// relates it to the matrix as a third implementation.
#pragma once

#include <stdexcept>
#include <string>

#include "formats/plc_map.hpp"
#include "model/matrix.hpp"
#include "plc/ast.hpp"

namespace cemv::plc_export {

// An option the program cannot express yet, named with its element
// ("cause 3 LT100_HH: ..."); the command line turns it into exit 2. Nothing
// is approximated.
class Unsupported : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Export {
  plc::Program program;  // one PROGRAM named after the matrix, scan_time_ms = cycle_ms
  formats::PlcMap map;   // every input, output and command, complete
};

// The program of a valid matrix (formats::load_valid_matrix). Throws
// Unsupported for what cannot be expressed.
Export export_program(const model::Matrix& m);

}  // namespace cemv::plc_export
