// Fuzz target: the PLC program reader (plc/parser.hpp, plc/plcopen.hpp,
// docs/plc.md), the bytes `cemv plc-check MATRIX PROGRAM` reads as Structured
// Text or PLCopen XML. Expected answers: a checked program, or a LoadError at
// FILE:LINE:COL. Invariants of an accepted program: printed as ST it reads
// back as the same program (plc/print.hpp), and the interpreter runs its
// PROGRAMs a few scans without an exception.
#include <cstddef>
#include <cstdint>
#include <string>

#include "formats/diagnostics.hpp"
#include "fuzz/fuzz_support.hpp"
#include "plc/interpreter.hpp"
#include "plc/parser.hpp"
#include "plc/print.hpp"

using namespace cemv;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  plc::Program program;
  try {
    program = plc::parse_program_text(fuzz::as_text(data, size), "fuzz.st");
  } catch (const formats::LoadError&) {
    return 0;
  }
  const std::string text = plc::print_program(program);
  try {
    const plc::Program again = plc::parse_st(text, "printed.st");
    plc::Program expected = plc::without_positions(program);
    expected.scan_time_ms.reset();  // a task interval is PLCopen's, ST has none
    if (plc::without_positions(again) != expected)
      fuzz::finding("a printed program reads back as another program", text);
  } catch (const formats::LoadError& e) {
    fuzz::finding("a printed program does not parse", text + "\n" + e.issues().front().message());
  }
  for (const plc::Pou& pou : program.pous) {
    if (pou.kind != plc::PouKind::Program) continue;
    plc::Interpreter run(program, pou.name);
    for (int scan = 0; scan < 3; ++scan) run.step({}, 100);
  }
  return 0;
}
