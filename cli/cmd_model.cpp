// `cemv fmt` and `cemv signature`: the canonical form of a matrix and its
// SHA-256 signature (docs/format.md). An invalid file throws formats::LoadError,
// which main() prints as `FILE:LINE:COL: error: ...` lines with exit status 2.
// `fmt --check FILE...` is the format gate of CI (like `gofmt -l`): it names
// every file that is not in canonical form and changes none.
#include <algorithm>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/errors.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "formats/matrix_json.hpp"

namespace cemv::cli {

namespace {

struct FmtOptions {
  std::vector<std::string> files;
  std::string out = "-";
  bool check = false;
};

// fmt --check: 0 when every file is canonical, 1 when one is not, 2 when one
// cannot be read (the worst file decides, as for validate).
int check_canonical(const std::vector<std::string>& files, bool quiet) {
  int worst = 0;
  std::string report;
  std::size_t not_canonical = 0;
  for (const auto& path : files) {
    try {
      const std::string text = read_input(path);
      const std::string canonical = formats::to_canonical_json(formats::parse_matrix(text, input_name(path)));
      if (text != canonical) {
        report += input_name(path) + ": not in canonical form (cemv fmt FILE -o FILE rewrites it)\n";
        ++not_canonical;
        worst = std::max(worst, 1);
      }
    } catch (const formats::LoadError& e) {
      print_load_error(e.in_file(input_name(path)), std::cerr);
      worst = 2;
    }
  }
  if (!quiet && files.size() > 1)
    report += std::to_string(files.size()) + " files: " + std::to_string(not_canonical) + " not in canonical form\n";
  write_output("-", report);
  return worst;
}

}  // namespace

void add_model_commands(CLI::App& app, Context& ctx) {
  auto fmt = std::make_shared<FmtOptions>();
  CLI::App* fmt_cmd = app.add_subcommand(
      "fmt", "Check a cemv-matrix/1 file and write its canonical form (sorted keys, every default spelt out); "
             "with --check, name the files that are not canonical (exit 1) and change none");
  fmt_cmd->add_option("FILE", fmt->files, "Matrix file(s) (cemv-matrix/1 JSON; '-' = standard input)")
      ->required();
  fmt_cmd->add_option("-o,--output", fmt->out,
                      "Write here instead of standard output (may be FILE itself; replaced atomically)");
  fmt_cmd->add_flag("--check", fmt->check,
                    "Change nothing: list each FILE not in canonical form; exit 0 all canonical, 1 some not, "
                    "2 unreadable");
  add_quiet_flag(fmt_cmd, ctx);
  fmt_cmd->callback([fmt, &ctx] {
    if (fmt->check) {
      if (fmt->out != "-") throw std::invalid_argument("fmt: --check changes no file; it does not take -o");
      ctx.exit_code = check_canonical(fmt->files, ctx.quiet);
      return;
    }
    if (fmt->files.size() != 1)
      throw std::invalid_argument("fmt: give one FILE to format, or --check FILE... to check several");
    check_writable(fmt->out);
    model::Matrix m = load_matrix_input(fmt->files.front());
    write_output(fmt->out, formats::to_canonical_json(m));
    ctx.exit_code = 0;
  });

  auto file = std::make_shared<std::string>();
  CLI::App* sig_cmd = app.add_subcommand(
      "signature", "Print the matrix signature: SHA-256 of the canonical form, lowercase hex");
  sig_cmd->add_option("FILE", *file, "Matrix file (cemv-matrix/1 JSON; '-' = standard input)")->required();
  add_quiet_flag(sig_cmd, ctx);
  sig_cmd->callback([file, &ctx] {
    write_output("-", formats::signature(load_matrix_input(*file)) + "\n");
    ctx.exit_code = 0;
  });
}

}  // namespace cemv::cli
