// The tag-name conventions of the Safety Matrix spreadsheet (6.6.2, "Notes on
// exported data"), internal to formats/:
//  - `#` as prefix: external connection; `#` as suffix: F-channel driver "with
//    monitoring". cemv-matrix/1 keeps both marks in the tag name itself (6.1.4,
//    docs/format.md "Tag names"), so they pass through unchanged.
//  - `[x]` / `[x][y]` after `Cause` / `Effect`: internal references (6.1.3),
//    also part of the name (`Cause[1]`, `Effect[7][2]`).
//  - `@` (used externally), `~` (customized), `*` (with preprocessing) as
//    prefix: options of the F-channel driver, outside the matrix logic and
//    outside cemv-matrix/1. The importer strips them and warns that they are
//    ignored.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace cemv::formats::workbook {

struct TagCell {
  std::string name;                    // as cemv-matrix/1 keeps it
  std::vector<std::string> ignored;    // the F-channel-driver options stripped, as words
  std::string normalized;              // non-empty when a reference's spelling was corrected
};

// Reads a tag cell: the prefixes `@`, `~`, `*` (each at most once, in any
// order) are stripped; `cause[1]` / `EFFECT[2][1]` become `Cause[1]` /
// `Effect[2][1]` (a reference written in other letter case would otherwise be
// read as an ordinary tag of that name, a different signal).
TagCell read_tag_cell(std::string_view text);

// The cell text of a tag name: the name itself, except that a name beginning
// with `*` (a legal cemv name that the prefix convention would read as the
// preprocessing option) is written `**NAME`, which reads back as NAME with
// the option, ignored.
std::string tag_cell_text(std::string_view name);

}  // namespace cemv::formats::workbook
