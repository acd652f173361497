// `cemv export-st MATRIX [--format st|plcopen] [-o FILE] [--map-out FILE]`:
// the matrix as a PLC program with its map (docs/plc.md "Generated
// programs"). The program is read back by plc/'s own reader before it is
// written: a generated program outside the subset is an internal error
// (exit 4), never an output.
#include <filesystem>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "cli/errors.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "formats/diagnostics.hpp"
#include "formats/plc_map.hpp"
#include "plc/parser.hpp"
#include "plc/plcopen.hpp"
#include "plc/print.hpp"
#include "plc_export/export.hpp"

namespace cemv::cli {

namespace {

struct ExportStArgs {
  std::string matrix;
  std::string format = "st";
  std::string output = "-";
  std::string map_out;
};

// FILE.st -> FILE.map.json beside it; standard output: no default.
std::string default_map_path(const std::string& output) {
  if (output == "-") return "";
  std::filesystem::path p(output);
  return (p.parent_path() / (p.stem().string() + ".map.json")).string();
}

int run_export_st(const ExportStArgs& a, bool quiet) {
  if (a.format != "st" && a.format != "plcopen")
    throw std::runtime_error("export-st: --format '" + a.format + "': expected st or plcopen");
  const std::string map_path = !a.map_out.empty() ? a.map_out : default_map_path(a.output);
  check_writable(a.output);
  if (!map_path.empty()) check_writable(map_path);
  const model::Matrix m = load_valid_matrix(a.matrix, "exported");
  plc_export::Export e;
  try {
    e = plc_export::export_program(m);
  } catch (const plc_export::Unsupported& u) {
    std::cerr << input_name(a.matrix) << ": error: export-st: " << u.what() << "\n";
    return 2;
  }
  const std::string text =
      a.format == "st" ? plc::print_program(e.program) : plc::write_plcopen(e.program);
  try {
    (void)plc::parse_program_text(text, "<generated program>");
  } catch (const formats::LoadError& err) {
    std::cerr << "internal error: export-st: the generated program is refused by cemv's own reader:\n";
    print_load_error(err, std::cerr);
    return 4;
  }
  write_output(a.output, text);
  if (!map_path.empty()) write_output(map_path, formats::plc_map_json(e.map));
  if (!quiet && a.output != "-")
    std::cerr << "wrote " << a.output << (map_path.empty() ? "" : " and its map " + map_path) << "\n";
  return 0;
}

}  // namespace

void add_export_st_commands(CLI::App& app, Context& ctx) {
  auto* cmd = app.add_subcommand("export-st", "Write the matrix as an IEC 61131-3 Structured Text (or PLCopen XML) "
                                              "program with its map (docs/plc.md)");
  static ExportStArgs a;
  cmd->add_option("MATRIX", a.matrix, "the matrix (cemv-matrix/1)")->required();
  cmd->add_option("--format", a.format, "st (Structured Text) or plcopen (PLCopen TC6 XML 2.01)")->capture_default_str();
  cmd->add_option("-o,--output", a.output, "write the program to FILE ('-' = standard output)")->type_name("FILE");
  cmd->add_option("--map-out", a.map_out,
                  "write the map (cemv-plc-map/1) to FILE (default with -o FILE.st: FILE.map.json beside it)")
      ->type_name("FILE");
  add_quiet_flag(cmd, ctx);
  cmd->footer(
      "Exit status: 0 written; 2 bad input, or an option of the matrix the program cannot express yet\n"
      "(the element is named); 4 internal error (the generated program is refused by cemv's reader).\n");
  cmd->callback([&ctx]() { ctx.exit_code = run_export_st(a, ctx.quiet); });
}

}  // namespace cemv::cli
