// `cemv export-csv` and `cemv import-csv`: spreadsheet exchange (6.6, docs/csv.md).
#include <fstream>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "formats/csv.hpp"
#include "formats/matrix_json.hpp"

namespace cemv::cli {

namespace {

// Writes text to a file, or stdout when path is empty; false when it cannot.
bool write_output(const std::string& path, const std::string& text, const char* what) {
  if (path.empty()) {
    std::cout << text;
    std::cout.flush();
    return true;
  }
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) std::cerr << "error: " << path << ": cannot write the " << what << "\n";
  return static_cast<bool>(out);
}

formats::CsvOrientation orientation_of(const std::string& text) {
  if (text == "causes-as-rows") return formats::CsvOrientation::CausesAsRows;
  if (text == "effects-as-rows") return formats::CsvOrientation::EffectsAsRows;
  return formats::CsvOrientation::Auto;
}

}  // namespace

void add_csv_commands(CLI::App& app, Context& ctx) {
  struct ExportOptions {
    std::string file;
    std::string output;
    std::string layout = "records";
    std::string orientation = "causes-as-rows";
  };
  auto ex = std::make_shared<ExportOptions>();
  auto* exp = app.add_subcommand(
      "export-csv",
      "Write a matrix as one cemv-csv/1 spreadsheet file holding every field (6.6), or as the C&E "
      "grid an engineer reviews");
  exp->add_option("FILE", ex->file, "Matrix file (cemv-matrix/1)")->required();
  exp->add_option("-o,--output", ex->output, "Write the CSV here instead of stdout");
  exp->add_option("--layout", ex->layout,
                  "records (default: cemv-csv/1, every field) or grid (ids, descriptions and "
                  "intersections only)")
      ->check(CLI::IsMember({"records", "grid"}));
  exp->add_option("--orientation", ex->orientation,
                  "Grid: causes-as-rows (default) or effects-as-rows")
      ->check(CLI::IsMember({"auto", "causes-as-rows", "effects-as-rows"}));
  exp->callback([ex, &ctx] {
    const model::Matrix m = formats::load_matrix(ex->file);
    const std::string text = ex->layout == "grid"
                                 ? formats::export_csv_grid(m, orientation_of(ex->orientation))
                                 : formats::export_csv(m);
    ctx.exit_code = write_output(ex->output, text, "CSV file") ? 0 : 2;
  });

  struct ImportOptions {
    std::string input;
    std::string output;
    std::string layout = "auto";
    std::string separator;
    std::string name;
    std::string orientation = "auto";
    bool strict = false;
  };
  auto im = std::make_shared<ImportOptions>();
  auto* imp = app.add_subcommand(
      "import-csv",
      "Read a cemv-csv/1 file or a C&E grid spreadsheet (like the LSST interlock table) and "
      "write a cemv-matrix/1 file; defects of the sheet are warnings on stderr");
  imp->add_option("INPUT", im->input, "CSV file")->required();
  imp->add_option("-o,--output", im->output, "Write the matrix here instead of stdout");
  imp->add_option("--layout", im->layout, "auto (default), records (cemv-csv/1) or grid")
      ->check(CLI::IsMember({"auto", "records", "grid"}));
  imp->add_option("--separator", im->separator, "Grid separator: ';', ',' or 'tab' (default: detect)")
      ->check(CLI::IsMember({";", ",", "tab"}));
  imp->add_option("--name", im->name,
                  "Grid: the matrix name (at most 16 characters, 6.1.2; default: from the file name)");
  imp->add_option("--orientation", im->orientation,
                  "Grid: auto (default: from the corner labels and id patterns, refused when "
                  "they are missing or disagree), causes-as-rows or effects-as-rows")
      ->check(CLI::IsMember({"auto", "causes-as-rows", "effects-as-rows"}));
  imp->add_flag("--strict", im->strict, "Every import warning is an error (exit 2), for CI");
  imp->callback([im, &ctx] {
    formats::CsvImportOptions options;
    options.layout = im->layout == "records" ? formats::CsvLayoutKind::Records
                     : im->layout == "grid"  ? formats::CsvLayoutKind::Grid
                                             : formats::CsvLayoutKind::Auto;
    options.matrix_name = im->name;
    options.orientation = orientation_of(im->orientation);
    options.strict = im->strict;
    if (!im->separator.empty()) options.separator = im->separator == "tab" ? '\t' : im->separator[0];
    const std::string text = formats::read_text_file(im->input);
    const formats::CsvImportResult result = formats::import_csv(text, im->input, options);
    for (const auto& w : result.warnings) std::cerr << "warning: " << w.str() << "\n";
    if (!result.summary.empty()) std::cerr << "note: " << im->input << ": " << result.summary << "\n";
    ctx.exit_code =
        write_output(im->output, formats::to_canonical_json(result.matrix), "matrix") ? 0 : 2;
  });
}

}  // namespace cemv::cli
