// Fuzz target: the layout description of a C&E sheet (sheets/sheet_layout.hpp,
// docs/csv.md "The layout description"), the bytes of `--sheet-layout FILE`.
// Expected answers: a layout, or a LoadError. Invariant of an accepted layout:
// written back (the form --save-layout writes) it reads as the same layout,
// and that form is a fixed point.
#include <cstddef>
#include <cstdint>

#include "formats/diagnostics.hpp"
#include "sheets/sheet_layout.hpp"
#include "fuzz/fuzz_support.hpp"

using namespace cemv;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  formats::SheetLayout layout;
  try {
    layout = formats::parse_sheet_layout(fuzz::as_text(data, size), "fuzz.json");
  } catch (const formats::LoadError&) {
    return 0;
  }
  const std::string written = formats::sheet_layout_json(layout);
  try {
    const std::string again = formats::sheet_layout_json(formats::parse_sheet_layout(written, "written.json"));
    if (again != written) fuzz::finding("a written layout is not a fixed point", written);
    const std::string one_line = formats::sheet_layout_json(layout, true);
    if (formats::sheet_layout_json(formats::parse_sheet_layout(one_line, "line.json")) != written)
      fuzz::finding("the one-line form reads as another layout", one_line);
  } catch (const formats::LoadError& e) {
    fuzz::finding("a written layout does not read back", e.issues().front().str() + "\n" + written);
  }
  return 0;
}
