// `cemv mutate MATRIX --out DIR [--equivalence] [--timeout S] [--suite DIR]`: every
// single-point mutant of a matrix as a cemv-matrix/1 file, with an index
// (cemv-mutants/1, docs/mutation.md); with --equivalence, each mutant decided
// equivalent or not on the product of the two transition systems, and a
// distinguishing scenario written for each one that is not.
// With --suite, the mutation adequacy report of an acceptance suite already
// written (`cemv testgen`'s folder, every *.scenario.json in it), as
// `cemv testgen --mutation-report` gives it for a suite it generates.
// Exit 0; with --equivalence 3 when a mutant stays undecided; 2 invalid
// input; 4 internal error (a distinguishing run the runtimes do not replay);
// with --suite 1 when a non-equivalent mutant survives the suite.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "checker/counterexample.hpp"
#include "checker/equivalence.hpp"
#include "checker/prover.hpp"
#include "cli/commands.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "cli/scenario_defaults.hpp"
#include "formats/matrix_json.hpp"
#include "mutate/mutants.hpp"
#ifdef CEMV_WITH_TESTGEN
#include "testgen/testgen.hpp"
#endif

namespace cemv::cli {

namespace {

using ordered_json = nlohmann::ordered_json;

struct MutateArgs {
  std::string matrix_file;
  std::string out_dir;
  bool equivalence = false;
  double timeout_s = 0.0;  // --timeout: the user's wall clock; work budgets bound the rest
  double total_timeout_s = 0.0;  // --total-timeout: the whole run (0 = none)
  bool list_operators = false;
  bool quiet = false;
  std::string suite_dir;
  int jobs = 1;  // --jobs: mutants decided at once with --suite
};

// The distinguishing run as a scenario of the original matrix that expects
// the original's value where the mutant differs: it passes on the original
// and fails on the mutant (a test that kills the mutant).
std::string killing_scenario(const model::Matrix& m, const mutate::Mutant& mu, const checker::Distinction& d) {
  return scenario_for_both(m, mu.matrix, d.run_a.inputs,
                           "Distinguishes mutant " + mu.id + " (" + mu.description + ", " + mu.element + ") from " +
                               m.name + ": " + d.key + " in cycle " + std::to_string(d.cycle + 1),
                           {{d.key, d.type, d.value_a}});
}

int run_mutate(const MutateArgs& a) {
  if (a.list_operators) {
    std::string text;
    for (const auto& op : mutate::operators()) text += std::string(op.name) + "  " + op.meaning + "\n";
    write_output("-", text);
    return 0;
  }
  if (a.out_dir.empty()) throw std::runtime_error("mutate: --out DIR is required");
  if (a.timeout_s < 0 || a.total_timeout_s < 0) throw std::runtime_error("mutate: time limits must not be negative");
  if (a.jobs < 1) throw std::runtime_error("mutate: --jobs must be at least 1");
  // --total-timeout: the run's one cancel token; the mutants it leaves are
  // undecided ("time limit"), every file is still written.
  checker::CancelToken cancel(a.total_timeout_s > 0
                                  ? checker::Clock::now() + std::chrono::duration_cast<checker::Clock::duration>(
                                                                std::chrono::duration<double>(a.total_timeout_s))
                                  : checker::Clock::time_point::max());
  const model::Matrix m = load_valid_matrix(a.matrix_file, "mutated");
  check_writable_directory(a.out_dir);
  const std::filesystem::path dir(a.out_dir);
  if (!a.suite_dir.empty()) {
#ifdef CEMV_WITH_TESTGEN
    testgen::TestSuite suite;
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(a.suite_dir, ec)) {
      const std::string name = e.path().filename().string();
      if (name.size() > 14 && name.ends_with(".scenario.json")) files.push_back(e.path());
    }
    if (ec || files.empty()) throw std::runtime_error("mutate: --suite " + a.suite_dir + ": no *.scenario.json test in this folder");
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
      std::ifstream in(f, std::ios::binary);
      std::ostringstream text;
      text << in.rdbuf();
      if (!in && !in.eof()) throw std::runtime_error("mutate: cannot read " + f.string());
      testgen::Test t;
      t.file_name = f.filename().string();
      t.scenario_json = text.str();
      suite.tests.push_back(std::move(t));
    }
    return mutation_report(m, suite, a.out_dir, &cancel, a.jobs);
#else
    throw std::runtime_error("mutate: --suite needs the test generator, which this build does not include");
#endif
  }
  mutate::MutantSet set = mutate::mutants(m);
  ordered_json index;
  index["format"] = "cemv-mutants/1";
  index["matrix"] = m.name;
  index["signature"] = formats::signature(m);
  int equivalent = 0, differs = 0, unknown = 0;
  ordered_json list = ordered_json::array();
  for (const auto& mu : set.mutants) {
    const std::string file = mu.id + ".json";
    write_output((dir / file).string(), formats::to_canonical_json(mu.matrix));
    ordered_json j;
    j["id"] = mu.id;
    j["operator"] = mu.op;
    j["element"] = mu.element;
    j["description"] = mu.description;
    j["file"] = file;
    j["signature"] = formats::signature(mu.matrix);
    if (a.equivalence) {
      checker::EquivalenceOptions o;
      o.timeout_s = a.timeout_s;
      o.cancel = &cancel;
      checker::GroupEquivalence r;
      if (cancel.cancelled()) {
        r.unknown = checker::UnknownReason::TimeLimit;
        r.reason = checker::to_string(r.unknown);
      } else {
        r = checker::decide_equivalence(m, mu.matrix, checker::whole_matrix(m, mu.matrix), o);
      }
      j["equivalence"] = checker::to_string(r.verdict);
      j["method"] = r.method;
      if (!r.reason.empty()) j["reason"] = r.reason;
      if (r.verdict == checker::EquivalenceVerdict::Equivalent) ++equivalent;
      if (r.verdict == checker::EquivalenceVerdict::Differs) ++differs;
      if (r.verdict == checker::EquivalenceVerdict::Unknown) ++unknown;
      if (r.distinction) {
        const auto& d = *r.distinction;
        const std::string scen = mu.id + ".distinguishing.scenario.json";
        write_output((dir / scen).string(), killing_scenario(m, mu, d));
        ordered_json dj;
        dj["key"] = d.key;
        dj["cycle"] = d.cycle + 1;
        dj["original"] = d.value_a;
        dj["mutant"] = d.value_b;
        dj["scenario"] = scen;
        j["distinguishing"] = dj;
      }
    }
    list.push_back(j);
  }
  index["mutants"] = list;
  ordered_json refused = ordered_json::array();
  for (const auto& r : set.refused)
    refused.push_back(ordered_json{{"id", r.id}, {"operator", r.op}, {"element", r.element},
                                   {"description", r.description}, {"reason", r.reason}});
  index["refused"] = refused;
  write_output((dir / "mutants.json").string(), index.dump(1) + "\n");
  std::string summary = m.name + ": " + std::to_string(set.mutants.size()) + " mutants written to " + a.out_dir +
                        " (" + std::to_string(set.refused.size()) + " single-point edits refused by validation)\n";
  if (a.equivalence)
    summary += "equivalent " + std::to_string(equivalent) + ", non-equivalent " + std::to_string(differs) +
               ", undecided " + std::to_string(unknown) + "\n";
  if (!a.quiet) write_output("-", summary);
  return unknown > 0 ? 3 : 0;
}

}  // namespace

void add_mutate_commands(CLI::App& app, Context& ctx) {
  auto* cmd = app.add_subcommand("mutate", "Write every single-point mutant of a matrix (docs/mutation.md)");
  static MutateArgs a;
  cmd->add_option("MATRIX", a.matrix_file, "cemv-matrix/1 file ('-' = standard input)");
  cmd->add_option("--out", a.out_dir, "folder for the mutants and mutants.json (created if missing)")
      ->type_name("DIR");
  cmd->add_flag("--equivalence", a.equivalence,
                "decide each mutant equivalent or not (product of the transition systems) and write a "
                "distinguishing scenario for each non-equivalent one");
  cmd->add_option("--timeout", a.timeout_s, "wall-clock limit per mutant with --equivalence, seconds (0 = none; a mutant it cuts short is undecided)")
      ->capture_default_str()
      ->type_name("S");
  cmd->add_option("--total-timeout", a.total_timeout_s,
                  "wall-clock limit of the whole run with --equivalence or --suite, seconds (0 = none; the "
                  "mutants it leaves are undecided)")
      ->type_name("S");
  cmd->add_flag("--list-operators", a.list_operators, "print the mutation operators and exit");
  cmd->add_flag("-q,--quiet", a.quiet, "print nothing but errors (no summary)");
  cmd->add_option("--suite", a.suite_dir,
                  "the mutation report of the acceptance suite in this folder (cemv testgen's tests): "
                  "mutation-report.json and .md into --out")
      ->type_name("DIR");
  cmd->add_option("--jobs", a.jobs, "mutants decided at once with --suite (the report does not depend on it)")
      ->capture_default_str()
      ->type_name("N");
  cmd->footer(
      "Exit status: 0 done; 2 invalid input or unwritable folder; 3 some mutant's equivalence undecided\n"
      "(--equivalence, --suite); 1 a non-equivalent mutant survives the suite (--suite); 4 internal error\n"
      "(a distinguishing run the runtimes do not reproduce).\n");
  cmd->callback([&ctx]() {
    if (!a.list_operators && a.matrix_file.empty()) throw CLI::RequiredError("MATRIX");
    try {
      ctx.exit_code = run_mutate(a);
    } catch (const checker::InternalError& e) {
      std::cerr << "internal error: " << e.what() << "\n";
      ctx.exit_code = 4;
    }
  });
}

}  // namespace cemv::cli
