// Fuzz target: the spreadsheet importers (sheets/csv.hpp, docs/csv.md), the
// bytes `cemv import-csv` reads: the record layout and the C&E grid, with the
// layout detected and with the grid forced in either orientation (strict in
// one, so the warnings-as-errors path runs too), and with a vendor sheet's
// layout description (marks, trip sides, footnotes). Expected answers: a matrix,
// or a LoadError. Invariants of an accepted matrix: it passes the matrix
// loader (the importer promises it was checked by parse_matrix), and the
// record layout is lossless (export, import: the same canonical form).
#include <cstddef>
#include <cstdint>

#include "sheets/csv.hpp"
#include "formats/matrix_json.hpp"
#include "fuzz/fuzz_support.hpp"

using namespace cemv;

namespace {

void import_with(std::string_view text, const formats::CsvImportOptions& options) {
  formats::CsvImportResult result;
  try {
    result = formats::import_csv(text, "fuzz.csv", options);
  } catch (const formats::LoadError&) {
    return;
  }
  const std::string canonical = formats::to_canonical_json(result.matrix);
  try {
    formats::parse_matrix(canonical, "imported.json");
  } catch (const formats::LoadError& e) {
    fuzz::finding("an imported matrix does not pass the matrix loader", e.issues().front().str());
  }
  const std::string records = formats::export_csv(result.matrix);
  try {
    formats::CsvImportOptions as_records;
    as_records.layout = formats::CsvLayoutKind::Records;
    if (formats::to_canonical_json(formats::import_csv(records, "exported.csv", as_records).matrix) != canonical)
      fuzz::finding("the record layout does not round-trip", records);
  } catch (const formats::LoadError& e) {
    fuzz::finding("the record layout export does not import", e.issues().front().str());
  }
  (void)formats::export_csv_grid(result.matrix, formats::CsvOrientation::EffectsAsRows);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto text = fuzz::as_text(data, size);
  import_with(text, {});
  formats::CsvImportOptions grid;
  grid.layout = formats::CsvLayoutKind::Grid;
  grid.orientation = formats::CsvOrientation::CausesAsRows;
  import_with(text, grid);
  grid.orientation = formats::CsvOrientation::EffectsAsRows;
  grid.strict = true;
  import_with(text, grid);
  // A vendor sheet's layout (docs/csv.md "The layout description"): marks,
  // trip sides and footnotes given, a rule for deleted rows.
  formats::CsvImportOptions vendor;
  vendor.layout = formats::CsvLayoutKind::Grid;
  vendor.sheet_layout = formats::SheetLayout{};
  vendor.sheet_layout->marks["NP"] = formats::MarkMeaning{std::nullopt, ""};
  vendor.sheet_layout->marks["S+"] = formats::MarkMeaning{model::IntersectionType::S, "*"};
  vendor.sheet_layout->trip_sides["6"] = model::LimitType::High;
  vendor.sheet_layout->footnotes["*"] = "footnote";
  vendor.sheet_layout->deleted.words = {"DELETED", "VOID"};
  import_with(text, vendor);
  return 0;
}
