// `cemv replay MATRIX DIR_OR_FILES... [--format text|junit]` (docs/testgen.md):
// scenarios run on the reference runtime, pass or fail per test and step.
// Exit 0 every test passes, 1 some test fails, 2 invalid input (a matrix
// that does not load, a file that cannot be read or does not load against
// the matrix).
#include <iostream>

#include "cli/commands.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "testgen/testgen.hpp"
#include "reports/xml_text.hpp"

namespace cemv::cli {

using reports::html_escape;

namespace {

struct ReplayArgs {
  std::string matrix_file;
  std::vector<std::string> paths;
  std::string format = "text";
  std::string output = "-";
  bool quiet = false;
};

std::string text_report(const model::Matrix& m, const testgen::ReplayResult& r) {
  std::string s;
  std::size_t expectations = 0;
  for (const auto& t : r.tests) {
    expectations += t.expectations;
    if (!t.load_error.empty()) {
      s += "FAIL " + t.name + ": does not load against the matrix\n  " + t.load_error + "\n";
      continue;
    }
    s += std::string(t.passed ? "PASS " : "FAIL ") + t.name + " (" + std::to_string(t.steps.size()) + " steps, " +
         std::to_string(t.cycles) + " cycles, " + std::to_string(t.expectations) + " expectations)\n";
    for (const auto& st : t.steps)
      if (!st.passed) {
        s += "  step " + std::to_string(st.step + 1) + " FAIL\n";
        for (const auto& f : st.failures) s += "    " + f + "\n";
      }
  }
  s += "matrix " + m.name + ": " + std::to_string(r.passed()) + " of " + std::to_string(r.tests.size()) +
       " tests passed, " + std::to_string(expectations) + " expectations\n" + (r.all_passed() ? "PASS\n" : "FAIL\n");
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
    std::string msg = t.load_error;
    for (const auto& st : t.steps)
      for (const auto& f : st.failures) msg += (msg.empty() ? "" : "\n") + f;
    s += ">\n   <failure message=\"" + html_escape(t.load_error.empty() ? "expectation failed" : "does not load") + "\">" +
         html_escape(msg) + "</failure>\n  </testcase>\n";
  }
  s += " </testsuite>\n</testsuites>\n";
  return s;
}

int run_replay(const ReplayArgs& a) {
  if (a.format != "text" && a.format != "junit") throw CLI::ValidationError("--format", "expected text or junit");
  model::Matrix m = load_valid_matrix(a.matrix_file, "replayed");
  check_writable(a.output);
  std::vector<std::filesystem::path> paths(a.paths.begin(), a.paths.end());
  testgen::ReplayResult r = testgen::replay_files(m, paths);
  // --quiet: no report on standard output, but a line per test that fails.
  if (!(a.quiet && a.format == "text" && a.output == "-"))
    write_output(a.output, a.format == "junit" ? junit_report(m, r) : text_report(m, r));
  if (a.quiet)
    for (const auto& t : r.tests)
      if (!t.passed) std::cerr << "FAIL " << t.name << (t.load_error.empty() ? "" : ": does not load against the matrix") << "\n";
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
  cmd->add_flag("-q,--quiet", a.quiet, "print nothing but errors and a line per test that fails");
  cmd->footer("Exit status: 0 every test passes; 1 some test fails; 2 invalid input.\n");
  cmd->callback([&ctx]() { ctx.exit_code = run_replay(a); });
}

}  // namespace cemv::cli
