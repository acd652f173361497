// `cemv fmt` and `cemv signature`: the canonical form of a matrix and its
// SHA-256 signature (docs/format.md). An invalid file throws formats::LoadError,
// which main() prints as `error: <where>: <what>` lines with exit status 2.
#include <iostream>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "formats/matrix_json.hpp"

namespace cemv::cli {

namespace {

struct FmtOptions {
  std::string file;
  std::string out;
};

}  // namespace

void add_model_commands(CLI::App& app, Context& ctx) {
  auto fmt = std::make_shared<FmtOptions>();
  CLI::App* fmt_cmd = app.add_subcommand(
      "fmt", "Check a cemv-matrix/1 file and write its canonical form (sorted keys, every default spelt out)");
  fmt_cmd->add_option("FILE", fmt->file, "Matrix file (cemv-matrix/1 JSON)")->required();
  fmt_cmd->add_option("-o,--output", fmt->out, "Write here instead of standard output (may be FILE itself)");
  fmt_cmd->callback([fmt, &ctx] {
    model::Matrix m = formats::load_matrix(fmt->file);
    if (fmt->out.empty()) {
      std::cout << formats::to_canonical_json(m) << std::flush;
    } else {
      formats::save_matrix(m, fmt->out);
    }
    ctx.exit_code = 0;
  });

  auto file = std::make_shared<std::string>();
  CLI::App* sig_cmd = app.add_subcommand(
      "signature", "Print the matrix signature: SHA-256 of the canonical form, lowercase hex");
  sig_cmd->add_option("FILE", *file, "Matrix file (cemv-matrix/1 JSON)")->required();
  sig_cmd->callback([file, &ctx] {
    std::cout << formats::signature(formats::load_matrix(*file)) << "\n";
    ctx.exit_code = 0;
  });
}

}  // namespace cemv::cli
