#include "reports/evidence_pages.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "reports/xml_text.hpp"

namespace cemv::reports::evidence_detail {

namespace {

constexpr double kPtMm = 0.3528;           // 1 pt in mm
// Average advance of DejaVu Sans in em, rounded up: its digits and capitals
// are 0.64-0.72 em, lower case 0.5-0.63; wide text (ids, tags) takes more.
constexpr double kCharEm = 0.64;
constexpr double kLineEm = 1.3;            // the CSS line-height of the report
constexpr double kCellPadMm = 1.8;         // padding (0.5 mm each side) and borders of a table row
constexpr double kCellSideMm = 2.4;        // horizontal padding and borders of a cell
constexpr double kParagraphGapMm = 2.0;    // margin under a paragraph

// UTF-8 code points, each one character wide.
std::size_t chars(const std::string& s, std::size_t from, std::size_t to) {
  std::size_t n = 0;
  for (std::size_t i = from; i < to; ++i) n += (static_cast<unsigned char>(s[i]) & 0xC0) != 0x80;
  return n;
}

}  // namespace

int lines_of(const std::string& text, double width_mm, double font_pt) {
  const double char_mm = font_pt * kPtMm * kCharEm;
  const auto per_line = static_cast<std::size_t>(std::max(1.0, std::floor(width_mm / char_mm)));
  int lines = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    // Greedy word wrap, a word longer than a line broken inside.
    std::size_t used = 0;
    int here = 1;
    std::size_t i = start;
    while (i < end) {
      std::size_t space = text.find(' ', i);
      if (space == std::string::npos || space > end) space = end;
      std::size_t word = chars(text, i, space);
      if (used > 0 && used + 1 + word > per_line) {
        ++here;
        used = 0;
      }
      while (word > per_line) {
        word -= per_line;
        ++here;
      }
      used += (used ? 1 : 0) + word;
      i = space + 1;
    }
    lines += here;
    if (end == text.size()) break;
    start = end + 1;
  }
  return std::max(lines, 1);
}

double lines_height(int lines, double font_pt) { return lines * font_pt * kPtMm * kLineEm; }

void Pages::new_sheet() {
  sheets_.emplace_back();
  used_ = 0;
}

// Puts a block on the current sheet, or on a new one when it does not fit;
// a heading waiting for it goes with it.
void Pages::place(const std::string& html, double height_mm) {
  if (sheets_.empty()) new_sheet();
  const double needed = pending_height_ + height_mm;
  if (used_ > 0 && used_ + needed > kPageHeightMm) {
    new_sheet();
    if (!pending_.empty())
      for (auto& e : toc_)
        if (e.sheet == static_cast<int>(sheets_.size()) - 1 && pending_.find("id=\"" + e.id + "\"") != std::string::npos)
          e.sheet = static_cast<int>(sheets_.size());
  }
  sheets_.back() += pending_ + html;
  used_ += needed;
  pending_.clear();
  pending_height_ = 0;
}

void Pages::chapter(const std::string& id, const std::string& number, const std::string& title) {
  if (!pending_.empty()) place("", 0);
  new_sheet();
  toc_.push_back({id, number, title, 1, static_cast<int>(sheets_.size())});
  const std::string text = number.empty() ? title : number + ". " + title;
  sheets_.back() += "<h2 id=\"" + id + "\">" + html_escape(text) + "</h2>\n";
  used_ += 4.0 + lines_height(lines_of(text, kPageWidthMm, 14), 14) + 3.0;
}

void Pages::section(const std::string& id, const std::string& number, const std::string& title, bool listed) {
  if (!pending_.empty()) place("", 0);
  if (sheets_.empty()) new_sheet();
  if (listed) toc_.push_back({id, number, title, 2, static_cast<int>(sheets_.size())});
  const std::string text = number.empty() ? title : number + " " + title;
  pending_ = "<h3 id=\"" + id + "\">" + html_escape(text) + "</h3>\n";
  pending_height_ = 4.5 + lines_height(lines_of(text, kPageWidthMm, 11.5), 11.5) + 1.5;
}

void Pages::caption(const std::string& text) {
  if (!pending_.empty()) place("", 0);
  if (sheets_.empty()) new_sheet();
  pending_ = "<p class=\"caption\">" + html_escape(text) + "</p>\n";
  pending_height_ = lines_height(lines_of(text, kPageWidthMm, 8.5), 8.5) + kParagraphGapMm;
}

void Pages::block(const std::string& html, double height_mm) { place(html, height_mm); }

void Pages::paragraph(const std::string& text, const std::string& css, double font_pt) {
  paragraph_html(html_escape(text), text, css, font_pt);
}

void Pages::paragraph_html(const std::string& html, const std::string& text, const std::string& css, double font_pt) {
  const bool boxed = !css.empty();  // a coloured paragraph has padding
  const double width = kPageWidthMm - (boxed ? 4.0 : 0.0);
  const double h = lines_height(lines_of(text, width, font_pt), font_pt) + kParagraphGapMm + (boxed ? 2.5 : 0.0);
  std::ostringstream o;
  o << "<p" << (css.empty() ? "" : " class=\"" + css + "\"");
  if (font_pt != 9.0) o << " style=\"font-size:" << font_pt << "pt\"";
  o << ">" << html << "</p>\n";
  place(o.str(), h);
}

double Pages::row_height(const Table& t, const std::vector<Cell>& row) const {
  double h = 0;
  for (std::size_t i = 0; i < row.size() && i < t.widths_mm.size(); ++i) {
    const double pt = row[i].font_pt > 0 ? row[i].font_pt : t.font_pt;
    h = std::max(h, lines_height(lines_of(row[i].text, t.widths_mm[i] - kCellSideMm, pt), pt));
  }
  return h + kCellPadMm;
}

std::string Pages::head_html(const Table& t) const {
  std::ostringstream o;
  o << "<table class=\"fixed" << (t.css.empty() ? "" : " " + t.css) << "\" style=\"font-size:" << t.font_pt
    << "pt\">\n<colgroup>";
  for (double w : t.widths_mm) o << "<col style=\"width:" << w << "mm\">";
  o << "</colgroup>\n";
  if (!t.head.empty()) {
    o << "<thead><tr>";
    for (const auto& h : t.head) o << "<th>" << html_escape(h) << "</th>";
    o << "</tr></thead>\n";
  }
  o << "<tbody>\n";
  return o.str();
}

void Pages::table(const Table& t) {
  double head_h = t.head_height_mm;
  if (head_h == 0 && !t.head.empty()) {
    std::vector<Cell> cells;
    for (const auto& h : t.head) cells.push_back({"", h, "", 0});
    head_h = row_height(t, cells);
  }
  // A short table that fits a page is not split: it moves to the next page whole.
  if (t.rows.size() <= 8 && !sheets_.empty() && used_ > 0) {
    double whole = head_h + 1.5 + pending_height_;
    for (const auto& r : t.rows) whole += row_height(t, r);
    if (whole <= kPageHeightMm && used_ + whole > kPageHeightMm) {
      std::string heading = pending_;
      const double heading_h = pending_height_;
      pending_.clear();
      pending_height_ = 0;
      new_sheet();
      for (auto& e : toc_)
        if (!heading.empty() && heading.find("id=\"" + e.id + "\"") != std::string::npos)
          e.sheet = static_cast<int>(sheets_.size());
      pending_ = heading;
      pending_height_ = heading_h;
    }
  }
  std::string body;
  double body_h = 0;
  auto flush = [&] {
    if (body.empty()) return;
    place(head_html(t) + body + "</tbody></table>\n", head_h + body_h + 1.5);
    body.clear();
    body_h = 0;
  };
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const double h = row_height(t, t.rows[r]);
    if (sheets_.empty()) new_sheet();
    const double room = kPageHeightMm - used_ - pending_height_ - head_h - 1.5;
    if (!body.empty() && body_h + h > room) flush();
    if (body.empty() && used_ > 0 && used_ + pending_height_ + head_h + h + 1.5 > kPageHeightMm) {
      // Not even the head and one row fit: the table starts on a new sheet.
      std::string heading = pending_;
      double heading_h = pending_height_;
      pending_.clear();
      pending_height_ = 0;
      new_sheet();
      for (auto& e : toc_)
        if (!heading.empty() && heading.find("id=\"" + e.id + "\"") != std::string::npos)
          e.sheet = static_cast<int>(sheets_.size());
      pending_ = heading;
      pending_height_ = heading_h;
    }
    std::ostringstream row;
    row << "<tr" << (r < t.row_css.size() && !t.row_css[r].empty() ? " class=\"" + t.row_css[r] + "\"" : "") << ">";
    for (const auto& c : t.rows[r]) {
      row << "<td" << (c.css.empty() ? "" : " class=\"" + c.css + "\"");
      if (c.font_pt > 0) row << " style=\"font-size:" << c.font_pt << "pt\"";
      row << ">" << c.html << "</td>";
    }
    row << "</tr>\n";
    body += row.str();
    body_h += h;
  }
  flush();
}

}  // namespace cemv::reports::evidence_detail
