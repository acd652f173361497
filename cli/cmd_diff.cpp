// `cemv diff OLD NEW [--format text|md|html|json]`: the structural and the
// semantic comparison of two versions of a matrix (docs/change-acceptance.md).
// Exit 0 no effect's behaviour changed, 1 some effect's behaviour changed,
// 2 invalid input, 3 some effect undecided within --timeout, 4 internal error
// (a distinguishing run that does not replay on both runtimes).
#include <cctype>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <string>

#include "checker/counterexample.hpp"
#include "checker/prover.hpp"
#include "cli/commands.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "cli/scenario_defaults.hpp"
#include "diff/print.hpp"
#include "formats/matrix_json.hpp"
#include "model/validate.hpp"

namespace cemv::cli {

namespace {

struct DiffArgs {
  std::string old_file, new_file;
  std::string format = "text";
  std::string output = "-";
  std::string out_dir;
  double timeout_s = 0.0;  // --timeout: the user's wall clock; work budgets bound the rest
  double total_timeout_s = 0.0;  // --total-timeout: the whole run (0 = none)
  bool quiet = false;
};

std::string file_stem(const std::string& group) {
  std::string s;
  for (char c : group) s += std::isalnum(static_cast<unsigned char>(c)) ? c : (c == ']' ? '\0' : '_');
  std::string out;
  for (char c : s)
    if (c) out += c;
  return out;
}

// A distinguishing run as a scenario of NEW expecting OLD's value: it fails
// on NEW, and its inputs replayed on OLD give that value (both checked by
// the equivalence checker before the file is written).
void write_scenarios(const DiffArgs& a, diff::DiffReport& r) {
  if (a.out_dir.empty()) return;
  for (const auto& e : r.behaviour.effects) {
    if (!e.result.distinction || !e.new_id) continue;
    const auto& d = *e.result.distinction;
    // Under NEW's own numbers (after a move, the run mapped back and
    // confirmed on NEW by the semantic comparison).
    const std::string file = (std::filesystem::path(a.out_dir) / (file_stem(e.result.group) + ".diff.scenario.json")).string();
    write_output(file, scenario_for_both(*r.new_m, *r.old_m, e.new_inputs,
                                         "Where " + r.new_m->name + " (NEW) differs from OLD: " + e.new_key +
                                             " in cycle " + std::to_string(d.cycle + 1) +
                                             "; the expectation is OLD's value, so NEW fails it",
                                         {{e.new_key, d.type, d.value_a}}));
    r.scenarios.emplace_back(e.result.group, file);
  }
}

int run_diff(const DiffArgs& a) {
  if (a.format != "text" && a.format != "md" && a.format != "html" && a.format != "json" && a.format != "sarif")
    throw std::runtime_error("diff: --format '" + a.format + "': expected text, md, html, json or sarif");
  if (a.timeout_s < 0 || a.total_timeout_s < 0) throw std::runtime_error("diff: time limits must not be negative");
  // --total-timeout: the run's one cancel token; the effects it leaves are
  // undecided ("time limit"), the report is written.
  checker::CancelToken cancel(a.total_timeout_s > 0
                                  ? checker::Clock::now() + std::chrono::duration_cast<checker::Clock::duration>(
                                                                std::chrono::duration<double>(a.total_timeout_s))
                                  : checker::Clock::time_point::max());
  if (a.old_file == "-" && a.new_file == "-") throw std::runtime_error("diff: '-' (standard input) can be read only once");
  // The texts are kept: SARIF places each change at its element's line. A
  // matrix with validation errors still gets its structural comparison; only
  // the behaviour, which needs an executable matrix, is not compared.
  const std::string old_text = read_input(a.old_file), new_text = read_input(a.new_file);
  const model::Matrix old_m = formats::parse_matrix(old_text, input_name(a.old_file));
  const model::Matrix new_m = formats::parse_matrix(new_text, input_name(a.new_file));
  check_writable(a.output);
  if (!a.out_dir.empty()) check_writable_directory(a.out_dir);
  std::vector<std::string> not_compared;
  for (const auto& [side, m] : {std::pair<const char*, const model::Matrix*>{"OLD", &old_m}, {"NEW", &new_m}})
    for (const auto& d : model::validate(*m))
      if (d.severity == model::Severity::Error)
        not_compared.push_back(std::string(side) + ": " + d.rule + " " + d.element + " (" + d.section + "): " + d.message);
  diff::DiffReport r;
  r.old_m = &old_m;
  r.new_m = &new_m;
  r.old_file = input_name(a.old_file);
  r.new_file = input_name(a.new_file);
  r.old_text = old_text;
  r.new_text = new_text;
  r.old_signature = formats::signature(old_m);
  r.new_signature = formats::signature(new_m);
  r.structure = diff::compare_structure(old_m, new_m);
  r.not_compared = not_compared;
  if (not_compared.empty()) {
    diff::SemanticOptions o;
    o.timeout_s = a.timeout_s;
    o.cancel = &cancel;
    r.behaviour = diff::compare_behaviour(old_m, new_m, r.structure, o);
    write_scenarios(a, r);
  }
  std::string text = a.format == "json"    ? diff::to_json(r)
                     : a.format == "sarif" ? diff::to_sarif(r, CEMV_VERSION)
                     : a.format == "md"   ? diff::to_markdown(r)
                     : a.format == "html" ? diff::to_html(r)
                                          : diff::to_text(r);
  // --quiet: the text report on standard output is what it silences; a file,
  // or a format asked for by name, is still written (README, "Every command").
  if (!(a.quiet && a.format == "text" && a.output == "-")) write_output(a.output, text);
  return r.exit_code();
}

}  // namespace

void add_diff_commands(CLI::App& app, Context& ctx) {
  auto* cmd = app.add_subcommand("diff", "Compare two versions of a matrix: structure and behaviour per effect "
                                         "(docs/change-acceptance.md)");
  static DiffArgs a;
  cmd->add_option("OLD", a.old_file, "the accepted version (cemv-matrix/1, '-' = standard input)")->required();
  cmd->add_option("NEW", a.new_file, "the changed version")->required();
  cmd->add_option("--format", a.format, "text, md, html, json (cemv-diff/1) or sarif (a result at each change's line)")
      ->capture_default_str();
  cmd->add_option("-o,--output", a.output, "write the report to FILE ('-' = standard output)")->type_name("FILE");
  cmd->add_option("--out", a.out_dir, "folder for the distinguishing scenarios (created if missing)")
      ->type_name("DIR");
  cmd->add_option("--total-timeout", a.total_timeout_s,
                  "wall-clock limit of the whole run, seconds (0 = none; the effects it leaves are undecided)")
      ->type_name("S");
  cmd->add_option("--timeout", a.timeout_s, "wall-clock limit per effect, seconds (0 = none; an effect it cuts short is undecided)")
      ->capture_default_str()
      ->type_name("S");
  cmd->add_flag("-q,--quiet", a.quiet, "print nothing but errors (and the output asked for)");
  cmd->footer(
      "Exit status: 0 no effect's behaviour changed (at most non-critical or behaviour-equivalent edits);\n"
      "1 some effect's behaviour changed; 2 invalid input (a matrix with validation errors: the structural\n"
      "comparison is written, the behaviour is not compared); 3 some effect undecided within --timeout;\n"
      "4 internal error (a distinguishing run that does not replay on both runtimes).\n");
  cmd->callback([&ctx]() {
    try {
      ctx.exit_code = run_diff(a);
    } catch (const checker::InternalError& e) {
      std::cerr << "internal error: " << e.what() << "\n";
      ctx.exit_code = 4;
    }
  });
}

}  // namespace cemv::cli
