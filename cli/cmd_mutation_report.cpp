// `cemv testgen MATRIX --out DIR --mutation-report`: the mutation adequacy of
// the generated suite (docs/mutation.md), written as DIR/mutation-report.json
// (cemv-mutation-report/1) and DIR/mutation-report.md, with one summary line.
// Built only with the test generator; `cemv testgen` calls it through the
// declaration in cli/commands.hpp.
#include <filesystem>
#include <string>

#include "cli/output.hpp"
#include "cli/commands.hpp"
#include "mutate/mutation_report.hpp"

namespace cemv::cli {

int mutation_report(const model::Matrix& m, const testgen::TestSuite& suite, const std::string& out_dir) {
  const mutate::MutationReport r = mutate::mutation_report(m, suite);
  const std::filesystem::path dir(out_dir);
  write_output((dir / "mutation-report.json").string(), mutate::report_json(r));
  write_output((dir / "mutation-report.md").string(), mutate::report_markdown(r));
  write_output("-", "mutation report: mutants " + std::to_string(r.mutants.size()) + ", equivalent " +
                        std::to_string(r.equivalent) + ", detected " + std::to_string(r.detected) + ", survived " +
                        std::to_string(r.survived) + ", undecided " + std::to_string(r.undecided) + "\n");
  return r.exit_code();
}

}  // namespace cemv::cli
