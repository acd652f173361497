// The geometry of a timing diagram (internal to reports/timing_svg*.cpp): where
// each column sits, how wide the labels and the picture are, how texts are
// measured and wrapped, and how each row's signal is drawn. timing_svg.cpp
// puts the header, the rows, the folds, the marks, the axes and the legend
// together; timing_svg_rows.cpp draws the rows.
#pragma once

#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

#include "checker/result.hpp"
#include "model/matrix.hpp"
#include "reports/timing_rows.hpp"
#include "reports/timing_svg.hpp"

namespace cemv::reports::timing {

// A coordinate with at most one decimal ("12.5", "3"; never "-0").
std::string num(double v);

// Width of a text in the diagram's sans font of `size` px, estimated (no font
// metrics without a browser): wide enough for the examples' names.
double text_width(const std::string& s, double size = 12);

// The words of `s` in lines no wider than `width` at `size` px (a word longer
// than a line is cut at the line's end: names have no spaces to break at).
// The title, the marks and the legend run across the whole picture, which is
// narrow for a short run: they wrap instead of running past the right edge.
std::vector<std::string> wrap(const std::string& s, double size, double width, double factor = 0.6);

constexpr double kFoldWidth = 44;  // a folded stretch of cycles
constexpr double kPad = 6;         // between a row's edge and its drawing

double row_height(RowKind k);

// The rows and columns of one diagram and their x positions: a label column,
// then one column per cycle shown (or per folded stretch).
struct Layout {
  Layout(const model::Matrix& m, std::vector<Row> rows, std::size_t cycles, const TimingDiagram& d);

  // A row at a column: its last cycle's segment (a fold is constant).
  const Segment& segment(const Row& r, std::size_t col) const { return r.at(cols[col].last); }
  double at(const Row& r, std::size_t col) const { return segment(r, col).value; }

  const model::Matrix& m;
  std::size_t cycles = 0;
  const TimingDiagram& d;
  std::vector<Row> rows;
  std::vector<Column> cols;
  std::vector<double> xs;  // left edge of each column, then the right edge of the last
  double label_w = 150, cell_w = 28, width = 0;
};

// One row between y and y + h: its label, grid line, signal and bad-quality
// shading (timing_svg_rows.cpp).
void draw_row(std::ostringstream& o, const Layout& l, const Row& r, double y, double h);

}  // namespace cemv::reports::timing
