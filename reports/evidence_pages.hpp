// The printed pages of the evidence report, laid out by cemv itself: a table
// of contents with page numbers needs to know on which page each chapter
// starts, and no browser tells that to the document it prints. Every block
// (a heading, a paragraph, a diagram, a table row) gets a height estimated
// from its text and the page's fixed geometry (A4, fixed fonts and line
// heights, fixed column widths), conservatively; blocks fill a sheet up to
// its height and a sheet ends with a forced page break. So each sheet prints
// as exactly one page, and the page numbers in the contents are the printed
// ones (tests/reports/evidence_pages.sh prints a report and compares).
// Internal to reports/evidence*.cpp.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace cemv::reports::evidence_detail {

// The printable area (docs/reports.md: A4, 16 mm margins above and below for
// the running header and footer, 12 mm at the sides), in mm.
inline constexpr double kPageWidthMm = 186.0;
inline constexpr double kPageHeightMm = 258.0;

// Lines of `text` in a column `width_mm` wide at `font_pt`: words wrapped
// like a browser wraps them, with a conservative average character width of
// DejaVu Sans. Explicit line breaks count.
int lines_of(const std::string& text, double width_mm, double font_pt);
// Height of `lines` lines at `font_pt` (line height 1.3), in mm.
double lines_height(int lines, double font_pt);

struct Cell {
  std::string html;      // what is shown
  std::string text;      // what is measured (the text of html, without markup)
  std::string css;       // class of the <td>
  double font_pt = 0;    // 0: the table's
};

struct Table {
  std::vector<double> widths_mm;   // sum <= kPageWidthMm
  std::vector<std::string> head;   // header cells (text), repeated on every page
  std::vector<std::vector<Cell>> rows;
  std::vector<std::string> row_css;  // per row (may be empty)
  std::string css;                   // class of the <table>
  double font_pt = 8.5;
  double head_height_mm = 0;         // 0: measured from the head texts
};

struct TocEntry {
  std::string id;      // the anchor
  std::string number;  // "1", "1.3", "A"
  std::string title;
  int level = 1;
  int sheet = 0;       // 1-based content sheet
};

class Pages {
 public:
  // A chapter starts a new sheet and is an entry of the contents.
  void chapter(const std::string& id, const std::string& number, const std::string& title);
  // A section heading (an entry of the contents when `listed`); never the
  // last block of a sheet.
  void section(const std::string& id, const std::string& number, const std::string& title, bool listed = true);
  // A one-line caption that stays with the block after it (like a heading,
  // not in the contents).
  void caption(const std::string& text);
  // A block that is never split, `height_mm` high.
  void block(const std::string& html, double height_mm);
  // A paragraph of `text` (escaped here) at `font_pt`, css class `css`.
  void paragraph(const std::string& text, const std::string& css = "", double font_pt = 9.0);
  // The same, with html given and `text` its plain text for measuring.
  void paragraph_html(const std::string& html, const std::string& text, const std::string& css = "",
                      double font_pt = 9.0);
  // Rows never split; a table split over sheets repeats its head.
  void table(const Table& t);

  const std::vector<std::string>& sheets() const { return sheets_; }
  const std::vector<TocEntry>& toc() const { return toc_; }

 private:
  void new_sheet();
  void place(const std::string& html, double height_mm);
  double row_height(const Table& t, const std::vector<Cell>& row) const;
  std::string head_html(const Table& t) const;

  std::vector<std::string> sheets_;
  std::vector<TocEntry> toc_;
  double used_ = 0;                 // mm of the current sheet
  std::string pending_;             // a heading waiting for the block it belongs to
  double pending_height_ = 0;
};

}  // namespace cemv::reports::evidence_detail
