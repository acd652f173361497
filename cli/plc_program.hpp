// A PLC program read for a command (docs/plc.md): the file, its PROGRAM, the
// map completed against the matrix (given with --map, else found by name),
// and the program's interpreter as a replay target for `cemv replay --plc`.
// Shared by plc-check, replay and evidence.
#pragma once

#include <memory>
#include <string>

#include "model/matrix.hpp"
#include "plc/ast.hpp"
#include "plc/interpreter.hpp"
#include "plc_check/map.hpp"
#include "plc_check/report.hpp"
#include "testgen/testgen.hpp"

namespace cemv::cli {

// The PROGRAM checked: `wanted`, else the file's only PROGRAM. Throws formats::LoadError.
const plc::Pou& choose_pou(const plc::Program& p, const std::string& wanted, const std::string& file);

// The program's interface as plc_check's map sees it.
plc_check::ProgramInterface program_interface(const plc::Program& program, const plc::Pou& pou, const std::string& file);

struct PlcProgram {
  std::string file;        // as messages name it
  std::string sha256;      // of the file's bytes
  std::string map_source;  // the map's file, or "found by name"
  plc::Program program;
  std::string pou;         // the PROGRAM's declared name
  plc_check::ResolvedMap map;
};

// Reads PROGRAM (ST or PLCopen XML) and MAP ("" = found by name) against `m`;
// `pou` overrides the map's. Throws formats::LoadError (exit 2).
std::unique_ptr<PlcProgram> load_plc_program(const model::Matrix& m, const std::string& program,
                                             const std::string& map, const std::string& pou = "");

// Decides every output of `r.map` (questions in effect and tag order), one
// output a task on --jobs workers, each result in its own slot so that none
// depends on `jobs`; fills r.outputs (and empty file names). Throws
// formats::LoadError for a program the encoding refuses (a timer not called
// once per scan), checker::InternalError for a run that does not replay.
void decide_outputs(const model::Matrix& m, const plc::Program& program, const plc::Pou& pou,
                    plc_check::PlcCheckReport& r, double timeout_s, double total_timeout_s, int jobs);

// The program's interpreter behind the map: matrix inputs and commands in,
// output tags out. A cycle that issues a command the map declares unused (the
// program does not implement it) cannot be run; status observables other
// than output tags have no counterpart in a program and are not observed.
class PlcReplayTarget : public testgen::ReplayTarget {
 public:
  PlcReplayTarget(const model::Matrix& m, const PlcProgram& p);
  void start() override;
  std::string cannot_run(const model::CycleInput& in) const override;
  void step(const model::CycleInput& in) override;
  bool observes(const formats::ExpectTarget& t) const override;
  int value(const formats::ExpectTarget& t) const override;

 private:
  std::string output_variable(const formats::ExpectTarget& t) const;
  const model::Matrix& m_;
  const PlcProgram& p_;
  model::InputTable table_;
  plc::Interpreter run_;
};

}  // namespace cemv::cli
