// cemv: formal verification and test generation for cause & effect matrices.
#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/errors.hpp"
#include "cli/output.hpp"
#include "formats/diagnostics.hpp"
#include "model/text.hpp"

namespace {

// `cemv WORD ...` where WORD is no command (and no option): CLI11 would answer
// "A subcommand is required"; name the word and the nearest command instead.
std::optional<std::string> unknown_command(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return std::nullopt;
  const std::string word = argv[1];
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (sub->check_name(word)) return std::nullopt;
    names.push_back(sub->get_name());
  }
  std::string message = "unknown command " + cemv::model::in_quotes(word);
  std::string hint = cemv::model::did_you_mean(word, names);  // " (did you mean 'graph'?)"
  if (hint.size() > 3) message += "; " + hint.substr(2, hint.size() - 3);
  return message + " (cemv --help lists the commands)";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"cemv: verification and acceptance tests for safety cause & effect matrices"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("cemv ") + CEMV_VERSION);
  cemv::cli::Context ctx;
  cemv::cli::add_model_commands(app, ctx);
  cemv::cli::add_validate_commands(app, ctx);
  cemv::cli::add_report_commands(app, ctx);
  cemv::cli::add_csv_commands(app, ctx);
  cemv::cli::add_params_commands(app, ctx);
  cemv::cli::add_simulate_commands(app, ctx);
  cemv::cli::add_smt_commands(app, ctx);
#ifdef CEMV_WITH_CHECK  // defined when the checker and the property language are built
  cemv::cli::add_check_commands(app, ctx);
#endif
#ifdef CEMV_WITH_VERIFICATION  // the commands built on the checker (not in the CLI tests' checker double)
  cemv::cli::add_mutate_commands(app, ctx);
  cemv::cli::add_diff_commands(app, ctx);
  cemv::cli::add_response_commands(app, ctx);
  cemv::cli::add_evidence_commands(app, ctx);
#endif
#ifdef CEMV_WITH_WORKBOOK  // the ODS/XLSX commands (their own guard: the CLI tests' doubles do not build them)
  cemv::cli::add_workbook_commands(app, ctx);
#endif
#ifdef CEMV_WITH_TESTGEN
  cemv::cli::add_testgen_commands(app, ctx);
  cemv::cli::add_replay_commands(app, ctx);
#endif
  if (auto message = unknown_command(app, argc, argv)) {
    std::cerr << "error: " << *message << "\n";
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  } catch (const cemv::cli::ClosedPipe&) {
    // The reader went away (`cemv ... | head`): end quietly, with the status
    // of a process that SIGPIPE killed.
    return 128 + 13;
  } catch (const cemv::formats::LoadError& e) {
    cemv::cli::print_load_error(e, std::cerr);
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return ctx.exit_code;
}
