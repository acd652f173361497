// `cemv record MATRIX FILLED.csv... [-o FILE] [--changed-from OLD --previous
// ACCEPTANCE]` (docs/acceptance.md): filled field checklists back into the
// matrix's acceptance status, cemv-acceptance/1.
//
// Exit status: 0 recorded, no deviation; 1 recorded, some step deviates;
// 2 bad input (a checklist of another matrix, an unknown step, a malformed
// row: FILE:LINE: error: ...); 4 internal error (the field suite does not replay).
#include <iostream>
#include <map>

#include "checker/prover.hpp"
#include "cli/commands.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "cli/testgen_change.hpp"
#include "formats/acceptance.hpp"
#include "formats/diagnostics.hpp"
#include "formats/matrix_json.hpp"
#include "testgen/field.hpp"

namespace cemv::cli {

namespace {

struct RecordArgs {
  std::string matrix_file;
  std::vector<std::string> filled;
  std::string out = "-";
  std::string changed_from;  // OLD matrix
  std::string previous;      // OLD's acceptance record
  double diff_timeout_s = 0.0;
};

// Elements the change did not touch keep OLD's status where no new result
// speaks for them (docs/acceptance.md, "After a change").
std::size_t carry_over(const RecordArgs& a, const model::Matrix& m, formats::Acceptance& acc) {
  const model::Matrix old = load_valid_matrix(a.changed_from, "compared");
  const formats::Acceptance prev = formats::read_acceptance(formats::read_text_file(a.previous), a.previous);
  if (prev.signature != formats::signature(old))
    throw formats::LoadError({{a.previous, "the acceptance record is for the matrix with signature " + prev.signature +
                                               ", not " + a.changed_from + " (signature " + formats::signature(old) + ")"}});
  testgen::TestgenOptions o;
  const ChangeScope scope = apply_change(a.changed_from, a.matrix_file, m, a.diff_timeout_s, o);
  if (!scope.partial || !o.elements) return 0;  // the whole matrix is retested: nothing carries over
  std::map<std::string, const formats::ElementAcceptance*> before;
  for (const auto& e : prev.elements) before[e.key()] = &e;
  auto touched = [&](const formats::ElementAcceptance& e) {
    const bool c = e.cause && o.elements->count({model::Node::Kind::Cause, e.cause});
    const bool f = e.effect && o.elements->count({model::Node::Kind::Effect, e.effect});
    return c || f;
  };
  auto name_of = [](const formats::Acceptance& x, const std::string& key) {
    for (const auto& e : x.elements)
      if (e.key() == key) return e.name;
    return std::string();
  };
  std::size_t n = 0;
  for (auto& e : acc.elements) {
    if (e.status != formats::AcceptanceStatus::NotTested || touched(e)) continue;
    auto it = before.find(e.key());
    if (it == before.end()) continue;
    // The same element by name as well as number (a renumbered matrix matches nothing).
    bool same = it->second->name == e.name;
    if (e.kind == formats::ElementKind::Intersection)
      same = name_of(prev, "cause[" + std::to_string(e.cause) + "]") == name_of(acc, "cause[" + std::to_string(e.cause) + "]") &&
             name_of(prev, "effect[" + std::to_string(e.effect) + "]") == name_of(acc, "effect[" + std::to_string(e.effect) + "]");
    if (!same || it->second->status == formats::AcceptanceStatus::NotTested) continue;
    e.status = it->second->status;
    e.deviations = it->second->deviations;
    e.carried_over = a.previous + " (signature " + prev.signature + ")";
    ++n;
  }
  return n;
}

int run_record(const RecordArgs& a, Context& ctx) {
  const model::Matrix m = load_valid_matrix(a.matrix_file, "recorded");
  if (a.changed_from.empty() != a.previous.empty())
    throw std::invalid_argument("--changed-from OLD and --previous ACCEPTANCE go together");
  if (a.out != "-") check_writable(a.out);
  std::vector<formats::FilledChecklist> filled;
  for (const auto& f : a.filled) filled.push_back(formats::read_filled_checklist(formats::read_text_file(f), f));
  testgen::FieldOptions fo;
  fo.resolution = filled.front().resolution;
  testgen::FieldSuite suite;
  try {
    suite = testgen::generate_field_suite(m, fo);
  } catch (const checker::InternalError& e) {
    std::cerr << "internal error: " << e.what() << "\n(a bug in cemv: please report it with the matrix)\n";
    return 4;
  }
  formats::Acceptance acc = testgen::record_acceptance(m, suite, filled, std::string("cemv ") + CEMV_VERSION);
  std::size_t carried = 0;
  if (!a.changed_from.empty()) {
    try {
      carried = carry_over(a, m, acc);
    } catch (const checker::InternalError& e) {
      std::cerr << "internal error: " << e.what() << "\n";
      return 4;
    }
  }
  write_output(a.out, formats::acceptance_json(acc));
  std::map<std::string, int> steps, elements;
  for (const auto& s : acc.steps) steps[formats::to_string(s.status)]++;
  for (const auto& e : acc.elements) elements[formats::to_string(e.status)]++;
  if (!ctx.quiet && a.out != "-") {
    std::string text = "matrix " + m.name + " signature " + acc.signature + "\n" + std::to_string(acc.steps.size()) +
                       " steps: " + std::to_string(steps["ok"]) + " ok, " + std::to_string(steps["deviation"]) +
                       " deviation, " + std::to_string(steps["open"]) + " open\n" +
                       std::to_string(acc.elements.size()) + " elements: " + std::to_string(elements["accepted"]) +
                       " accepted, " + std::to_string(elements["deviation"]) + " deviation, " +
                       std::to_string(elements["not-tested"]) + " not-tested" +
                       (carried ? " (" + std::to_string(carried) + " carried over from " + a.previous + ")" : "") +
                       "\n";
    for (const auto& e : acc.elements)
      for (const auto& d : e.deviations) text += "deviation " + e.key() + ": " + d + "\n";
    text += "acceptance: " + a.out + "\n";
    write_output("-", text);
  }
  return steps["deviation"] > 0 ? 1 : 0;
}

}  // namespace

void add_record_commands(CLI::App& app, Context& ctx) {
  auto* cmd = app.add_subcommand("record", "Record filled field checklists as the matrix's acceptance status "
                                           "(docs/acceptance.md)");
  static RecordArgs a;
  cmd->add_option("MATRIX", a.matrix_file, "cemv-matrix/1 file the checklists were generated from")->required();
  cmd->add_option("FILLED", a.filled, "filled field checklists (DIR/field/checklist.csv with Result, Initials, Date)")
      ->required();
  cmd->add_option("-o,--output", a.out, "the cemv-acceptance/1 file ('-' = standard output)")
      ->capture_default_str()
      ->type_name("FILE");
  cmd->add_option("--changed-from", a.changed_from,
                  "the accepted version OLD: the elements the change did not touch keep their status "
                  "(with --previous)")
      ->type_name("OLD");
  cmd->add_option("--previous", a.previous, "OLD's acceptance record (cemv-acceptance/1)")->type_name("ACCEPTANCE");
  cmd->add_option("--diff-timeout", a.diff_timeout_s,
                  "with --changed-from: wall-clock limit per effect of the comparison, seconds (0 = none)")
      ->capture_default_str()
      ->type_name("S");
  add_quiet_flag(cmd, ctx);
  cmd->footer(
      "Exit status: 0 recorded, no deviation; 1 some step records a deviation; 2 bad input (FILE:LINE: error:\n"
      "a checklist of another matrix, an unknown step, a malformed row); 4 internal error.\n");
  cmd->callback([&ctx]() { ctx.exit_code = run_record(a, ctx); });
}

}  // namespace cemv::cli
