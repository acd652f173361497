// `cemv plc-check MATRIX PROGRAM`: a PLC program compared with its matrix,
// output tag by output tag (docs/plc.md). Exit 0 every output related as
// asked, 1 a difference, 2 bad input, 3 unknown and no difference, 4
// internal error (a run that does not replay on both sides).
#include <chrono>
#include <filesystem>
#include <iostream>
#include <string>

#include "checker/prover.hpp"
#include "checker/counterexample.hpp"
#include "checker/work_queue.hpp"
#include "cli/commands.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "cli/plc_program.hpp"
#include "formats/diagnostics.hpp"
#include "formats/matrix_json.hpp"
#include "formats/plc_map.hpp"
#include "formats/scenario_writer.hpp"
#include "model/vocabulary.hpp"
#include "plc/parser.hpp"
#include "plc_check/check.hpp"
#include "plc_check/report.hpp"
#include "plc_encoder/encode.hpp"
#include "reports/check_report.hpp"
#include "reports/timing_svg.hpp"

namespace cemv::cli {

namespace {

struct PlcArgs {
  std::string matrix, program, map, pou, save_map;
  std::string relation = "equal";
  std::string format = "text";
  std::string output = "-";
  std::string out_dir;
  double timeout_s = 0.0;
  double total_timeout_s = 0.0;
  int jobs = 1;
  bool quiet = false;
};

std::string stem(const std::string& tag) {
  std::string s;
  for (char c : tag) s += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return s;
}

void write_difference(const PlcArgs& a, const model::Matrix& m, plc_check::PlcCheckReport& r, std::size_t i) {
  const auto& o = r.outputs[i];
  if (a.out_dir.empty() || !o.difference) return;
  const auto& d = *o.difference;
  const std::string base = (std::filesystem::path(a.out_dir) / ("plc." + stem(o.question.tag))).string();
  const std::string key = "effect[" + std::to_string(o.question.effect) + "].tag[" + std::to_string(o.question.position) + "]";
  std::vector<formats::ExpectedValue> expect{{key, model::FieldType::Bool, d.program_values.back()}};
  r.scenario_files[i] = base + ".scenario.json";
  write_output(r.scenario_files[i],
               formats::scenario_text(
                   m, formats::checked_at_end(d.matrix_inputs,
                                              "Where program " + r.pou + " (" + r.program_file + ") differs from matrix " +
                                                  m.name + ": " + o.question.tag + " in scan " +
                                                  std::to_string(d.scan + 1) +
                                                  "; the expectation is the program's value, so the matrix fails it",
                                              expect)));
  reports::TimingDiagram diagram;
  diagram.title = "program " + r.pou + " against matrix " + m.name + ": " + o.question.tag;
  diagram.shown.push_back(key);
  // Every input the run holds away from the plant at rest, changing or not:
  // the run is made of what the difference needs (docs/plc.md).
  const model::CycleInput rest = model::default_cycle_input(m);
  const model::InputTable table(m);
  for (std::size_t i = 0; i < table.size(); ++i)
    for (const auto& scan : d.matrix_inputs)
      if (scan.tags.at(i).value != rest.tags.at(i).value || scan.tags.at(i).bad_quality != rest.tags.at(i).bad_quality) {
        diagram.inputs_shown.push_back(table.tags()[i].name);
        break;
      }
  diagram.marks.push_back({static_cast<std::size_t>(d.scan), "first difference: matrix " +
                                                                 std::to_string(d.matrix_values.back()) + ", program " +
                                                                 std::to_string(d.program_values.back())});
  for (std::size_t c = 0; c < d.program_values.size(); ++c)
    if (c == 0 || d.program_values[c] != d.program_values[c - 1])
      diagram.notes.push_back("scan " + std::to_string(c + 1) + ": program " + o.question.variable + " = " +
                              std::to_string(d.program_values[c]));
  if (d.assigned_at)
    diagram.notes.push_back(r.program_file + ":" + std::to_string(d.assigned_at->line) + ":" +
                            std::to_string(d.assigned_at->column) + ": the statement that set " + o.question.variable +
                            " in scan " + std::to_string(d.scan + 1));
  r.diagram_files[i] = base + ".svg";
  write_output(r.diagram_files[i], reports::timing_svg(m, d.runtime, diagram));
}

int run_plc_check(const PlcArgs& a) {
  plc_check::Relation relation;
  if (a.relation == "equal") relation = plc_check::Relation::Equal;
  else if (a.relation == "safe-side") relation = plc_check::Relation::SafeSide;
  else throw std::runtime_error("plc-check: --relation '" + a.relation + "': expected equal or safe-side");
  const auto format = reports::check_format_from_string(a.format);
  if (!format) throw std::runtime_error("plc-check: --format '" + a.format + "': expected text, json, junit or sarif");
  if (a.jobs < 1) throw std::runtime_error("plc-check: --jobs must be at least 1");
  const model::Matrix m = load_valid_matrix(a.matrix, "plc-check");
  const std::string program_text = read_input(a.program);
  const plc::Program program = plc::read_program(a.program);
  std::optional<formats::PlcMap> given;
  if (!a.map.empty()) given = formats::parse_plc_map(read_input(a.map), input_name(a.map));
  const plc::Pou& pou = choose_pou(program, !a.pou.empty() ? a.pou : given ? given->pou : "", input_name(a.program));
  const plc_check::ProgramInterface iface = program_interface(program, pou, input_name(a.program));
  check_writable(a.output);
  if (!a.save_map.empty()) check_writable(a.save_map);
  if (!a.out_dir.empty()) check_writable_directory(a.out_dir);
  const auto map = plc_check::resolve_map(m, iface, given ? &*given : nullptr, input_name(a.map));
  if (!a.save_map.empty()) write_output(a.save_map, formats::plc_map_json(map.map));
  if (!given && !a.quiet) std::cerr << "map found by name (--save-map writes it):\n" << formats::plc_map_json(map.map);

  plc_check::PlcCheckReport r;
  r.matrix_file = input_name(a.matrix);
  r.matrix_signature = formats::signature(m);
  r.program_file = input_name(a.program);
  r.program_sha256 = formats::sha256_hex(program_text);
  r.pou = pou.name;
  r.relation = relation;
  r.map = map;
  r.map_source = given ? input_name(a.map) : "found by name";
  r.tool_version = CEMV_VERSION;
  decide_outputs(m, program, pou, r, a.timeout_s, a.total_timeout_s, a.jobs);
  for (std::size_t i = 0; i < r.outputs.size(); ++i) write_difference(a, m, r, i);
  std::string text;
  if (*format == reports::CheckFormat::Text) text = plc_check::to_text(r, m);
  else if (*format == reports::CheckFormat::Json) text = plc_check::to_json(r);
  else text = reports::check_report(plc_check::as_check_result(r), {input_name(a.matrix)}, *format);
  if (!(a.quiet && *format == reports::CheckFormat::Text && a.output == "-")) write_output(a.output, text);
  if (a.quiet)
    for (const auto& o : r.outputs)
      if (o.verdict != plc_check::OutputVerdict::Related)
        std::cerr << r.program_file << ": " << (o.verdict == plc_check::OutputVerdict::Differs ? "error" : "warning")
                  << ": output " << o.question.tag << " " << plc_check::to_string(o.verdict) << "\n";
  return plc_check::exit_code(r);
}

}  // namespace

void add_plc_commands(CLI::App& app, Context& ctx) {
  auto* cmd = app.add_subcommand("plc-check", "Prove a PLC program (Structured Text or PLCopen XML) equal to its matrix "
                                              "output by output, or show where it differs (docs/plc.md)");
  static PlcArgs a;
  cmd->add_option("MATRIX", a.matrix, "the matrix (cemv-matrix/1)")->required();
  cmd->add_option("PROGRAM", a.program, "the program: Structured Text, or PLCopen TC6 XML 2.01")->required();
  cmd->add_option("--map", a.map, "the map between matrix and program (cemv-plc-map/1); without it, found by name")
      ->type_name("MAP");
  cmd->add_option("--save-map", a.save_map, "write the completed map to FILE")->type_name("FILE");
  cmd->add_option("--pou", a.pou, "the PROGRAM to check (default: the map's, or the file's only PROGRAM)")->type_name("NAME");
  cmd->add_option("--relation", a.relation, "equal (the same output at every scan) or safe-side (safe whenever the matrix is)")
      ->capture_default_str();
  cmd->add_option("--format", a.format, "text, json (cemv-plc-result/1), junit or sarif")->capture_default_str();
  cmd->add_option("-o,--output", a.output, "write the report to FILE ('-' = standard output)")->type_name("FILE");
  cmd->add_option("--out", a.out_dir, "folder for each difference's scenario and timing diagram")->type_name("DIR");
  cmd->add_option("--timeout", a.timeout_s, "wall-clock limit per output, seconds (0 = none)")->type_name("S");
  cmd->add_option("--total-timeout", a.total_timeout_s, "wall-clock limit of the whole run, seconds (0 = none)")->type_name("S");
  cmd->add_option("--jobs", a.jobs, "outputs decided at once (the results do not depend on it)")->type_name("N");
  cmd->add_flag("-q,--quiet", a.quiet, "print nothing but errors (and the output asked for)");
  cmd->footer(
      "Exit status: 0 every output related as asked; 1 an output differs (a run replayed on the matrix's\n"
      "runtime and the program's interpreter); 2 bad input (a program outside the subset, an incomplete\n"
      "map); 3 some output undecided and none differs; 4 internal error (a run that does not replay).\n");
  cmd->callback([&ctx]() {
    try {
      ctx.exit_code = run_plc_check(a);
    } catch (const checker::InternalError& e) {
      std::cerr << "internal error: " << e.what() << "\n";
      ctx.exit_code = 4;
    }
  });
}

}  // namespace cemv::cli
