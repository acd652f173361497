// `cemv report`: the configuration report of 11.4 (docs/reports.md).
#include <fstream>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "formats/matrix_json.hpp"
#include "reports/config_report.hpp"

namespace cemv::cli {

void add_report_commands(CLI::App& app, Context& ctx) {
  struct Options {
    std::string file;
    std::string format = "md";
    std::string output;
  };
  auto opt = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "report", "Configuration report of a matrix (11.4): properties, statistics, every cause, "
                "effect and intersection, SIF groups, validation summary, signature");
  cmd->add_option("FILE", opt->file, "Matrix file (cemv-matrix/1)")->required();
  cmd->add_option("--format", opt->format, "md (default), html (one self-contained file) or json")
      ->check(CLI::IsMember({"md", "markdown", "html", "json"}));
  cmd->add_option("-o,--output", opt->output, "Write the report here instead of stdout");
  cmd->callback([opt, &ctx] {
    const model::Matrix m = formats::load_matrix(opt->file);
    const std::string text =
        reports::configuration_report(m, *reports::report_format_from_string(opt->format));
    if (opt->output.empty()) {
      std::cout << text;
      std::cout.flush();
    } else {
      std::ofstream out(opt->output, std::ios::binary);
      out << text;
      out.close();
      if (!out) {
        std::cerr << "error: " << opt->output << ": cannot write the report\n";
        ctx.exit_code = 2;
        return;
      }
    }
    ctx.exit_code = 0;
  });
}

}  // namespace cemv::cli
