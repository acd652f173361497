// The options of import-csv and import-workbook that describe a vendor's C&E
// sheet (docs/csv.md "The layout description"): `--orientation`,
// `--sheet-layout FILE` gives a
// cemv-sheet-layout/1 file, `--save-layout FILE` writes the layout the sheet
// was read with, and the summary prints it, so that the next revision of the
// same sheet is read the same way.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "sheets/sheet_layout.hpp"

namespace cemv::cli {

struct SheetLayoutOptions {
  std::string layout_file;
  std::string save_file;
};

void add_sheet_layout_options(CLI::App* cmd, SheetLayoutOptions& options);

// `--orientation auto|causes-as-rows|effects-as-rows` of a grid import (the
// layout's `orientation` the same, or auto), and its value.
void add_orientation_option(CLI::App* cmd, std::string& orientation);
formats::CsvOrientation orientation_of(const std::string& text);

// Checks before the work that --save-layout can be written.
void check_sheet_layout_output(const SheetLayoutOptions& options);

// The layout of --sheet-layout (LoadError placed in its file), or none.
std::optional<formats::SheetLayout> load_sheet_layout(const SheetLayoutOptions& options);

// After an import: the layout used as one note on standard error (unless
// quiet), and written to --save-layout when given.
void report_layout_used(const std::string& input, const formats::SheetLayout& used, const SheetLayoutOptions& options,
                        bool quiet);

}  // namespace cemv::cli
