// `cemv import-workbook` and `cemv export-workbook`: the Safety Matrix's six
// tables as an ODS or XLSX workbook (6.6, docs/workbook.md). After an import
// into an existing matrix (`--into OLD`), what changed is listed by the
// structural comparison of cemv diff (6.6.3: the import log's "Matrix
// comparison", source the spreadsheet, reference the matrix before).
#include <iostream>
#include <memory>
#include <stdexcept>

#include "cli/commands.hpp"
#include "cli/export_check.hpp"
#include "cli/import_support.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "cli/sheet_layout_options.hpp"
#include "diff/structural.hpp"
#include "formats/matrix_json.hpp"
#include "sheets/workbook.hpp"

namespace cemv::cli {

namespace {

std::string change_lines(const diff::StructuralDiff& d) {
  std::string out;
  std::size_t critical = 0;
  for (const auto& c : d.changes) {
    critical += c.critical() ? 1 : 0;
    out += std::string("  ") + (c.critical() ? "critical     " : "non-critical ") + diff::to_string(c.kind) + " " + c.label();
    if (c.kind == diff::ChangeKind::Moved)
      out += " (number " + std::to_string(c.old_id) + " -> " + std::to_string(c.new_id) + ")";
    out += "\n";
    for (const auto& f : c.fields)
      out += "      " + f.field + ": " + (f.old_value.empty() ? "(none)" : f.old_value) + " -> " +
             (f.new_value.empty() ? "(none)" : f.new_value) + (f.critical ? "" : "  [non-critical]") + "\n";
  }
  return std::to_string(d.changes.size()) + " change" + (d.changes.size() == 1 ? "" : "s") + ", " +
         std::to_string(critical) + " critical\n" + out;
}

}  // namespace

void add_workbook_commands(CLI::App& app, Context& ctx) {
  struct ImportOptions {
    std::string input;
    std::string output = "-";
    std::string into;
    std::string sheet;
    std::string orientation = "auto";
    SheetLayoutOptions layout;
    std::string params;
  };
  auto im = std::make_shared<ImportOptions>();
  auto* imp = app.add_subcommand(
      "import-workbook",
      "Read an ODS or XLSX workbook (the six tables of 6.6.2, or a C&E grid on one of its sheets) and write a "
      "cemv-matrix/1 file; warnings on stderr");
  imp->add_option("FILE", im->input, "Workbook (.ods or .xlsx, told by its content; '-' = standard input)")->required();
  imp->add_option("-o,--output", im->output, "Write the matrix here instead of stdout");
  imp->add_option("--into", im->into,
                  "The matrix before the import (6.6.3): list what the workbook changes in it (the structural "
                  "comparison of cemv diff)");
  imp->add_option("--sheet", im->sheet,
                  "Grid: the sheet that holds the matrix, by name or number (default: the one sheet with a C&E grid)");
  add_orientation_option(imp, im->orientation);
  add_sheet_layout_options(imp, im->layout);
  imp->add_option("--params", im->params,
                  "Plant parameters the sheet cannot state (cemv-params/1, docs/params.md), applied and recorded "
                  "in the matrix with their origin")
      ->type_name("FILE");
  add_quiet_flag(imp, ctx);
  imp->callback([im, &ctx] {
    check_writable(im->output);
    check_sheet_layout_output(im->layout);
    std::optional<model::Matrix> old;
    if (!im->into.empty()) old = load_matrix_input(im->into);
    const std::string name = input_name(im->input);
    const std::string bytes = read_input(im->input);
    formats::WorkbookImportResult result;
    formats::WorkbookImportOptions options;
    options.sheet = im->sheet;
    options.orientation = orientation_of(im->orientation);
    options.sheet_layout = load_sheet_layout(im->layout);
    options.parameter_trip_sides = parameter_trip_sides(im->params);
    try {
      result = formats::import_workbook(bytes, name, options);
    } catch (const formats::LoadError& e) {
      throw e.in_file(name);
    }
    // A grid is recorded in the matrix it makes; the six tables are the matrix.
    ImportedSheet sheet{std::move(result.matrix), name, bytes, result.grid ? "import-workbook grid" : "", "UTF-8",
                        result.summary, result.warnings};
    result.matrix = finish_import(std::move(sheet), im->params, ctx.quiet, std::cerr);
    write_output(im->output, formats::to_canonical_json(result.matrix));
    if (result.layout_used) report_layout_used(name, *result.layout_used, im->layout, ctx.quiet);
    if (old && !ctx.quiet) {
      const diff::StructuralDiff d = diff::compare_structure(*old, result.matrix);
      std::cerr << name << ": note: matrix comparison (6.6.3), source " << name << ", reference " << input_name(im->into)
                << ": " << (d.empty() ? "no change\n" : change_lines(d));
    }
    ctx.exit_code = 0;
  });

  struct ExportOptions {
    std::string file;
    std::string output;
    std::string format;
  };
  auto ex = std::make_shared<ExportOptions>();
  auto* exp = app.add_subcommand(
      "export-workbook",
      "Write a matrix as the six tables of 6.6.2 (matrix properties, alarm profiles, causes configuration, "
      "intersections overview, effects configuration, legend) in an ODS or XLSX workbook");
  exp->add_option("MATRIX", ex->file, "Matrix file (cemv-matrix/1; '-' = standard input)")->required();
  exp->add_option("-o,--output", ex->output, "The workbook: FILE.ods or FILE.xlsx ('-' = stdout, with --format)")
      ->required();
  exp->add_option("--format", ex->format, "ods or xlsx (default: from the extension of -o)")
      ->check(CLI::IsMember({"ods", "xlsx"}));
  add_quiet_flag(exp, ctx);
  exp->callback([ex, &ctx] {
    std::optional<formats::WorkbookFormat> format = formats::workbook_format_of(ex->output);
    if (!ex->format.empty()) {
      auto given = ex->format == "ods" ? formats::WorkbookFormat::Ods : formats::WorkbookFormat::Xlsx;
      if (format && *format != given)
        throw std::invalid_argument("export-workbook: --format " + ex->format + " contradicts the extension of " + ex->output);
      format = given;
    }
    if (!format)
      throw std::invalid_argument("export-workbook: -o " + ex->output +
                                  ": the workbook's name must end in .ods or .xlsx (or give --format)");
    check_writable(ex->output);
    const std::string text = read_input(ex->file);
    const model::Matrix m = formats::parse_matrix(text, input_name(ex->file));
    const std::string bytes = formats::export_workbook(m, *format);
    // An invalid matrix goes out only when the workbook reads back to it.
    refuse_unreadable_export(text, input_name(ex->file), m, "a workbook", [&]() -> std::optional<std::string> {
      if (formats::signature(formats::import_workbook(bytes, "export").matrix) != formats::signature(m))
        return std::string("another signature");
      return std::nullopt;
    });
    write_output(ex->output, bytes);
    ctx.exit_code = 0;
  });
}

}  // namespace cemv::cli
