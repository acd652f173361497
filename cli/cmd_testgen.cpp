// `cemv testgen MATRIX --out DIR [--sif N] [--jobs N]` (docs/testgen.md):
// the acceptance tests of a matrix as cemv-scenario/1 files, coverage.json
// and the checklist (Markdown, HTML, CSV), every file written atomically
// through cli/output.hpp.
//
// Exit status: 0 every objective covered or proved infeasible; 2 invalid
// input or an unwritable destination; 3 some objective undecided (a limit);
// 4 internal error (a generated test that does not replay green).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "checker/limits.hpp"
#include "checker/prover.hpp"
#include "cli/commands.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "cli/testgen_change.hpp"
#include "cli/progress.hpp"
#include "cli/trace_pictures.hpp"
#include "testgen/checklist.hpp"
#include "testgen/field.hpp"
#include "testgen/testgen.hpp"

namespace cemv::cli {

namespace {

struct TestgenArgs {
  std::string matrix_file;
  std::string out_dir;
  int sif = 0;
  int jobs = 1;
  // Budgets of work in millions of Z3 resource units (checker/limits.hpp):
  // about 0.5 to 1 s each on the reference machine, the same answer on every
  // machine.
  double budget = 20.0;
  double proof_budget = 3.0;
  bool mutation_report = false;
  std::string changed_from;  // OLD: only the tests the change needs
  double diff_timeout_s = 0.0;
  double total_timeout_s = 0.0;  // --total-timeout: the whole run (0 = none)
  bool quiet = false;
  bool verbose = false;
  double resolution = 0.1;   // of the field suite's values
  bool field_only = false;   // only DIR/field/ (no search: seconds)
};

// The field suite into DIR/field/ (docs/testgen.md, "Field suite"): its
// scenarios, the checklist in three forms. Returns the summary lines.
std::string write_field_suite(const model::Matrix& m, const TestgenArgs& a, const std::string& tool,
                              const checker::CancelToken& cancel, testgen::FieldSuite& fs) {
  const std::filesystem::path dir = std::filesystem::path(a.out_dir) / "field";
  testgen::FieldOptions fo;
  fo.resolution = a.resolution;
  fo.cancel = &cancel;
  if (a.matrix_file != "-") {
    std::error_code ec;
    auto rel = std::filesystem::relative(std::filesystem::absolute(a.matrix_file), std::filesystem::absolute(dir), ec);
    fo.matrix_ref = ec ? std::filesystem::absolute(a.matrix_file).string() : rel.generic_string();
  }
  fs = testgen::generate_field_suite(m, fo);
  check_writable_directory(dir.string());
  for (const auto& t : fs.tests) write_output((dir / t.file_name).string(), t.scenario_json);
  const std::string date = testgen::report_date();
  write_output((dir / "checklist.md").string(), testgen::field_checklist_markdown(m, fs, date, tool));
  write_output((dir / "checklist.html").string(), testgen::field_checklist_html(m, fs, date, tool));
  write_output((dir / "checklist.csv").string(), testgen::field_checklist_csv(m, fs, date, tool));
  std::size_t steps = 0;
  for (const auto& t : fs.tests) steps += t.steps.size();
  return "field suite: " + std::to_string(fs.tests.size()) + " loop tests, " + std::to_string(steps) +
         " steps, about " + std::to_string((fs.field_s + 59) / 60) + " min on the plant; " +
         std::to_string(fs.witnessed()) + " of " + std::to_string(fs.objectives.size()) +
         " objectives witnessed in the field, the rest automated-only; every test replays green (" +
         (dir / "checklist.md").string() + ")\n" +
         (fs.interrupted ? "field suite: the time limit (--total-timeout) ended it; the loops not built and the "
                           "objectives not decided are listed in its checklist\n"
                         : "");
}

int run_testgen(const TestgenArgs& a) {
  if (a.total_timeout_s < 0) throw std::invalid_argument("--total-timeout must not be negative");
  // --total-timeout: the run's one cancel token. Every search polls it; the
  // objectives it leaves are undecided ("time limit") and the suite holds
  // the tests made before, every one replayed green.
  checker::CancelToken cancel(a.total_timeout_s > 0
                                  ? checker::Clock::now() + std::chrono::duration_cast<checker::Clock::duration>(
                                                                std::chrono::duration<double>(a.total_timeout_s))
                                  : checker::Clock::time_point::max());
  model::Matrix m = load_valid_matrix(a.matrix_file, "tested");
  check_writable_directory(a.out_dir);
  if (!(a.resolution > 0.0) || a.resolution > 1000.0) throw std::invalid_argument("--resolution must be in (0, 1000]");
  const std::string tool = std::string("cemv ") + CEMV_VERSION;
  std::string field_summary;
  testgen::FieldSuite field;
  try {
    field_summary = write_field_suite(m, a, tool, cancel, field);
  } catch (const checker::InternalError& e) {
    std::cerr << "internal error: " << e.what() << "\n(a bug in cemv: please report it with the matrix)\n";
    return 4;
  }
  if (a.field_only) {
    if (!a.quiet) write_output("-", "matrix " + m.name + "\n" + field_summary);
    const int code = field.interrupted ? 3 : 0;
    return a.mutation_report
               ? std::max(code, field_mutation_report(m, nullptr, field, a.out_dir, testgen::report_date(), tool, &cancel))
               : code;
  }
  testgen::TestgenOptions o;
  if (a.sif > 0) o.sif = a.sif;
  o.jobs = a.jobs;
  o.cancel = &cancel;
  if (!(a.budget > 0) || !(a.proof_budget > 0)) throw std::invalid_argument("--budget and --proof-budget must be positive");
  o.objective_work = static_cast<checker::Work>(a.budget * checker::kMega);
  o.proof_work = static_cast<checker::Work>(a.proof_budget * checker::kMega);
  if (a.matrix_file != "-") {
    std::error_code ec;
    auto rel = std::filesystem::relative(std::filesystem::absolute(a.matrix_file),
                                         std::filesystem::absolute(a.out_dir), ec);
    o.matrix_ref = ec ? std::filesystem::absolute(a.matrix_file).string() : rel.generic_string();
  }
  if (a.verbose)
    o.on_decided = [](const testgen::ObjectiveResult& r) {
      char t[32];
      std::snprintf(t, sizeof t, "%.2f s", r.seconds);
      std::cerr << testgen::to_string(r.status) << " " << r.objective.id << " [" << r.method << ", " << t << "]"
                << (r.reason.empty() ? "" : " " + r.reason) << "\n";
    };
  // On a terminal (not --quiet, not -v, whose lines are the progress): objectives decided / total.
  std::size_t objectives = 0;
  for (const auto& ob : testgen::derive_objectives(m)) objectives += !o.sif || ob.sif == *o.sif;
  Progress progress("cemv testgen", objectives, "objectives", !a.quiet && !a.verbose && Progress::terminal(),
                    std::cerr);
  if (!a.verbose) o.on_decided = [&](const testgen::ObjectiveResult& r) { progress.finished(r.objective.id); };
  testgen::TestSuite suite;
  ChangeScope change;
  try {
    if (!a.changed_from.empty()) change = apply_change(a.changed_from, a.matrix_file, m, a.diff_timeout_s, o);
    suite = testgen::generate_tests(m, o);
  } catch (const checker::InternalError& e) {
    progress.stop();
    std::cerr << "internal error: " << e.what() << "\n(a bug in cemv: please report it with the matrix)\n";
    return 4;
  }
  const std::filesystem::path dir(a.out_dir);
  progress.stop();
  std::string diagrams;  // each test's timing diagram beside its scenario, named in the summary
  for (const auto& t : suite.tests) {
    write_output((dir / t.file_name).string(), t.scenario_json);
    const std::string svg = diagram_name((dir / t.file_name).string());
    write_output(svg, test_diagram(m, "Test " + t.description, t.inputs, t.checkpoints));
    diagrams += "diagram: " + svg + "\n";
  }
  auto header = testgen::checklist_header(m, suite, tool);
  header.preface_markdown = change.preface_markdown;
  header.preface_html = change.preface_html;
  header.preface_csv = change.preface_csv;
  write_output((dir / "coverage.json").string(), testgen::coverage_json(suite, tool));
  write_output((dir / "checklist.md").string(), testgen::checklist_markdown(m, suite, header));
  write_output((dir / "checklist.html").string(), testgen::checklist_html(m, suite, header));
  write_output((dir / "checklist.csv").string(), testgen::checklist_csv(m, suite, header));
  if (!a.quiet) {
    std::string text = "matrix " + suite.matrix_name + " signature " + suite.signature + "\n" +
                       std::to_string(suite.objectives.size()) + " objectives: " + std::to_string(suite.covered) +
                       " covered, " + std::to_string(suite.infeasible) + " infeasible, " +
                       std::to_string(suite.undecided) + " undecided\n" + std::to_string(suite.tests.size()) +
                       " tests, " + std::to_string(suite.total_steps) + " steps, " +
                       std::to_string(suite.total_cycles) + " scan cycles; every test replays green\n" + diagrams +
                       field_summary + change.summary;
    for (const auto& r : suite.objectives)
      if (r.status != testgen::ObjectiveStatus::Covered)
        text += std::string(testgen::to_string(r.status)) + " " + r.objective.id + ": " + r.objective.text + " (" +
                r.reason + ")\n";
    write_output("-", text);
  }
  int code = suite.undecided > 0 || field.interrupted ? 3 : 0;
  if (a.mutation_report)
    code = std::max(code, field_mutation_report(m, &suite, field, a.out_dir, testgen::report_date(), tool, &cancel));
  return code;
}

}  // namespace

void add_testgen_commands(CLI::App& app, Context& ctx) {
  auto* cmd = app.add_subcommand("testgen", "Generate the acceptance tests and checklist of a matrix (docs/testgen.md)");
  static TestgenArgs a;
  cmd->add_option("MATRIX", a.matrix_file, "cemv-matrix/1 file ('-' = standard input)")->required();
  cmd->add_option("--out", a.out_dir, "folder for the tests, coverage.json and the checklists (created if missing)")
      ->type_name("DIR")
      ->required();
  cmd->add_option("--sif", a.sif, "only the objectives of SIF group N")->type_name("N");
  cmd->add_option("--jobs", a.jobs, "SIF groups searched in parallel")->capture_default_str();
  cmd->add_option("--budget", a.budget,
                  "search work per objective, in millions of Z3 resource units (about 0.5-1 s each; "
                  "the same suite on every machine)")
      ->capture_default_str()
      ->type_name("W");
  cmd->add_option("--proof-budget", a.proof_budget,
                  "infeasibility proof work per objective, in millions of Z3 resource units")
      ->capture_default_str()
      ->type_name("W");
  cmd->add_flag("--mutation-report", a.mutation_report,
                "also decide, for every single-point mutant, equivalence and detection by the suite");
  cmd->add_option("--changed-from", a.changed_from,
                  "the accepted version OLD: only the tests the change needs, and a change checklist "
                  "(docs/change-acceptance.md)")
      ->type_name("OLD");
  cmd->add_option("--diff-timeout", a.diff_timeout_s,
                  "with --changed-from: wall-clock limit per effect of the comparison, seconds (0 = none; an "
                  "effect it cuts short is undecided)")
      ->capture_default_str()
      ->type_name("S");
  cmd->add_option("--total-timeout", a.total_timeout_s,
                  "wall-clock limit of the whole run, seconds (0 = none; the objectives it leaves are undecided, "
                  "the tests made before are written)")
      ->type_name("S");
  cmd->add_option("--resolution", a.resolution,
                  "field suite: the resolution values are set and printed with (the calibrator's, the tag unit's)")
      ->capture_default_str()
      ->type_name("R");
  cmd->add_flag("--field-only", a.field_only, "write only the field suite DIR/field/ (no search of the automated suite)");
  cmd->add_flag("-q,--quiet", a.quiet, "print nothing but errors");
  cmd->add_flag("-v,--verbose", a.verbose, "print each objective as it is decided (standard error)");
  cmd->footer(
      "Exit status: 0 every objective covered or proved infeasible; 2 invalid input or unwritable\n"
      "destination; 3 some objective undecided (a limit was reached); 4 internal error.\n");
  cmd->callback([&ctx]() { ctx.exit_code = run_testgen(a); });
}

}  // namespace cemv::cli
