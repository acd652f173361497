#include "cli/sheet_layout_options.hpp"

#include <iostream>

#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "formats/diagnostics.hpp"

namespace cemv::cli {

void add_sheet_layout_options(CLI::App* cmd, SheetLayoutOptions& options) {
  cmd->add_option("--sheet-layout", options.layout_file,
                  "Grid: a cemv-sheet-layout/1 file saying what the sheet holds where (attribute columns, header "
                  "rows, marks, footnotes, trip sides, deleted rows); what it leaves out is found from the sheet");
  cmd->add_option("--save-layout", options.save_file,
                  "Grid: write the layout the sheet was read with (given and found), to give it again with "
                  "--sheet-layout for the next revision");
}

void add_orientation_option(CLI::App* cmd, std::string& orientation) {
  cmd->add_option("--orientation", orientation,
                  "Grid: auto (default: from the corner labels, id patterns and attribute headers, refused when "
                  "they are missing or disagree), causes-as-rows or effects-as-rows")
      ->check(CLI::IsMember({"auto", "causes-as-rows", "effects-as-rows"}));
}

formats::CsvOrientation orientation_of(const std::string& text) {
  if (text == "causes-as-rows") return formats::CsvOrientation::CausesAsRows;
  if (text == "effects-as-rows") return formats::CsvOrientation::EffectsAsRows;
  return formats::CsvOrientation::Auto;
}

void check_sheet_layout_output(const SheetLayoutOptions& options) {
  if (!options.save_file.empty()) check_writable(options.save_file);
}

std::optional<formats::SheetLayout> load_sheet_layout(const SheetLayoutOptions& options) {
  if (options.layout_file.empty()) return std::nullopt;
  const std::string name = input_name(options.layout_file);
  const std::string text = read_input(options.layout_file);
  try {
    return formats::parse_sheet_layout(text, name);
  } catch (const formats::LoadError& e) {
    throw e.in_file(name);
  }
}

void report_layout_used(const std::string& input, const formats::SheetLayout& used, const SheetLayoutOptions& options,
                        bool quiet) {
  if (!quiet)
    std::cerr << input << ": note: layout used (" << (options.layout_file.empty() ? "found in the sheet" : "given, completed from the sheet")
              << "; --save-layout keeps it): " << formats::sheet_layout_json(used, true) << "\n";
  if (!options.save_file.empty()) write_output(options.save_file, formats::sheet_layout_json(used));
}

}  // namespace cemv::cli
