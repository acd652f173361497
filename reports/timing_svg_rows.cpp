// The rows of a timing diagram (timing_layout.hpp): a label and a grid line
// each, then the signal drawn by its kind: a digital waveform, a bus with its
// values written in, a timer's bar, an analog plot with its reference lines,
// the operator-command markers; input tags shade their bad-quality cycles.
#include <algorithm>
#include <cstdio>

#include "reports/timing_layout.hpp"
#include "reports/xml_text.hpp"

namespace cemv::reports::timing {

namespace {

class RowPainter {
 public:
  explicit RowPainter(const Layout& layout) : l(layout) {}

  void draw_row(std::ostringstream& o, const Row& r, double y, double h) const {
    draw_label(o, r, y, h);
    const double top = y + kPad, bottom = y + h - kPad;
    switch (r.kind) {
      case RowKind::Digital: digital(o, r, top, bottom); break;
      case RowKind::Bus: bus(o, r, top, bottom); break;
      case RowKind::Timer: timer(o, r, top, bottom); break;
      case RowKind::Analog: analog(o, r, y, top, bottom); break;
      case RowKind::Commands: commands(o, r, top, bottom); break;
    }
    if (r.any_bad())
      for (std::size_t i = 0; i < l.cols.size(); ++i)
        if (l.segment(r, i).bad)
          o << "<rect class=\"bad\" x=\"" << num(l.xs[i]) << "\" y=\"" << num(top) << "\" width=\""
            << num(l.xs[i + 1] - l.xs[i]) << "\" height=\"" << num(bottom - top)
            << "\"><title>bad quality</title></rect>\n";
  }

 private:
  void draw_label(std::ostringstream& o, const Row& r, double y, double h) const {
    o << "<line class=\"grid\" x1=\"0\" y1=\"" << num(y + h) << "\" x2=\"" << num(l.width) << "\" y2=\""
      << num(y + h) << "\"/>\n";
    double ty = r.kind == RowKind::Analog ? y + 18 : y + h / 2 + (r.note.empty() ? 4 : -2);
    o << "<text x=\"10\" y=\"" << num(ty) << "\">" << html_escape(r.label) << "</text>\n";
    if (!r.note.empty())
      o << "<text class=\"sub small\" x=\"10\" y=\"" << num(ty + 13) << "\">" << html_escape(r.note) << "</text>\n";
  }

  // The stepped line of a row through every column, `y_of` mapping values.
  template <class F>
  std::string steps(const Row& r, F y_of) const {
    std::string p;
    for (std::size_t i = 0; i < l.cols.size(); ++i) {
      double y = y_of(l.at(r, i));
      p += i == 0 ? "M" + num(l.xs[0]) + " " + num(y) : (l.at(r, i) != l.at(r, i - 1) ? " V" + num(y) : "");
      p += " H" + num(l.xs[i + 1]);
    }
    return p;
  }

  void digital(std::ostringstream& o, const Row& r, double top, double bottom) const {
    for (std::size_t i = 0; i < l.cols.size();) {
      std::size_t j = i;
      while (j + 1 < l.cols.size() && (l.at(r, j + 1) != 0) == (l.at(r, i) != 0)) ++j;
      if (l.at(r, i) != 0)
        o << "<rect class=\"high\" x=\"" << num(l.xs[i]) << "\" y=\"" << num(top) << "\" width=\""
          << num(l.xs[j + 1] - l.xs[i]) << "\" height=\"" << num(bottom - top) << "\"/>\n";
      i = j + 1;
    }
    o << "<path class=\"wave\" d=\"" << steps(r, [&](double v) { return v != 0 ? top : bottom; }) << "\"/>\n";
  }

  void bus(std::ostringstream& o, const Row& r, double top, double bottom) const {
    const double mid = (top + bottom) / 2;
    for (std::size_t i = 0; i < l.cols.size();) {
      std::size_t j = i;
      while (j + 1 < l.cols.size() && l.at(r, j + 1) == l.at(r, i)) ++j;
      double a = l.xs[i], b = l.xs[j + 1], e = std::min(3.0, (b - a) / 2);
      const std::string& text = l.segment(r, i).text;
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
    o << "<line class=\"grid\" x1=\"" << num(l.xs.front()) << "\" y1=\"" << num(bottom) << "\" x2=\""
      << num(l.xs.back()) << "\" y2=\"" << num(bottom) << "\"/>\n";
    for (std::size_t i = 0; i < l.cols.size(); ++i) {
      double e = double(r.running_for(l.cols[i].last)) * l.m.cycle_ms;
      if (e == 0) continue;
      double frac = r.duration_ms > 0 ? std::min(1.0, e / r.duration_ms) : 1.0;
      double h = std::max(2.0, frac * (bottom - top));
      o << "<rect class=\"timer\" x=\"" << num(l.xs[i]) << "\" y=\"" << num(bottom - h) << "\" width=\""
        << num(l.xs[i + 1] - l.xs[i]) << "\" height=\"" << num(h) << "\"><title>running "
        << time_text(e) << "</title></rect>\n";
    }
  }

  void analog(std::ostringstream& o, const Row& r, double y, double top, double bottom) const {
    top += 22;  // room for the label line above the plot
    (void)y;
    double lo = r.segments.front().value, hi = lo;
    for (const auto& s : r.segments) lo = std::min(lo, s.value), hi = std::max(hi, s.value);
    for (const auto& lv : r.levels) lo = std::min(lo, lv.value), hi = std::max(hi, lv.value);
    double pad = hi > lo ? (hi - lo) * 0.08 : 1.0;
    lo -= pad, hi += pad;
    auto y_of = [&](double v) { return bottom - (v - lo) / (hi - lo) * (bottom - top); };
    o << "<text class=\"sub small\" text-anchor=\"end\" x=\"" << num(l.label_w - 6) << "\" y=\"" << num(top + 8)
      << "\">" << html_escape(timing_number(hi)) << "</text>\n";
    o << "<text class=\"sub small\" text-anchor=\"end\" x=\"" << num(l.label_w - 6) << "\" y=\"" << num(bottom)
      << "\">" << html_escape(timing_number(lo)) << "</text>\n";
    double last_label_y = -1e9;
    std::vector<Level> levels = r.levels;
    std::stable_sort(levels.begin(), levels.end(), [](const auto& a, const auto& b) { return a.value > b.value; });
    for (const auto& lv : levels) {
      double ly = y_of(lv.value);
      o << "<line class=\"" << lv.css << "\" x1=\"" << num(l.xs.front()) << "\" y1=\"" << num(ly) << "\" x2=\""
        << num(l.xs.back()) << "\" y2=\"" << num(ly) << "\"/>\n";
      double ty = std::max(ly + 4, last_label_y + 11);
      last_label_y = ty;
      o << "<text class=\"small lvl-" << lv.css << "\" x=\"" << num(l.xs.back() + 6) << "\" y=\"" << num(ty)
        << "\">" << html_escape(lv.label) << "</text>\n";
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
    for (std::size_t i = 0; i < l.cols.size(); ++i) {
      const std::string& text = l.segment(r, i).text;
      if (l.cols[i].folded || text.empty()) continue;
      double x = (l.xs[i] + l.xs[i + 1]) / 2;
      o << "<polygon class=\"cmd\" points=\"" << num(x - 5) << "," << num(top) << " " << num(x + 5) << ","
        << num(top) << " " << num(x) << "," << num(top + 9) << "\"><title>cycle " << l.cols[i].first + 1 << ": "
        << html_escape(text) << "</title></polygon>\n";
      // The label stops at the picture's right edge (the marker's tooltip has it all).
      std::string label = text;
      const std::size_t room = static_cast<std::size_t>(std::max(0.0, l.width - x - 10) / (10 * 0.6));
      if (label.size() > room) label = room > 3 ? label.substr(0, room - 3) + "..." : "";
      o << "<text class=\"small\" x=\"" << num(x + 6) << "\" y=\"" << num(top + 20 + 11 * lane) << "\">"
        << html_escape(label) << "</text>\n";
      lane = 1 - lane;
    }
    (void)bottom;
  }

  const Layout& l;
};

}  // namespace

void draw_row(std::ostringstream& o, const Layout& l, const Row& r, double y, double h) {
  RowPainter(l).draw_row(o, r, y, h);
}

}  // namespace cemv::reports::timing
