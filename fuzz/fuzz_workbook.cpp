// Fuzz target: the workbook importer (sheets/workbook.hpp, docs/workbook.md),
// the bytes `cemv import-workbook` reads: an ODS or XLSX file, the six tables
// or a C&E grid. Expected answers: a matrix, or a LoadError. Invariants of an
// accepted matrix: it passes the matrix loader (the importer promises the JSON
// loader's checks), and its export as ODS and as XLSX imports back to the same
// canonical form (the lossless round trip of docs/workbook.md).
//
// The first byte chooses how the input is read (docs/fuzzing.md):
// - 'P' (a zip file begins "PK"): the input is the workbook file itself; this
//   reaches the zip container (directory, sizes, the limits) but rarely the
//   XML behind it, because every entry is deflated and CRC-checked;
// - anything else: the input is a listing of the archive's entries, each
//   introduced by a line "@@ NAME", which the target packs into a zip (the
//   `mimetype` entry stored, the others deflated) before importing it. Whether
//   that is an ODS or an XLSX is told by the entries, as for a file. This is
//   how the fuzzer reaches the XML of content.xml, the shared strings and the
//   sheets with byte-level mutations.
// The file name only names the input in messages (the reader never looks at
// it): "fuzz.ods" for a file, "fuzz.xlsx"/"fuzz.ods" for a listing after the
// package it builds.
#include <cstddef>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>

#include "formats/matrix_json.hpp"
#include "sheets/workbook.hpp"
#include "sheets/workbook_zip.hpp"
#include "fuzz/fuzz_support.hpp"

using namespace cemv;

namespace {

// At most this many entries are packed: the importer reads a handful of named
// parts; more only slows every execution down.
constexpr std::size_t kMaxListedEntries = 32;

// The listing as a zip archive; "" when the listing names no entry. An entry
// named twice is packed once (the first), as a zip directory holds a name once.
std::string pack_listing(std::string_view text, bool& xlsx) {
  formats::workbook::ZipWriter zip;
  std::set<std::string> names;
  xlsx = false;
  std::size_t pos = text.rfind("@@ ", 0) == 0 ? 0 : text.find("\n@@ ");
  if (pos != std::string_view::npos && pos > 0) ++pos;  // at the "@@ " of the first entry
  while (pos != std::string_view::npos && names.size() < kMaxListedEntries) {
    const std::size_t name_end = text.find('\n', pos);
    const std::string name(text.substr(pos + 3, name_end == std::string_view::npos ? std::string_view::npos
                                                                                     : name_end - pos - 3));
    std::size_t next = name_end == std::string_view::npos ? std::string_view::npos : text.find("\n@@ ", name_end);
    std::string data;
    if (name_end != std::string_view::npos)
      data = std::string(text.substr(name_end + 1, next == std::string_view::npos ? std::string_view::npos
                                                                                   : next - name_end - 1));
    if (!name.empty() && names.insert(name).second) {
      if (name == "[Content_Types].xml" || name.rfind("xl/", 0) == 0) xlsx = true;
      zip.add(name, std::move(data), name == "mimetype");
    }
    pos = next == std::string_view::npos ? next : next + 1;
  }
  if (names.empty()) return {};
  return zip.finish();
}

void round_trip(const model::Matrix& m, formats::WorkbookFormat format, const std::string& canonical) {
  const std::string bytes = formats::export_workbook(m, format);
  const char* name = format == formats::WorkbookFormat::Ods ? "exported.ods" : "exported.xlsx";
  try {
    if (formats::to_canonical_json(formats::parse_workbook(bytes, name)) != canonical)
      fuzz::finding("the workbook does not round-trip", name);
  } catch (const formats::LoadError& e) {
    fuzz::finding("the exported workbook of an imported matrix does not import", e.issues().front().str());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto text = fuzz::as_text(data, size);
  std::string bytes;
  std::string name = "fuzz.ods";
  if (!text.empty() && text.front() == 'P') {
    bytes = std::string(text);
  } else {
    bool xlsx = false;
    try {
      bytes = pack_listing(text, xlsx);
    } catch (const std::runtime_error&) {
      return 0;  // libzip refused an entry name: the target's packing, not the importer
    }
    if (bytes.empty()) return 0;
    if (xlsx) name = "fuzz.xlsx";
  }
  model::Matrix m;
  try {
    m = formats::parse_workbook(bytes, name);
  } catch (const formats::LoadError&) {
    return 0;
  }
  const std::string canonical = formats::to_canonical_json(m);
  try {
    formats::parse_matrix(canonical, "imported.json");
  } catch (const formats::LoadError& e) {
    fuzz::finding("an imported matrix does not pass the matrix loader", e.issues().front().str());
  }
  round_trip(m, formats::WorkbookFormat::Ods, canonical);
  round_trip(m, formats::WorkbookFormat::Xlsx, canonical);
  return 0;
}
