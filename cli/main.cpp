// cemv: formal verification and test generation for cause & effect matrices.
#include <exception>
#include <string>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/output.hpp"
#include "formats/diagnostics.hpp"

int main(int argc, char** argv) {
  CLI::App app{"cemv: verification and acceptance tests for safety cause & effect matrices"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("cemv ") + CEMV_VERSION);
  cemv::cli::Context ctx;
  cemv::cli::add_model_commands(app, ctx);
  cemv::cli::add_validate_commands(app, ctx);
  cemv::cli::add_report_commands(app, ctx);
  cemv::cli::add_csv_commands(app, ctx);
  cemv::cli::add_simulate_commands(app, ctx);
  cemv::cli::add_smt_commands(app, ctx);
#ifdef CEMV_WITH_CHECK  // defined when the checker and the property language are built
  cemv::cli::add_check_commands(app, ctx);
#endif
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
    for (const auto& issue : e.issues()) std::cerr << "error: " << issue.str() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return ctx.exit_code;
}
