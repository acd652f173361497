// `cemv apply-params MATRIX PARAMS [-o OUT]`: the plant parameters a
// published sheet cannot state (cemv-params/1, docs/params.md), set in a
// matrix with a record of every value and its origin, which the signature
// covers (docs/format.md "Provenance").
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/import_support.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "formats/matrix_json.hpp"

namespace cemv::cli {

void add_params_commands(CLI::App& app, Context& ctx) {
  struct Options {
    std::string matrix;
    std::string params;
    std::string output = "-";
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "apply-params",
      "Set the plant parameters of a cemv-params/1 file (override times, soft-bypass and simulation policy, "
      "secure write, cycle, SIF groups, tag descriptions, footnotes) in a matrix, each recorded with its origin");
  cmd->add_option("MATRIX", o->matrix, "Matrix file (cemv-matrix/1; '-' = standard input)")->required();
  cmd->add_option("PARAMS", o->params, "Parameters file (cemv-params/1, docs/params.md)")->required();
  cmd->add_option("-o,--output", o->output, "Write the matrix here instead of stdout (may be MATRIX itself)");
  add_quiet_flag(cmd, ctx);
  cmd->footer("Exit status: 0 written; 2 a file that cannot be read or applied (FILE:LINE:COL: error: ...).\n");
  cmd->callback([o, &ctx] {
    check_writable(o->output);
    const model::Matrix m = load_matrix_input(o->matrix);
    write_output(o->output, formats::to_canonical_json(apply_params_file(m, o->params, ctx.quiet, std::cerr)));
    ctx.exit_code = 0;
  });
}

}  // namespace cemv::cli
