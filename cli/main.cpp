// cemv: formal verification and test generation for cause & effect matrices.
#include <algorithm>
#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "checker/limits.hpp"
#include "cli/commands.hpp"
#include "cli/errors.hpp"
#include "cli/output.hpp"
#include "cli/version.hpp"
#include "formats/diagnostics.hpp"
#include "model/text.hpp"

namespace {

// `cemv WORD ...` where WORD is no command (and no option): CLI11 would answer
// "A subcommand is required"; name the word and the nearest command instead.
std::optional<std::string> unknown_command(const CLI::App& app, int argc, char** argv) {
  if (argc < 2) return std::nullopt;
  const std::string word = argv[1];
  if (word[0] == '-') {  // `cemv --verison`: an option of cemv itself
    const std::vector<std::string> options{"--help", "-h", "--version"};
    const std::string name = word.substr(0, word.find('='));
    if (std::find(options.begin(), options.end(), name) != options.end()) return std::nullopt;
    std::string message = "unknown option " + cemv::model::in_quotes(name);
    std::string hint = cemv::model::did_you_mean(name, options);
    if (hint.size() > 3) message += "; " + hint.substr(2, hint.size() - 3);
    return message + " (cemv --help lists the commands and options)";
  }
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

// `cemv check m.json --timout 5`: CLI11 says "The following argument was not
// expected: --timout"; name the option and the nearest one of that command
// instead, as for a command (nullopt when no extra argument is an option).
std::optional<std::string> unknown_option(const CLI::App& app) {
  const CLI::App* cmd = &app;
  std::vector<CLI::App*> chosen = app.get_subcommands();
  if (!chosen.empty()) cmd = chosen.front();
  std::vector<std::string> names;
  for (const CLI::Option* o : cmd->get_options()) {
    for (const auto& l : o->get_lnames()) names.push_back("--" + l);
    for (const auto& s : o->get_snames()) names.push_back("-" + s);
  }
  const std::string who = cmd == &app ? "cemv" : "cemv " + cmd->get_name();
  for (const std::string& arg : cmd->remaining()) {
    if (arg.size() < 2 || arg[0] != '-') continue;
    const std::string word = arg.substr(0, arg.find('='));  // --timout=5
    std::string message = (cmd == &app ? "" : cmd->get_name() + ": ") + "unknown option " + cemv::model::in_quotes(word);
    std::string hint = cemv::model::did_you_mean(word, names);  // " (did you mean '--timeout'?)"
    if (hint.size() > 3) message += "; " + hint.substr(2, hint.size() - 3);
    return message + " (" + who + " --help lists the options)";
  }
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  // Named, so that help and the man page say `cemv`, not the path it was started by.
  CLI::App app{"cemv: verification and acceptance tests for safety cause & effect matrices", "cemv"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("cemv ") + cemv::cli::build_version());
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
#ifdef CEMV_WITH_DEFEATS
  cemv::cli::add_defeats_commands(app, ctx);
#endif
#ifdef CEMV_WITH_PLC  // the PLC program's commands (docs/plc.md)
  cemv::cli::add_plc_commands(app, ctx);
  cemv::cli::add_export_st_commands(app, ctx);
#endif
#ifdef CEMV_WITH_WORKBOOK  // the ODS/XLSX commands (their own guard: the CLI tests' doubles do not build them)
  cemv::cli::add_workbook_commands(app, ctx);
#endif
#ifdef CEMV_WITH_TESTGEN
  cemv::cli::add_testgen_commands(app, ctx);
  cemv::cli::add_replay_commands(app, ctx);
  cemv::cli::add_record_commands(app, ctx);
#endif
  if (auto message = unknown_command(app, argc, argv)) {
    std::cerr << "error: " << *message << "\n";
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ExtrasError& e) {
    if (auto message = unknown_option(app)) {
      std::cerr << "error: " << *message << "\n";
      return 2;
    }
    app.exit(e);
    return 2;
  } catch (const CLI::ParseError& e) {
    int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  } catch (const cemv::cli::ClosedPipe&) {
    // The reader went away (`cemv ... | head`): end quietly, with the status
    // of a process that SIGPIPE killed.
    return 128 + 13;
  } catch (const cemv::checker::Interrupted&) {
    // Every command turns the end of its time limit into unknown results in
    // a complete report; this is the last guard against one that does not:
    // no report, but no crash either.
    std::cerr << "error: the time limit ended the run before its report could be written\n";
    return 3;
  } catch (const cemv::formats::LoadError& e) {
    cemv::cli::print_load_error(e, std::cerr);
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return ctx.exit_code;
}
