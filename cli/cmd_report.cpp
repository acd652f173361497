// `cemv report`: the configuration report of 11.4 (docs/reports.md). It is
// how an engineer sees a matrix's errors, so unlike the commands that compute
// from a matrix it renders an invalid one too: with a banner and the
// validation section first, and exit status 1.
#include <memory>

#include "cli/commands.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "model/validate.hpp"
#include "reports/config_report.hpp"

namespace cemv::cli {

void add_report_commands(CLI::App& app, Context& ctx) {
  struct Options {
    std::string file;
    std::string format = "md";
    std::string output = "-";
  };
  auto opt = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "report", "Configuration report of a matrix (11.4): properties, statistics, every cause, "
                "effect and intersection, SIF groups, validation summary, signature; exit 1 when "
                "the matrix has validation errors (the report shows them first)");
  cmd->add_option("FILE", opt->file, "Matrix file (cemv-matrix/1; '-' = standard input)")->required();
  cmd->add_option("--format", opt->format, "md (default), html (one self-contained file) or json")
      ->check(CLI::IsMember({"md", "markdown", "html", "json"}));
  cmd->add_option("-o,--output", opt->output, "Write the report here instead of stdout");
  add_quiet_flag(cmd, ctx);
  cmd->callback([opt, &ctx] {
    check_writable(opt->output);
    const model::Matrix m = load_matrix_input(opt->file);
    write_output(opt->output,
                 reports::configuration_report(m, *reports::report_format_from_string(opt->format)));
    ctx.exit_code = model::has_errors(model::validate(m)) ? 1 : 0;
  });
}

}  // namespace cemv::cli
