// `cemv export-csv` and `cemv import-csv`: spreadsheet exchange (6.6, docs/csv.md).
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>

#include "cli/commands.hpp"
#include "cli/export_check.hpp"
#include "cli/import_support.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "cli/sheet_layout_options.hpp"
#include "sheets/csv.hpp"
#include "formats/matrix_json.hpp"
#include "formats/text_encoding.hpp"
#include "model/names.hpp"
#include "model/text.hpp"

namespace cemv::cli {

namespace {

// 6.1.2: the name of a matrix in the engineering tool.
constexpr std::size_t kMaxImportedName = 16;

}  // namespace

void add_csv_commands(CLI::App& app, Context& ctx) {
  struct ExportOptions {
    std::string file;
    std::string output = "-";
    std::string layout = "records";
    std::string orientation = "causes-as-rows";
  };
  auto ex = std::make_shared<ExportOptions>();
  auto* exp = app.add_subcommand(
      "export-csv",
      "Write a matrix as one cemv-csv/1 spreadsheet file holding every field (6.6), or as the C&E "
      "grid an engineer reviews");
  exp->add_option("FILE", ex->file, "Matrix file (cemv-matrix/1; '-' = standard input)")->required();
  exp->add_option("-o,--output", ex->output, "Write the CSV here instead of stdout");
  exp->add_option("--layout", ex->layout,
                  "records (default: cemv-csv/1, every field) or grid (ids, descriptions and "
                  "intersections only)")
      ->check(CLI::IsMember({"records", "grid"}));
  exp->add_option("--orientation", ex->orientation,
                  "Grid: causes-as-rows (default) or effects-as-rows")
      ->check(CLI::IsMember({"auto", "causes-as-rows", "effects-as-rows"}));
  add_quiet_flag(exp, ctx);
  exp->callback([ex, exp, &ctx] {
    if (ex->layout != "grid" && exp->count("--orientation") > 0)
      throw std::invalid_argument("export-csv: --orientation applies to --layout grid only");
    check_writable(ex->output);
    const std::string text = read_input(ex->file);
    const model::Matrix m = formats::parse_matrix(text, input_name(ex->file));
    const bool grid = ex->layout == "grid";
    const std::string csv = grid ? formats::export_csv_grid(m, orientation_of(ex->orientation)) : formats::export_csv(m);
    // An invalid matrix goes out only when the sheet reads back to it.
    refuse_unreadable_export(text, input_name(ex->file), m, grid ? "a grid" : "the record layout", [&]() -> std::optional<std::string> {
      const model::Matrix back = formats::import_csv(csv, "export.csv").matrix;
      if (!grid) {
        if (formats::signature(back) != formats::signature(m)) return std::string("another signature");
        return std::nullopt;
      }
      if (back.intersections.size() != m.intersections.size()) return std::string("other intersections");
      for (std::size_t i = 0; i < m.intersections.size(); ++i)
        if (back.intersections[i].cause != m.intersections[i].cause ||
            back.intersections[i].effect != m.intersections[i].effect ||
            back.intersections[i].type != m.intersections[i].type)
          return std::string("other intersections");
      return std::nullopt;
    });
    write_output(ex->output, csv);
    ctx.exit_code = 0;
  });

  struct ImportOptions {
    std::string input;
    std::string output = "-";
    std::string layout = "auto";
    std::string separator;
    std::string name;
    std::string orientation = "auto";
    bool strict = false;
    SheetLayoutOptions sheet;
    std::string params;
    std::string encoding = "utf-8";
  };
  auto im = std::make_shared<ImportOptions>();
  auto* imp = app.add_subcommand(
      "import-csv",
      "Read a cemv-csv/1 file or a C&E grid spreadsheet (like the LSST interlock table) and "
      "write a cemv-matrix/1 file; defects of the sheet are warnings on stderr");
  imp->add_option("INPUT", im->input, "CSV file ('-' = standard input)")->required();
  imp->add_option("-o,--output", im->output, "Write the matrix here instead of stdout");
  imp->add_option("--layout", im->layout, "auto (default), records (cemv-csv/1) or grid")
      ->check(CLI::IsMember({"auto", "records", "grid"}));
  imp->add_option("--separator", im->separator, "Grid separator: ';', ',' or 'tab' (default: detect)")
      ->check(CLI::IsMember({";", ",", "tab"}));
  imp->add_option("--name", im->name,
                  "Grid: the matrix name (at most 16 characters, 6.1.2; default: from the file name)");
  add_orientation_option(imp, im->orientation);
  imp->add_flag("--strict", im->strict, "Every import warning is an error (exit 2), for CI");
  add_sheet_layout_options(imp, im->sheet);
  imp->add_option("--params", im->params,
                  "Plant parameters the sheet cannot state (cemv-params/1, docs/params.md), applied and recorded "
                  "in the matrix with their origin")
      ->type_name("FILE");
  imp->add_option("--encoding", im->encoding,
                  "utf-8 (default: a file that is not UTF-8 is refused at its first bad byte) or windows-1252")
      ->check(CLI::IsMember({"utf-8", "utf8", "windows-1252", "cp1252"}));
  add_quiet_flag(imp, ctx);
  imp->callback([im, imp, &ctx] {
    // 6.1.2: a matrix name has at most 16 characters, as the help text says
    // (and the name rule of docs/format.md); checked before the sheet is read.
    if (imp->count("--name") > 0) {
      std::optional<std::string> problem = model::element_name_problem(im->name);
      if (!problem && im->name.size() > kMaxImportedName)
        problem = std::to_string(im->name.size()) + " characters; a matrix name has at most " +
                  std::to_string(kMaxImportedName) + " (6.1.2)";
      if (problem) throw std::invalid_argument("import-csv: --name " + model::in_quotes(im->name) + ": " + *problem);
    }
    const bool grid_only = imp->count("--separator") + imp->count("--name") + imp->count("--sheet-layout") +
                                   imp->count("--save-layout") > 0 ||
                           (imp->count("--orientation") > 0 && im->orientation != "auto");
    if (im->layout == "records" && grid_only)
      throw std::invalid_argument("import-csv: --separator, --name and --orientation apply to grids, not to "
                                  "--layout records (so do --sheet-layout and --save-layout)");
    check_writable(im->output);
    check_sheet_layout_output(im->sheet);
    formats::CsvImportOptions options;
    options.layout = im->layout == "records" ? formats::CsvLayoutKind::Records
                     : im->layout == "grid"  ? formats::CsvLayoutKind::Grid
                                             : formats::CsvLayoutKind::Auto;
    options.matrix_name = im->name;
    options.orientation = orientation_of(im->orientation);
    options.strict = im->strict;
    if (!im->separator.empty()) options.separator = im->separator == "tab" ? '\t' : im->separator[0];
    options.sheet_layout = load_sheet_layout(im->sheet);
    options.parameter_trip_sides = parameter_trip_sides(im->params);
    const std::string name = input_name(im->input);
    const std::string bytes = read_input(im->input);
    const formats::TextEncoding encoding = *formats::text_encoding_from_string(im->encoding);
    formats::CsvImportResult result;
    try {
      result = formats::import_csv(formats::decode_text(bytes, encoding, name), name, options);
    } catch (const formats::LoadError& e) {
      throw e.in_file(name);
    }
    // A grid is recorded in the matrix it makes (its source, warnings and the
    // defaults it adopted); the record layout is the matrix itself.
    const bool grid = result.layout == formats::CsvLayoutKind::Grid;
    ImportedSheet sheet{std::move(result.matrix), name, bytes, grid ? "import-csv grid" : "",
                        formats::to_string(encoding), result.summary, result.warnings};
    write_output(im->output, formats::to_canonical_json(finish_import(std::move(sheet), im->params, ctx.quiet, std::cerr)));
    if (grid) report_layout_used(name, result.layout_used, im->sheet, ctx.quiet);
    ctx.exit_code = 0;
  });
}

}  // namespace cemv::cli
