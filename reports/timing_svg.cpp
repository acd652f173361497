#include "reports/timing_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "reports/timing_rows.hpp"
#include "reports/xml_text.hpp"

namespace cemv::reports {

namespace {

using timing::Column;
using timing::Row;
using timing::RowKind;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  std::string s = buf;
  if (s.size() > 2 && s.compare(s.size() - 2, 2, ".0") == 0) s.resize(s.size() - 2);
  return s == "-0" ? "0" : s;
}

// Width of a text in the diagram's 12 px sans font, estimated (no font
// metrics without a browser): wide enough for the examples' names.
double text_width(const std::string& s, double size = 12) { return s.size() * size * 0.6; }

// The words of `s` in lines no wider than `width` at `size` px (a word longer
// than a line is cut at the line's end: names have no spaces to break at).
// The title, the marks and the legend run across the whole picture, which is
// narrow for a short run: they wrap instead of running past the right edge.
std::vector<std::string> wrap(const std::string& s, double size, double width, double factor = 0.6) {
  const std::size_t max_chars = std::max<std::size_t>(8, static_cast<std::size_t>(width / (size * factor)));
  std::vector<std::string> lines;
  std::string line;
  std::istringstream words(s);
  for (std::string w; words >> w;) {
    while (w.size() > max_chars) {
      if (!line.empty()) lines.push_back(line), line.clear();
      lines.push_back(w.substr(0, max_chars));
      w.erase(0, max_chars);
    }
    if (!line.empty() && line.size() + 1 + w.size() > max_chars) lines.push_back(line), line.clear();
    line += (line.empty() ? "" : " ") + w;
  }
  if (!line.empty() || lines.empty()) lines.push_back(line);
  return lines;
}

constexpr double kFoldWidth = 44;
constexpr double kPad = 6;

double row_height(RowKind k) {
  switch (k) {
    case RowKind::Analog: return 96;
    case RowKind::Commands: return 40;
    default: return 30;
  }
}

const char* kStyle =
    "<style>\n"
    "text{fill:#1f2937}.title{font-size:15px;font-weight:bold}.sub{fill:#4b5563}.small{font-size:10px}\n"
    ".grid{stroke:#e5e7eb;stroke-width:1}.wave{fill:none;stroke:#1d4ed8;stroke-width:1.6}\n"
    ".high{fill:#dbeafe}.bus{fill:#ecfdf5;stroke:#047857;stroke-width:1.2}.analog{fill:none;stroke:#7c3aed;stroke-width:1.6}\n"
    ".limit{stroke:#dc2626;stroke-width:1.2;stroke-dasharray:6 3}.prewarning{stroke:#d97706;stroke-width:1.2;stroke-dasharray:4 3}\n"
    ".hysteresis{stroke:#6b7280;stroke-width:1;stroke-dasharray:2 3}.lvl-limit{fill:#dc2626}.lvl-prewarning{fill:#b45309}"
    ".lvl-hysteresis{fill:#4b5563}\n"
    ".timer{fill:#fde68a;stroke:#b45309;stroke-width:0.8}.bad{fill:#ef4444;fill-opacity:0.25}\n"
    ".fold{fill:url(#hatch)}.mark{fill:#ef4444;fill-opacity:0.14}.markline{stroke:#dc2626;stroke-width:1.5}\n"
    ".cmd{fill:#111827}.marktext{fill:#b91c1c;font-weight:bold}.check{fill:#15803d}\n"
    "</style>\n";

class Drawing {
 public:
  Drawing(const model::Matrix& m, const checker::ConcreteTrace& t, const TimingDiagram& d)
      : m_(m), t_(t), d_(d), rows_(timing::rows_of(m, t, d)),
        cols_(timing::columns_of(rows_, t.inputs.size(), d.marks)) {
    label_w_ = 150;
    for (const auto& r : rows_) label_w_ = std::max(label_w_, text_width(r.label) + 24);
    std::size_t single = 0;
    for (const auto& c : cols_) single += !c.folded;
    cell_w_ = std::clamp(std::floor(960.0 / std::max<std::size_t>(single, 1)), 3.0, 28.0);
    double x = label_w_;
    for (const auto& c : cols_) {
      xs_.push_back(x);
      x += c.folded ? kFoldWidth : cell_w_;
    }
    xs_.push_back(x);
    bool levels = false;
    for (const auto& r : rows_) levels |= !r.levels.empty();
    // At least wide enough for a readable line of title and legend.
    width_ = std::max(x + (levels ? 190 : 24), 560.0);
  }

  std::string svg() {
    // The header: title (15 px bold), subtitle, one line per mark, each
    // wrapped to the picture's width.
    const double text_w = width_ - 20;
    std::ostringstream head;
    double hy = 20;
    for (const auto& line : wrap(d_.title, 15, text_w, 0.66)) {
      head << "<text class=\"title\" x=\"10\" y=\"" << num(hy) << "\">" << html_escape(line) << "</text>\n";
      hy += 18;
    }
    for (const auto& line : wrap(subtitle(), 12, text_w)) {
      head << "<text class=\"sub\" x=\"10\" y=\"" << num(hy) << "\">" << html_escape(line) << "</text>\n";
      hy += 15;
    }
    for (const auto& mk : d_.marks) {
      std::string text = "\u25B2 " + mk.label + " (cycle " + std::to_string(mk.cycle + 1) +
                         ", t = " + timing::time_text(double(mk.cycle) * m_.cycle_ms) + ")";
      for (const auto& line : wrap(text, 12, text_w, 0.66)) {
        head << "<text class=\"marktext\" x=\"10\" y=\"" << num(hy + 1) << "\">" << html_escape(line)
             << "</text>\n";
        hy += 16;
      }
    }
    double header = hy;
    double axis_top = header + 18;
    double y = axis_top + 6;
    double rows_end = y;
    for (const auto& r : rows_) rows_end += row_height(r.kind);
    std::ostringstream body;
    draw_folds(body, axis_top, rows_end);  // under the rows: the waveforms run across
    for (const auto& r : rows_) {
      double h = row_height(r.kind);
      draw_row(body, r, y, h);
      y += h;
    }
    std::ostringstream over;
    draw_marks(over, axis_top, rows_end);
    draw_axes(over, axis_top, rows_end);
    std::vector<std::string> foot;
    for (const auto& paragraph : footer())
      for (auto& line : wrap(paragraph, 10, text_w)) foot.push_back(std::move(line));
    double height = rows_end + 30 + 15 * static_cast<double>(foot.size()) + 8;

    std::ostringstream o;
    o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width_) << "\" height=\"" << num(height)
      << "\" viewBox=\"0 0 " << num(width_) << " " << num(height)
      << "\" font-family=\"DejaVu Sans, Arial, Helvetica, sans-serif\" font-size=\"12\">\n";
    o << "<title>" << html_escape(d_.title) << "</title>\n" << kStyle;
    o << "<defs><pattern id=\"hatch\" width=\"6\" height=\"6\" patternUnits=\"userSpaceOnUse\" "
         "patternTransform=\"rotate(45)\"><rect width=\"6\" height=\"6\" fill=\"#f3f4f6\"/>"
         "<line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"6\" stroke=\"#d1d5db\" stroke-width=\"2\"/></pattern></defs>\n";
    o << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    o << head.str() << body.str() << over.str();
    double fy = rows_end + 34;
    for (const auto& line : foot) {
      o << "<text class=\"sub small\" x=\"10\" y=\"" << num(fy) << "\">" << html_escape(line) << "</text>\n";
      fy += 15;
    }
    o << "</svg>\n";
    return o.str();
  }

 private:
  std::string subtitle() const {
    std::size_t folded = 0, hidden = 0;
    for (const auto& c : cols_)
      if (c.folded) ++folded, hidden += c.last - c.first + 1;
    std::string s = "matrix " + m_.name + ", " + std::to_string(t_.inputs.size()) +
                    (t_.inputs.size() == 1 ? " cycle of " : " cycles of ") +
                    std::to_string(m_.cycle_ms) + " ms (" +
                    timing::time_text(double(t_.inputs.size()) * m_.cycle_ms) + ")";
    if (folded)
      s += "; " + std::to_string(folded) + (folded == 1 ? " stretch" : " stretches") + " of " +
           std::to_string(hidden) + " unchanged cycles folded";
    return s;
  }

  std::vector<std::string> footer() const {
    std::vector<std::string> out;
    // The legend names only what this picture draws.
    bool levels = false, bad = false, timers = false;
    for (const auto& r : rows_) {
      levels |= !r.levels.empty();
      for (bool b : r.bad) bad |= b;
      timers |= r.kind == RowKind::Timer;
    }
    std::string legend = "Cycle n starts at t = (n-1) x " + std::to_string(m_.cycle_ms) +
                         " ms; values are those after the cycle.";
    if (levels) legend += " Red dashes: limit; orange: prewarning; grey dots: hysteresis release.";
    if (bad) legend += " Red shading: bad quality.";
    if (timers) legend += " Bars: timers filling up to their time.";
    out.push_back(legend);
    if (!d_.checks.empty())
      out.push_back("Green ticks under the cycle numbers: the cycles at which the test checks its expectations.");
    std::size_t listed = 0, folds = 0;
    for (const auto& c : cols_) {
      if (!c.folded) continue;
      ++folds;
      if (listed == 4) continue;
      ++listed;
      out.push_back("Folded: cycles " + std::to_string(c.first + 1) + "-" + std::to_string(c.last + 1) + " (" +
                    std::to_string(c.last - c.first + 1) + " cycles, t = " +
                    timing::time_text(double(c.first) * m_.cycle_ms) + " to " +
                    timing::time_text(double(c.last) * m_.cycle_ms) + "): no drawn signal changes.");
    }
    if (folds > listed) out.push_back("... and " + std::to_string(folds - listed) + " more folded stretches.");
    return out;
  }

  // Value of a row at a column: its last cycle's (a fold is constant).
  double at(const Row& r, std::size_t col) const { return r.value[cols_[col].last]; }

  void draw_label(std::ostringstream& o, const Row& r, double y, double h) const {
    o << "<line class=\"grid\" x1=\"0\" y1=\"" << num(y + h) << "\" x2=\"" << num(width_) << "\" y2=\""
      << num(y + h) << "\"/>\n";
    double ty = r.kind == RowKind::Analog ? y + 18 : y + h / 2 + (r.note.empty() ? 4 : -2);
    o << "<text x=\"10\" y=\"" << num(ty) << "\">" << html_escape(r.label) << "</text>\n";
    if (!r.note.empty())
      o << "<text class=\"sub small\" x=\"10\" y=\"" << num(ty + 13) << "\">" << html_escape(r.note) << "</text>\n";
  }

  void draw_row(std::ostringstream& o, const Row& r, double y, double h) {
    draw_label(o, r, y, h);
    const double top = y + kPad, bottom = y + h - kPad;
    switch (r.kind) {
      case RowKind::Digital: digital(o, r, top, bottom); break;
      case RowKind::Bus: bus(o, r, top, bottom); break;
      case RowKind::Timer: timer(o, r, top, bottom); break;
      case RowKind::Analog: analog(o, r, y, top, bottom); break;
      case RowKind::Commands: commands(o, r, top, bottom); break;
    }
    if (!r.bad.empty())
      for (std::size_t i = 0; i < cols_.size(); ++i)
        if (r.bad[cols_[i].last])
          o << "<rect class=\"bad\" x=\"" << num(xs_[i]) << "\" y=\"" << num(top) << "\" width=\""
            << num(xs_[i + 1] - xs_[i]) << "\" height=\"" << num(bottom - top)
            << "\"><title>bad quality</title></rect>\n";
  }

  // The stepped line of a row through every column, `y_of` mapping values.
  template <class F>
  std::string steps(const Row& r, F y_of) const {
    std::string p;
    for (std::size_t i = 0; i < cols_.size(); ++i) {
      double y = y_of(at(r, i));
      p += i == 0 ? "M" + num(xs_[0]) + " " + num(y) : (at(r, i) != at(r, i - 1) ? " V" + num(y) : "");
      p += " H" + num(xs_[i + 1]);
    }
    return p;
  }

  void digital(std::ostringstream& o, const Row& r, double top, double bottom) const {
    for (std::size_t i = 0; i < cols_.size();) {
      std::size_t j = i;
      while (j + 1 < cols_.size() && (at(r, j + 1) != 0) == (at(r, i) != 0)) ++j;
      if (at(r, i) != 0)
        o << "<rect class=\"high\" x=\"" << num(xs_[i]) << "\" y=\"" << num(top) << "\" width=\""
          << num(xs_[j + 1] - xs_[i]) << "\" height=\"" << num(bottom - top) << "\"/>\n";
      i = j + 1;
    }
    o << "<path class=\"wave\" d=\"" << steps(r, [&](double v) { return v != 0 ? top : bottom; }) << "\"/>\n";
  }

  void bus(std::ostringstream& o, const Row& r, double top, double bottom) const {
    const double mid = (top + bottom) / 2;
    for (std::size_t i = 0; i < cols_.size();) {
      std::size_t j = i;
      while (j + 1 < cols_.size() && at(r, j + 1) == at(r, i)) ++j;
      double a = xs_[i], b = xs_[j + 1], e = std::min(3.0, (b - a) / 2);
      const std::string& text = r.text[cols_[i].last];
      o << "<polygon class=\"bus\" points=\"" << num(a) << "," << num(mid) << " " << num(a + e) << ","
        << num(top) << " " << num(b - e) << "," << num(top) << " " << num(b) << "," << num(mid) << " "
        << num(b - e) << "," << num(bottom) << " " << num(a + e) << "," << num(bottom) << "\"><title>"
        << html_escape(text) << "</title></polygon>\n";
      if (b - a >= text_width(text, 11) + 6)
        o << "<text font-size=\"11\" text-anchor=\"middle\" x=\"" << num((a + b) / 2) << "\" y=\""
          << num(mid + 4) << "\">" << html_escape(text) << "</text>\n";
      i = j + 1;
    }
  }

  // A running timer is a bar that fills up to its configured time.
  void timer(std::ostringstream& o, const Row& r, double top, double bottom) const {
    std::vector<double> elapsed(r.value.size(), 0.0);
    for (std::size_t k = 0; k < r.value.size(); ++k)
      if (r.value[k] != 0) elapsed[k] = (k ? elapsed[k - 1] : 0.0) + m_.cycle_ms;
    o << "<line class=\"grid\" x1=\"" << num(xs_.front()) << "\" y1=\"" << num(bottom) << "\" x2=\""
      << num(xs_.back()) << "\" y2=\"" << num(bottom) << "\"/>\n";
    for (std::size_t i = 0; i < cols_.size(); ++i) {
      double e = elapsed[cols_[i].last];
      if (e == 0) continue;
      double frac = r.duration_ms > 0 ? std::min(1.0, e / r.duration_ms) : 1.0;
      double h = std::max(2.0, frac * (bottom - top));
      o << "<rect class=\"timer\" x=\"" << num(xs_[i]) << "\" y=\"" << num(bottom - h) << "\" width=\""
        << num(xs_[i + 1] - xs_[i]) << "\" height=\"" << num(h) << "\"><title>running "
        << timing::time_text(e) << "</title></rect>\n";
    }
  }

  void analog(std::ostringstream& o, const Row& r, double y, double top, double bottom) const {
    top += 22;  // room for the label line above the plot
    (void)y;
    double lo = r.value[0], hi = r.value[0];
    for (double v : r.value) lo = std::min(lo, v), hi = std::max(hi, v);
    for (const auto& l : r.levels) lo = std::min(lo, l.value), hi = std::max(hi, l.value);
    double pad = hi > lo ? (hi - lo) * 0.08 : 1.0;
    lo -= pad, hi += pad;
    auto y_of = [&](double v) { return bottom - (v - lo) / (hi - lo) * (bottom - top); };
    o << "<text class=\"sub small\" text-anchor=\"end\" x=\"" << num(label_w_ - 6) << "\" y=\"" << num(top + 8)
      << "\">" << html_escape(timing_number(hi)) << "</text>\n";
    o << "<text class=\"sub small\" text-anchor=\"end\" x=\"" << num(label_w_ - 6) << "\" y=\"" << num(bottom)
      << "\">" << html_escape(timing_number(lo)) << "</text>\n";
    double last_label_y = -1e9;
    std::vector<timing::Level> levels = r.levels;
    std::stable_sort(levels.begin(), levels.end(), [](const auto& a, const auto& b) { return a.value > b.value; });
    for (const auto& l : levels) {
      double ly = y_of(l.value);
      o << "<line class=\"" << l.css << "\" x1=\"" << num(xs_.front()) << "\" y1=\"" << num(ly) << "\" x2=\""
        << num(xs_.back()) << "\" y2=\"" << num(ly) << "\"/>\n";
      double ty = std::max(ly + 4, last_label_y + 11);
      last_label_y = ty;
      o << "<text class=\"small lvl-" << l.css << "\" x=\"" << num(xs_.back() + 6) << "\" y=\"" << num(ty)
        << "\">" << html_escape(l.label) << "</text>\n";
    }
    o << "<path class=\"analog\" d=\"" << steps(r, y_of) << "\"/>\n";
  }

  static std::string timing_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
  }

  void commands(std::ostringstream& o, const Row& r, double top, double bottom) const {
    int lane = 0;
    for (std::size_t i = 0; i < cols_.size(); ++i) {
      const std::string& text = r.text[cols_[i].last];
      if (cols_[i].folded || text.empty()) continue;
      double x = (xs_[i] + xs_[i + 1]) / 2;
      o << "<polygon class=\"cmd\" points=\"" << num(x - 5) << "," << num(top) << " " << num(x + 5) << ","
        << num(top) << " " << num(x) << "," << num(top + 9) << "\"><title>cycle " << cols_[i].first + 1 << ": "
        << html_escape(text) << "</title></polygon>\n";
      // The label stops at the picture's right edge (the marker's tooltip has it all).
      std::string label = text;
      const std::size_t room = static_cast<std::size_t>(std::max(0.0, width_ - x - 10) / (10 * 0.6));
      if (label.size() > room) label = room > 3 ? label.substr(0, room - 3) + "..." : "";
      o << "<text class=\"small\" x=\"" << num(x + 6) << "\" y=\"" << num(top + 20 + 11 * lane) << "\">"
        << html_escape(label) << "</text>\n";
      lane = 1 - lane;
    }
    (void)bottom;
  }

  void draw_folds(std::ostringstream& o, double axis_top, double rows_end) const {
    for (std::size_t i = 0; i < cols_.size(); ++i) {
      if (!cols_[i].folded) continue;
      std::size_t n = cols_[i].last - cols_[i].first + 1;
      double a = xs_[i] + 8, b = xs_[i + 1] - 8;
      o << "<rect class=\"fold\" x=\"" << num(a) << "\" y=\"" << num(axis_top) << "\" width=\"" << num(b - a)
        << "\" height=\"" << num(rows_end - axis_top) << "\"><title>cycles "
        << cols_[i].first + 1 << "-" << cols_[i].last + 1 << " folded: " << n
        << " cycles without a change</title></rect>\n";
      o << "<text class=\"small\" text-anchor=\"middle\" x=\"" << num((a + b) / 2) << "\" y=\""
        << num(axis_top + 12) << "\">" << n << "</text>\n";
    }
  }

  void draw_marks(std::ostringstream& o, double axis_top, double rows_end) const {
    for (std::size_t c : d_.checks)
      for (std::size_t i = 0; i < cols_.size(); ++i)
        if (!cols_[i].folded && cols_[i].first <= c && c <= cols_[i].last) {
          double x = (xs_[i] + xs_[i + 1]) / 2;
          o << "<polygon class=\"check\" points=\"" << num(x - 4) << "," << num(axis_top) << " " << num(x + 4) << ","
            << num(axis_top) << " " << num(x) << "," << num(axis_top + 6) << "\"><title>cycle " << c + 1
            << ": expectations checked</title></polygon>\n";
        }
    for (const auto& mk : d_.marks)
      for (std::size_t i = 0; i < cols_.size(); ++i)
        if (cols_[i].first <= mk.cycle && mk.cycle <= cols_[i].last) {
          o << "<rect class=\"mark\" x=\"" << num(xs_[i]) << "\" y=\"" << num(axis_top) << "\" width=\""
            << num(xs_[i + 1] - xs_[i]) << "\" height=\"" << num(rows_end - axis_top) << "\"><title>"
            << html_escape(mk.label) << "</title></rect>\n";
          o << "<line class=\"markline\" x1=\"" << num(xs_[i + 1]) << "\" y1=\"" << num(axis_top - 4)
            << "\" x2=\"" << num(xs_[i + 1]) << "\" y2=\"" << num(rows_end) << "\"/>\n";
        }
  }

  // Cycle numbers above the rows, times below, at "nice" steps far enough apart.
  void draw_axes(std::ostringstream& o, double axis_top, double rows_end) const {
    static const std::size_t nice[] = {1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000};
    std::size_t step = 10000;
    for (std::size_t s : nice)
      if (double(s) * cell_w_ >= 40) {
        step = s;
        break;
      }
    o << "<text class=\"sub small\" x=\"10\" y=\"" << num(axis_top - 4) << "\">cycle</text>\n";
    o << "<text class=\"sub small\" x=\"10\" y=\"" << num(rows_end + 16) << "\">time</text>\n";
    double last_x = -1e9;
    for (std::size_t i = 0; i < cols_.size(); ++i) {
      if (cols_[i].folded) continue;
      std::size_t c = cols_[i].first;
      bool after_fold = i > 0 && cols_[i - 1].folded;
      bool wanted = c == 0 || (c + 1) % step == 0 || after_fold || (step == 1);
      double x = (xs_[i] + xs_[i + 1]) / 2;
      if (!wanted || x - last_x < 40) continue;
      last_x = x;
      o << "<line class=\"grid\" x1=\"" << num(x) << "\" y1=\"" << num(axis_top) << "\" x2=\"" << num(x)
        << "\" y2=\"" << num(rows_end) << "\"/>\n";
      o << "<text class=\"small\" text-anchor=\"middle\" x=\"" << num(x) << "\" y=\"" << num(axis_top - 4)
        << "\">" << c + 1 << "</text>\n";
      o << "<text class=\"small\" text-anchor=\"middle\" x=\"" << num(x) << "\" y=\"" << num(rows_end + 16)
        << "\">" << html_escape(timing::time_text(double(c) * m_.cycle_ms)) << "</text>\n";
    }
  }

  const model::Matrix& m_;
  const checker::ConcreteTrace& t_;
  const TimingDiagram& d_;
  std::vector<Row> rows_;
  std::vector<Column> cols_;
  std::vector<double> xs_;
  double label_w_ = 150, cell_w_ = 28, width_ = 0;
};

}  // namespace

std::string timing_svg(const model::Matrix& m, const checker::ConcreteTrace& trace, const TimingDiagram& d) {
  return Drawing(m, trace, d).svg();
}

TimingDiagram diagram_of(const checker::PropertyResult& p) {
  TimingDiagram d;
  bool witness = p.verdict == checker::PropertyVerdict::Reachable;
  d.title = std::string(witness ? "Witness of " : "Counterexample to ") + p.name;
  if (!p.description.empty()) d.title += ": " + p.description;
  d.shown = p.matters;
  if (p.violation_cycle >= 0)
    d.marks.push_back({static_cast<std::size_t>(p.violation_cycle),
                       std::string(witness ? "reached: " : "violated: ") + p.name});
  return d;
}

}  // namespace cemv::reports
