// The intersections overview (6.6.2, docs/workbook.md "Intersections
// overview"), internal to formats/: effect numbers along row 2, cause numbers
// down column A (both by the rule of 6.6.3), one mark per cell.
#pragma once

#include <set>
#include <vector>

#include "sheets/workbook_cells.hpp"
#include "model/matrix.hpp"

namespace cemv::formats::workbook {

// The intersections of the overview in (cause, effect) order, each
// remembered as `intersections[i]`; `causes` and `effects` are the numbers of
// the two tables (a number without a row there is a warning). Problems go to
// the reader's errors and warnings.
std::vector<model::Intersection> read_overview(const Sheet& sheet, const std::set<int>& causes,
                                               const std::set<int>& effects, CellReader& reader);

}  // namespace cemv::formats::workbook
