// `cemv response MATRIX`: the exact worst-case response time of every path of
// every SIF group, held against its process safety time
// (docs/response-time.md). Exit status as `cemv check`: 0 every path within,
// 1 some path over or unbounded, 2 bad input, 3 some path unknown and none
// over, 4 internal error.
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "cli/path_analysis.hpp"
#include "response/analysis.hpp"
#include "response/report.hpp"

namespace cemv::cli {

namespace {

struct ResponseArgs {
  std::string matrix_file;
  std::vector<int> sifs;
  std::string format = "text";
  std::string output = "-";
  std::string out_dir;
  bool conservative = false;
  double timeout_s = 0.0;
  double total_timeout_s = 0.0;  // --total-timeout: the whole run (0 = none)
  int jobs = 1;
  bool quiet = false;
};

struct BadArguments : std::runtime_error {
  using std::runtime_error::runtime_error;
};

int run_response(const ResponseArgs& a) {
  response::Format format;
  if (a.format == "text") format = response::Format::Text;
  else if (a.format == "json") format = response::Format::Json;
  else if (a.format == "junit") format = response::Format::Junit;
  else if (a.format == "sarif") format = response::Format::Sarif;
  else throw BadArguments("--format: '" + a.format + "' is not a format; expected text, json, junit or sarif");
  if (a.jobs < 1) throw BadArguments("--jobs must be at least 1");
  if (a.timeout_s < 0 || a.total_timeout_s < 0) throw BadArguments("time limits must not be negative");
  check_writable(a.output);
  if (!a.out_dir.empty()) check_writable_directory(a.out_dir);

  const model::Matrix m = load_valid_matrix(a.matrix_file, "analysed");
  response::ResponseOptions o;
  o.sifs = a.sifs;
  o.conservative = a.conservative;
  o.timeout_s = a.timeout_s;
  o.total_timeout_s = a.total_timeout_s;
  o.jobs = a.jobs;
  o.out_dir = a.out_dir;
  std::optional<response::ResponseResult> analysed;
  try {
    analysed = run_path_analysis("cemv response", o, a.quiet, [&] { return response::analyse(m, o); });
  } catch (const std::invalid_argument& e) {
    throw BadArguments(e.what());
  }
  if (!analysed) return 4;
  const response::ResponseResult& r = *analysed;
  // --quiet: no table on standard output, but a line per path over its
  // process safety time, unbounded or undecided (docs/response-time.md).
  if (!(a.quiet && format == response::Format::Text && a.output == "-"))
    write_output(a.output, response::response_report(r, input_name(a.matrix_file), format, a.out_dir));
  if (a.quiet)
    for (const auto& p : r.paths)
      if (p.verdict == response::Verdict::Over || p.verdict == response::Verdict::Unbounded ||
          p.verdict == response::Verdict::Unknown)
        std::cerr << input_name(a.matrix_file) << ": " << (p.verdict == response::Verdict::Unknown ? "warning" : "error")
                  << ": path " << p.path.key() << " of SIF " << p.path.sif
                  << (p.sif_name.empty() ? "" : " " + p.sif_name) << ": " << response::to_string(p.verdict) << "\n";
  return response::exit_code(r);
}

}  // namespace

void add_response_commands(CLI::App& app, Context& ctx) {
  auto* cmd = app.add_subcommand(
      "response", "Exact worst-case response time of every safety function (docs/response-time.md)");
  static ResponseArgs a;
  cmd->add_option("MATRIX", a.matrix_file, "cemv-matrix/1 file ('-' = standard input)")->required();
  cmd->add_option("--sif", a.sifs, "analyse only these SIF groups (repeatable)")->type_name("N");
  cmd->add_option("--format", a.format, "text, json (cemv-response/1), junit, sarif")->capture_default_str();
  cmd->add_option("-o,--output", a.output, "write the report to FILE ('-' = standard output)")->type_name("FILE");
  cmd->add_option("--out", a.out_dir, "folder for the T-1 counterexample scenarios (created if missing)")
      ->type_name("DIR");
  cmd->add_flag("--conservative", a.conservative,
                "the controller's share is twice watchdog_ms instead of twice cycle_ms (HIMatrix 3.2.6)");
  cmd->add_option("--timeout", a.timeout_s, "wall-clock limit per decided property, seconds (0 = none)")
      ->type_name("S");
  cmd->add_option("--total-timeout", a.total_timeout_s,
                  "wall-clock limit of the whole run, seconds (0 = none; the paths it leaves are unknown)")
      ->type_name("S");
  cmd->add_option("--jobs", a.jobs, "paths decided in parallel")->capture_default_str();
  cmd->add_flag("-q,--quiet", a.quiet, "print nothing but errors and a line per path over, unbounded or unknown");
  cmd->footer(
      "Exit status: 0 every path within its process safety time (or none declared); 1 some path\n"
      "over it or unbounded; 2 invalid input; 3 some path unknown and none over; 4 internal error.\n");
  cmd->callback([&ctx]() {
    try {
      ctx.exit_code = run_response(a);
    } catch (const BadArguments& e) {
      std::cerr << "error: response: " << e.what() << "\n";
      ctx.exit_code = 2;
    }
  });
}

}  // namespace cemv::cli
