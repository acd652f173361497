// The subcommands of `cemv`, one registration function per command group, each
// in its own file. A command's callback stores its exit status in Context:
// 0 success, 1 a negative verdict (validation errors, failed expectation,
// counterexample), 2 bad input (unreadable or invalid file, bad arguments);
// `check` adds 3 (undecided) and 4 (internal error), docs/checker.md.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace cemv::model { struct Matrix; }
namespace cemv::checker { class CancelToken; }
namespace cemv::testgen { struct TestSuite; struct FieldSuite; }

namespace cemv::cli {

struct Context {
  int exit_code = 0;
  bool quiet = false;  // --quiet: print nothing but errors (README, "Commands")
};

// `-q,--quiet` on a command: human-readable text on standard output (tables,
// summaries, notes and warnings) is left out; errors, the files a command is
// asked to write and machine-readable output still are written.
inline void add_quiet_flag(CLI::App* cmd, Context& ctx) {
  cmd->add_flag("-q,--quiet", ctx.quiet, "Print nothing but errors (and the output asked for)");
}

void add_model_commands(CLI::App& app, Context& ctx);     // fmt, signature
void add_validate_commands(CLI::App& app, Context& ctx);  // validate, graph
void add_report_commands(CLI::App& app, Context& ctx);    // report
void add_csv_commands(CLI::App& app, Context& ctx);       // export-csv, import-csv
void add_params_commands(CLI::App& app, Context& ctx);    // apply-params
void add_simulate_commands(CLI::App& app, Context& ctx);  // simulate
void add_smt_commands(CLI::App& app, Context& ctx);       // export-smt
void add_check_commands(CLI::App& app, Context& ctx);     // check
void add_testgen_commands(CLI::App& app, Context& ctx);   // testgen
void add_replay_commands(CLI::App& app, Context& ctx);    // replay
void add_record_commands(CLI::App& app, Context& ctx);    // record

// `cemv testgen --mutation-report`: after the suite is written to `out_dir`,
// the mutation adequacy report (docs/testgen.md); returns an exit status.
// `cancel`: the run's token (--total-timeout; nullptr: none); `jobs`:
// mutants decided at once (the report does not depend on it).
int mutation_report(const model::Matrix& m, const testgen::TestSuite& suite, const std::string& out_dir,
                    checker::CancelToken* cancel = nullptr, int jobs = 1);
// The same for the automated suite and the field suite (DIR/field/), and the
// comparison of the two in the field checklists; returns an exit status.
int field_mutation_report(const model::Matrix& m, const testgen::TestSuite* automated, testgen::FieldSuite& field,
                          const std::string& out_dir, const std::string& date, const std::string& tool,
                          checker::CancelToken* cancel = nullptr);
void add_mutate_commands(CLI::App& app, Context& ctx);    // mutate
void add_diff_commands(CLI::App& app, Context& ctx);      // diff
void add_response_commands(CLI::App& app, Context& ctx);  // response
void add_defeats_commands(CLI::App& app, Context& ctx);   // defeats
void add_evidence_commands(CLI::App& app, Context& ctx);  // evidence
void add_workbook_commands(CLI::App& app, Context& ctx);  // import-workbook, export-workbook
void add_plc_commands(CLI::App& app, Context& ctx);       // plc-check
void add_export_st_commands(CLI::App& app, Context& ctx); // export-st

}  // namespace cemv::cli
