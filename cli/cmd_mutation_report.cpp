// `cemv testgen MATRIX --out DIR --mutation-report`: the mutation adequacy of
// the generated suite (docs/mutation.md), written as DIR/mutation-report.json
// (cemv-mutation-report/1) and DIR/mutation-report.md, with one summary line.
// Built only with the test generator; `cemv testgen` calls it through the
// declaration in cli/commands.hpp.
#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>

#include "cli/output.hpp"
#include "cli/commands.hpp"
#include "mutate/mutation_report.hpp"
#include "testgen/field.hpp"

namespace cemv::cli {

namespace {

mutate::MutationReport write_report(const model::Matrix& m, const testgen::TestSuite& suite, const std::string& out_dir,
                                    const std::string& label, checker::CancelToken* cancel) {
  mutate::MutationOptions o;
  o.cancel = cancel;
  const mutate::MutationReport r = mutate::mutation_report(m, suite, o);
  const std::filesystem::path dir(out_dir);
  write_output((dir / "mutation-report.json").string(), mutate::report_json(r));
  write_output((dir / "mutation-report.md").string(), mutate::report_markdown(r));
  write_output("-", label + "mutation report: mutants " + std::to_string(r.mutants.size()) + ", equivalent " +
                        std::to_string(r.equivalent) + ", detected " + std::to_string(r.detected) + ", survived " +
                        std::to_string(r.survived) + ", undecided " + std::to_string(r.undecided) + "\n");
  return r;
}

}  // namespace

int field_mutation_report(const model::Matrix& m, const testgen::TestSuite* automated, testgen::FieldSuite& field,
                          const std::string& out_dir, const std::string& date, const std::string& tool,
                          checker::CancelToken* cancel) {
  int code = 0;
  std::optional<mutate::MutationReport> a;
  if (automated) {
    a = write_report(m, *automated, out_dir, "", cancel);
    code = a->exit_code();
  }
  testgen::TestSuite fs;
  for (const auto& t : field.tests) {
    testgen::Test x;
    x.file_name = t.file_name;
    x.scenario_json = t.scenario_json;
    fs.tests.push_back(std::move(x));
  }
  const std::filesystem::path dir = std::filesystem::path(out_dir) / "field";
  const mutate::MutationReport f = write_report(m, fs, dir.string(), "field suite ", cancel);
  if (!a) return std::max(code, f.exit_code());
  // The two reports list the same mutants in the same order (one operator set).
  testgen::FieldMutation mu;
  mu.mutants = f.mutants.size();
  for (std::size_t i = 0; i < f.mutants.size() && i < a->mutants.size(); ++i) {
    const auto& fm = f.mutants[i];
    const auto& am = a->mutants[i];
    const bool equivalent = fm.status == mutate::MutantStatus::Equivalent || am.status == mutate::MutantStatus::Equivalent;
    mu.equivalent += equivalent;
    mu.field += fm.status == mutate::MutantStatus::Detected;
    mu.automated += am.status == mutate::MutantStatus::Detected;
    if (am.status == mutate::MutantStatus::Detected && fm.status != mutate::MutantStatus::Detected)
      mu.automated_only.push_back(fm.id + ": " + fm.description);
    else if (!equivalent && am.status != mutate::MutantStatus::Detected && fm.status != mutate::MutantStatus::Detected)
      mu.neither.push_back(fm.id + ": " + fm.description);
  }
  field.mutation = mu;
  write_output((dir / "checklist.md").string(), testgen::field_checklist_markdown(m, field, date, tool));
  write_output((dir / "checklist.html").string(), testgen::field_checklist_html(m, field, date, tool));
  write_output((dir / "checklist.csv").string(), testgen::field_checklist_csv(m, field, date, tool));
  write_output("-", "field versus automated: field detects " + std::to_string(mu.field) + ", automated " +
                        std::to_string(mu.automated) + ", automated only " + std::to_string(mu.automated_only.size()) +
                        "\n");
  return code;
}

int mutation_report(const model::Matrix& m, const testgen::TestSuite& suite, const std::string& out_dir,
                    checker::CancelToken* cancel, int jobs) {
  mutate::MutationOptions o;
  o.cancel = cancel;
  o.jobs = jobs;
  const mutate::MutationReport r = mutate::mutation_report(m, suite, o);
  const std::filesystem::path dir(out_dir);
  write_output((dir / "mutation-report.json").string(), mutate::report_json(r));
  write_output((dir / "mutation-report.md").string(), mutate::report_markdown(r));
  write_output("-", "mutation report: mutants " + std::to_string(r.mutants.size()) + ", equivalent " +
                        std::to_string(r.equivalent) + ", detected " + std::to_string(r.detected) + ", survived " +
                        std::to_string(r.survived) + ", undecided " + std::to_string(r.undecided) + "\n");
  return r.exit_code();
}

}  // namespace cemv::cli
