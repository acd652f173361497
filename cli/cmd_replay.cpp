// `cemv replay MATRIX DIR_OR_FILES... [--format text|junit] [--plc PROGRAM
// [--map MAP]]` (docs/testgen.md, docs/plc.md): scenarios run on the
// reference runtime, or on a PLC program's interpreter through its map, pass
// or fail per test and step.
// Exit 0 every test passes, 1 some test fails, 2 invalid input (a matrix
// that does not load, a file that cannot be read or does not load against
// the matrix).
#include <iostream>

#include "cli/commands.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "testgen/testgen.hpp"
#include "reports/xml_text.hpp"
#ifdef CEMV_WITH_PLC
#include "cli/plc_program.hpp"
#endif

namespace cemv::cli {

using reports::html_escape;

namespace {

struct ReplayArgs {
  std::string matrix_file;
  std::vector<std::string> paths;
  std::string format = "text";
  std::string output = "-";
  std::string plc, map, pou;  // --plc: the program replayed instead of the runtime
  bool quiet = false;
};

// `on`: what the suite ran on, for the report's first line ("" = the runtime).
std::string text_report(const model::Matrix& m, const testgen::ReplayResult& r, const std::string& on) {
  std::string s = on.empty() ? "" : on;
  std::size_t expectations = 0, skipped = 0;
  for (const auto& t : r.tests) {
    expectations += t.expectations;
    skipped += t.skipped;
    if (!t.load_error.empty()) {
      s += "FAIL " + t.name + ": does not load against the matrix\n  " + t.load_error + "\n";
      continue;
    }
    if (!t.not_run.empty()) {
      s += "FAIL " + t.name + ": not run on the program: " + t.not_run + "\n";
      continue;
    }
    s += std::string(t.passed ? "PASS " : "FAIL ") + t.name + " (" + std::to_string(t.steps.size()) + " steps, " +
         std::to_string(t.cycles) + " cycles, " + std::to_string(t.expectations) + " expectations" +
         (t.skipped ? ", " + std::to_string(t.skipped) + " on status the program does not have" : std::string()) +
         ")\n";
    for (const auto& st : t.steps)
      if (!st.passed) {
        s += "  step " + std::to_string(st.step + 1) + " FAIL\n";
        for (const auto& f : st.failures) s += "    " + f + "\n";
      }
  }
  s += (on.empty() ? "matrix " + m.name : "program") + ": " + std::to_string(r.passed()) + " of " +
       std::to_string(r.tests.size()) + " tests passed, " + std::to_string(expectations) + " expectations" +
       (on.empty() ? std::string() : ", " + std::to_string(skipped) + " expectations on status not checked") + "\n" +
       (r.all_passed() ? "PASS\n" : "FAIL\n");
  return s;
}

std::string junit_report(const model::Matrix& m, const testgen::ReplayResult& r) {
  std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += "<testsuites name=\"cemv replay\" tests=\"" + std::to_string(r.tests.size()) + "\" failures=\"" +
       std::to_string(r.tests.size() - r.passed()) + "\">\n";
  s += " <testsuite name=\"" + html_escape(m.name) + "\" tests=\"" + std::to_string(r.tests.size()) + "\" failures=\"" +
       std::to_string(r.tests.size() - r.passed()) + "\">\n";
  for (const auto& t : r.tests) {
    s += "  <testcase classname=\"" + html_escape(m.name) + "\" name=\"" + html_escape(t.name) + "\"";
    if (t.passed) {
      s += "/>\n";
      continue;
    }
    std::string msg = !t.not_run.empty() ? "not run on the program: " + t.not_run : t.load_error;
    for (const auto& st : t.steps)
      for (const auto& f : st.failures) msg += (msg.empty() ? "" : "\n") + f;
    s += ">\n   <failure message=\"" + html_escape(!t.not_run.empty()        ? "not run on the program"
                                    : t.load_error.empty() ? "expectation failed"
                                                           : "does not load") + "\">" +
         html_escape(msg) + "</failure>\n  </testcase>\n";
  }
  s += " </testsuite>\n</testsuites>\n";
  return s;
}

int run_replay(const ReplayArgs& a) {
  if (a.format != "text" && a.format != "junit") throw CLI::ValidationError("--format", "expected text or junit");
  if (a.plc.empty() && (!a.map.empty() || !a.pou.empty()))
    throw CLI::ValidationError("--map", "--map and --pou apply to --plc PROGRAM");
  model::Matrix m = load_valid_matrix(a.matrix_file, "replayed");
  check_writable(a.output);
  std::vector<std::filesystem::path> paths(a.paths.begin(), a.paths.end());
  testgen::ReplayResult r;
  std::string on;
  if (a.plc.empty()) {
    r = testgen::replay_files(m, paths);
  } else {
#ifdef CEMV_WITH_PLC
    const auto program = load_plc_program(m, a.plc, a.map, a.pou);
    PlcReplayTarget target(m, *program);
    r = testgen::replay_files(m, paths, &target);
    on = "program " + program->pou + " in " + program->file + " (sha256 " + program->sha256 + "), map " +
         program->map_source + ", against matrix " + m.name + "\nassumptions:" +
         (program->map.assumptions.empty() ? " none" : "") + "\n";
    for (const auto& x : program->map.assumptions) on += "  - " + x + "\n";
#else
    throw CLI::ValidationError("--plc", "this build has no PLC front end");
#endif
  }
  // --quiet: no report on standard output, but a line per test that fails.
  if (!(a.quiet && a.format == "text" && a.output == "-"))
    write_output(a.output, a.format == "junit" ? junit_report(m, r) : text_report(m, r, on));
  if (a.quiet)
    for (const auto& t : r.tests)
      if (!t.passed)
        std::cerr << "FAIL " << t.name
                  << (!t.load_error.empty() ? ": does not load against the matrix"
                      : !t.not_run.empty()  ? ": not run on the program"
                                            : "")
                  << "\n";
  for (const auto& t : r.tests)
    if (!t.load_error.empty()) return 2;
  return r.all_passed() ? 0 : 1;
}

}  // namespace

void add_replay_commands(CLI::App& app, Context& ctx) {
  auto* cmd = app.add_subcommand("replay", "Run test scenarios on the reference runtime (docs/testgen.md)");
  static ReplayArgs a;
  cmd->add_option("MATRIX", a.matrix_file, "cemv-matrix/1 file ('-' = standard input)")->required();
  cmd->add_option("DIR_OR_FILES", a.paths, "scenario files, or folders of *.scenario.json")->required();
  cmd->add_option("--format", a.format, "text or junit")->capture_default_str();
  cmd->add_option("-o,--output", a.output, "write the report to FILE ('-' = standard output)")->type_name("FILE");
  cmd->add_option("--plc", a.plc, "run the tests on this PLC program (Structured Text or PLCopen XML) instead of the runtime")
      ->type_name("PROGRAM");
  cmd->add_option("--map", a.map, "with --plc: the map (cemv-plc-map/1); without it, found by name")->type_name("MAP");
  cmd->add_option("--pou", a.pou, "with --plc: the PROGRAM to run (default: the map's, or the file's only one)")
      ->type_name("NAME");
  cmd->add_flag("-q,--quiet", a.quiet, "print nothing but errors and a line per test that fails");
  cmd->footer("Exit status: 0 every test passes; 1 some test fails (with --plc: also a test that issues a command\n"
              "the program does not implement); 2 invalid input.\n");
  cmd->callback([&ctx]() { ctx.exit_code = run_replay(a); });
}

}  // namespace cemv::cli
