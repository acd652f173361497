// cemv: formal verification and test generation for cause & effect matrices.
#include <cctype>
#include <exception>
#include <string>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/output.hpp"
#include "formats/diagnostics.hpp"

namespace {

// "FILE:LINE:COL": ends in two colon-separated runs of digits after a name.
bool has_file_line_column(const std::string& where) {
  auto digits_before = [&](std::size_t end) {
    std::size_t i = end;
    while (i > 0 && std::isdigit(static_cast<unsigned char>(where[i - 1]))) --i;
    return i < end && i > 0 && where[i - 1] == ':' ? i - 1 : std::string::npos;
  };
  std::size_t col = digits_before(where.size());
  if (col == std::string::npos) return false;
  std::size_t line = digits_before(col);
  return line != std::string::npos && line > 0;
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
  cemv::cli::add_simulate_commands(app, ctx);
  cemv::cli::add_smt_commands(app, ctx);
#ifdef CEMV_WITH_CHECK  // defined when the checker and the property language are built
  cemv::cli::add_check_commands(app, ctx);
  cemv::cli::add_evidence_commands(app, ctx);
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
    for (const auto& issue : e.issues()) {
      // A place of the form FILE:LINE:COL leads its line, as compilers write
      // it (editors and CI log views jump there); other places keep the
      // "error: PLACE: message" form of the matrix and scenario loaders.
      if (has_file_line_column(issue.where))
        std::cerr << issue.where << ": error: " << issue.what << "\n";
      else
        std::cerr << "error: " << issue.str() << "\n";
    }
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return ctx.exit_code;
}
