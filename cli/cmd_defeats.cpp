// `cemv defeats MATRIX`: the minimal sets of maintenance operations and input
// faults under which a path of a SIF group no longer meets its trip
// requirement (docs/defeats.md). Exit status as `cemv check`: 0 every path's
// sets enumerated, 1 some path fails without any action or fails the
// --require-distance gate, 2 bad input, 3 some path incomplete, 4 internal
// error.
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/evidence_inputs.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "cli/path_analysis.hpp"
#include "defeats/analysis.hpp"
#include "response/paths.hpp"
#include "defeats/report.hpp"

namespace cemv::cli {

namespace {

struct DefeatsArgs {
  std::string matrix_file;
  std::vector<int> sifs;
  int max_size = 2;
  int require_distance = 0;
  std::string format = "text";
  std::string output = "-";
  std::string out_dir;
  std::string response_file;
  double timeout_s = 0.0;
  double total_timeout_s = 0.0;
  int jobs = 1;
  bool quiet = false;
};

struct BadArguments : std::runtime_error {
  using std::runtime_error::runtime_error;
};

int run_defeats(const DefeatsArgs& a) {
  defeats::Format format;
  if (a.format == "text") format = defeats::Format::Text;
  else if (a.format == "json") format = defeats::Format::Json;
  else if (a.format == "junit") format = defeats::Format::Junit;
  else if (a.format == "sarif") format = defeats::Format::Sarif;
  else throw BadArguments("--format: '" + a.format + "' is not a format; expected text, json, junit or sarif");
  if (a.jobs < 1) throw BadArguments("--jobs must be at least 1");
  if (a.max_size < 0) throw BadArguments("--max-size must not be negative");
  if (a.require_distance < 0) throw BadArguments("--require-distance must not be negative");
  if (a.timeout_s < 0) throw BadArguments("--timeout must not be negative");
  if (a.total_timeout_s < 0) throw BadArguments("--total-timeout must not be negative");
  check_writable(a.output);
  if (!a.out_dir.empty()) check_writable_directory(a.out_dir);

  const model::Matrix m = load_valid_matrix(a.matrix_file, "analysed");
  defeats::DefeatsOptions o;
  o.sifs = a.sifs;
  o.max_size = a.max_size;
  o.timeout_s = a.timeout_s;
  o.total_timeout_s = a.total_timeout_s;
  o.jobs = a.jobs;
  o.out_dir = a.out_dir;
  if (!a.response_file.empty()) {
    std::map<std::string, std::string> keys;  // "1,2>3" -> the path's key
    for (const auto& p : response::response_paths(m, {})) {
      std::string k;
      for (int c : p.causes) k += std::to_string(c) + ",";
      keys[k + ">" + std::to_string(p.effect)] = p.key();
    }
    o.known_figures = read_response_figures(a.response_file, m, keys);
  }
  std::optional<defeats::DefeatsResult> analysed;
  try {
    analysed = run_path_analysis("cemv defeats", o, a.quiet, [&] { return defeats::analyse(m, o); });
  } catch (const std::invalid_argument& e) {
    throw BadArguments(e.what());
  }
  if (!analysed) return 4;
  const defeats::DefeatsResult& r = *analysed;
  if (!(a.quiet && format == defeats::Format::Text && a.output == "-"))
    write_output(a.output,
                 defeats::defeats_report(m, r, input_name(a.matrix_file), format, a.out_dir, a.require_distance));
  if (a.quiet)
    for (const defeats::PathDefeats* p : defeats::gate_failures(r, a.require_distance))
      std::cerr << input_name(a.matrix_file) << ": error: path " << p->path.key() << " of SIF " << p->path.sif
                << ": defeat distance " << *p->distance << " below --require-distance " << a.require_distance << "\n";
  return defeats::exit_code(r, a.require_distance);
}

}  // namespace

void add_defeats_commands(CLI::App& app, Context& ctx) {
  auto* cmd = app.add_subcommand(
      "defeats", "Minimal sets of maintenance operations and faults that defeat each safety function (docs/defeats.md)");
  static DefeatsArgs a;
  cmd->add_option("MATRIX", a.matrix_file, "cemv-matrix/1 file ('-' = standard input)")->required();
  cmd->add_option("--sif", a.sifs, "analyse only these SIF groups (repeatable)")->type_name("N");
  cmd->add_option("--max-size", a.max_size, "the largest sets enumerated (K)")->capture_default_str();
  cmd->add_option("--require-distance", a.require_distance,
                  "exit 1 when a path of a SIL 2+ group has an indirect defeat set smaller than N (0 = no gate)")
      ->type_name("N");
  cmd->add_option("--format", a.format, "text, json (cemv-defeats/1), junit, sarif")->capture_default_str();
  cmd->add_option("-o,--output", a.output, "write the report to FILE ('-' = standard output)")->type_name("FILE");
  cmd->add_option("--out", a.out_dir, "folder for the counterexample scenarios of the sets (created if missing)")
      ->type_name("DIR");
  cmd->add_option("--response", a.response_file,
                  "take each path's trip requirement T from this `cemv response --format json` report of the "
                  "same matrix instead of proving it again")
      ->type_name("FILE");
  cmd->add_option("--timeout", a.timeout_s, "wall-clock limit per decided property, seconds (0 = none)")
      ->type_name("S");
  cmd->add_option("--total-timeout", a.total_timeout_s, "wall-clock limit of the whole run, seconds (0 = none)")
      ->type_name("S");
  cmd->add_option("--jobs", a.jobs, "paths decided in parallel")->capture_default_str();
  cmd->add_flag("-q,--quiet", a.quiet, "print nothing but errors and a line per path below --require-distance");
  cmd->footer(
      "Exit status: 0 every path's minimal sets enumerated; 1 some path fails its trip requirement\n"
      "without any action, or has an indirect set below --require-distance (SIL 2+); 2 invalid input;\n"
      "3 some path incomplete; 4 internal error.\n");
  cmd->callback([&ctx]() {
    try {
      ctx.exit_code = run_defeats(a);
    } catch (const BadArguments& e) {
      std::cerr << "error: defeats: " << e.what() << "\n";
      ctx.exit_code = 2;
    }
  });
}

}  // namespace cemv::cli
