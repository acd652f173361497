// The subcommands of `cemv`, one registration function per command group, each
// in its own file. A command's callback stores its exit status in Context:
// 0 success, 1 a negative verdict (validation errors, failed expectation,
// counterexample), 2 bad input (unreadable or invalid file, bad arguments);
// `check` adds 3 (undecided) and 4 (internal error), docs/checker.md.
#pragma once

#include <CLI/CLI.hpp>

namespace cemv::cli {

struct Context {
  int exit_code = 0;
};

void add_model_commands(CLI::App& app, Context& ctx);     // fmt, signature
void add_validate_commands(CLI::App& app, Context& ctx);  // validate, graph
void add_report_commands(CLI::App& app, Context& ctx);    // report
void add_csv_commands(CLI::App& app, Context& ctx);       // export-csv, import-csv
void add_simulate_commands(CLI::App& app, Context& ctx);  // simulate
void add_smt_commands(CLI::App& app, Context& ctx);       // export-smt
void add_check_commands(CLI::App& app, Context& ctx);     // check
void add_evidence_commands(CLI::App& app, Context& ctx);  // evidence

}  // namespace cemv::cli
