// Timing diagrams as SVG (timing_svg.hpp): the picture put together from its
// header (title, subtitle, marks, wrapped to its width), the rows
// (timing_svg_rows.cpp), the folds, marks and axes drawn across them, and the
// legend under them. The geometry is timing_layout.hpp's.
#include "reports/timing_svg.hpp"

#include "reports/check_report.hpp"

#include <sstream>
#include <string>
#include <vector>

#include "reports/check_report.hpp"
#include "reports/timing_layout.hpp"
#include "reports/timing_rows.hpp"
#include "reports/xml_text.hpp"

namespace cemv::reports {

namespace {

using namespace timing;

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
  Drawing(const model::Matrix& m, std::vector<timing::Row> rows, std::size_t cycles, const TimingDiagram& d)
      : l_(m, std::move(rows), cycles, d) {}

  std::string svg() {
    // The header: title (15 px bold), subtitle, one line per mark, each
    // wrapped to the picture's width.
    const double text_w = l_.width - 20;
    std::ostringstream head;
    double hy = 20;
    for (const auto& line : wrap(l_.d.title, 15, text_w, 0.66)) {
      head << "<text class=\"title\" x=\"10\" y=\"" << num(hy) << "\">" << html_escape(line) << "</text>\n";
      hy += 18;
    }
    for (const auto& line : wrap(subtitle(), 12, text_w)) {
      head << "<text class=\"sub\" x=\"10\" y=\"" << num(hy) << "\">" << html_escape(line) << "</text>\n";
      hy += 15;
    }
    for (const auto& mk : l_.d.marks) {
      std::string text = "\u25B2 " + mk.label + " (cycle " + std::to_string(mk.cycle + 1) +
                         ", t = " + time_text(double(mk.cycle) * l_.m.cycle_ms) + ")";
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
    for (const auto& r : l_.rows) rows_end += row_height(r.kind);
    std::ostringstream body;
    draw_folds(body, axis_top, rows_end);  // under the rows: the waveforms run across
    for (const auto& r : l_.rows) {
      double h = row_height(r.kind);
      draw_row(body, l_, r, y, h);
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
    o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(l_.width) << "\" height=\"" << num(height)
      << "\" viewBox=\"0 0 " << num(l_.width) << " " << num(height)
      << "\" font-family=\"DejaVu Sans, Arial, Helvetica, sans-serif\" font-size=\"12\">\n";
    o << "<title>" << html_escape(l_.d.title) << "</title>\n" << kStyle;
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
    for (const auto& c : l_.cols)
      if (c.folded) ++folded, hidden += c.last - c.first + 1;
    std::string s = "matrix " + l_.m.name + ", " + std::to_string(l_.cycles) +
                    (l_.cycles == 1 ? " cycle of " : " cycles of ") +
                    std::to_string(l_.m.cycle_ms) + " ms (" +
                    time_text(double(l_.cycles) * l_.m.cycle_ms) + ")";
    if (folded)
      s += "; " + std::to_string(folded) + (folded == 1 ? " stretch" : " stretches") + " of " +
           std::to_string(hidden) + " unchanged cycles folded";
    return s;
  }

  std::vector<std::string> footer() const {
    std::vector<std::string> out;
    if (!l_.d.notes.empty()) {
      out.push_back("Why, per step (the rules of docs/semantics.md the runtime applied):");
      for (const auto& n : l_.d.notes) out.push_back("\u2022 " + n);
    }
    // The legend names only what this picture draws.
    bool levels = false, bad = false, timers = false;
    for (const auto& r : l_.rows) {
      levels |= !r.levels.empty();
      bad |= r.any_bad();
      timers |= r.kind == RowKind::Timer;
    }
    std::string legend = "Cycle n starts at t = (n-1) x " + std::to_string(l_.m.cycle_ms) +
                         " ms; values are those after the cycle.";
    if (levels) legend += " Red dashes: limit; orange: prewarning; grey dots: hysteresis release.";
    if (bad) legend += " Red shading: bad quality.";
    if (timers) legend += " Bars: timers filling up to their time.";
    out.push_back(legend);
    if (!l_.d.checks.empty())
      out.push_back("Green ticks under the cycle numbers: the cycles at which the test checks its expectations.");
    std::size_t listed = 0, folds = 0;
    for (const auto& c : l_.cols) {
      if (!c.folded) continue;
      ++folds;
      if (listed == 4) continue;
      ++listed;
      out.push_back("Folded: cycles " + std::to_string(c.first + 1) + "-" + std::to_string(c.last + 1) + " (" +
                    std::to_string(c.last - c.first + 1) + " cycles, t = " +
                    time_text(double(c.first) * l_.m.cycle_ms) + " to " +
                    time_text(double(c.last) * l_.m.cycle_ms) + "): no drawn signal changes.");
    }
    if (folds > listed) out.push_back("... and " + std::to_string(folds - listed) + " more folded stretches.");
    return out;
  }

  void draw_folds(std::ostringstream& o, double axis_top, double rows_end) const {
    for (std::size_t i = 0; i < l_.cols.size(); ++i) {
      if (!l_.cols[i].folded) continue;
      std::size_t n = l_.cols[i].last - l_.cols[i].first + 1;
      double a = l_.xs[i] + 8, b = l_.xs[i + 1] - 8;
      o << "<rect class=\"fold\" x=\"" << num(a) << "\" y=\"" << num(axis_top) << "\" width=\"" << num(b - a)
        << "\" height=\"" << num(rows_end - axis_top) << "\"><title>cycles "
        << l_.cols[i].first + 1 << "-" << l_.cols[i].last + 1 << " folded: " << n
        << " cycles without a change</title></rect>\n";
      o << "<text class=\"small\" text-anchor=\"middle\" x=\"" << num((a + b) / 2) << "\" y=\""
        << num(axis_top + 12) << "\">" << n << "</text>\n";
    }
  }

  void draw_marks(std::ostringstream& o, double axis_top, double rows_end) const {
    for (std::size_t c : l_.d.checks)
      for (std::size_t i = 0; i < l_.cols.size(); ++i)
        if (!l_.cols[i].folded && l_.cols[i].first <= c && c <= l_.cols[i].last) {
          double x = (l_.xs[i] + l_.xs[i + 1]) / 2;
          o << "<polygon class=\"check\" points=\"" << num(x - 4) << "," << num(axis_top) << " " << num(x + 4) << ","
            << num(axis_top) << " " << num(x) << "," << num(axis_top + 6) << "\"><title>cycle " << c + 1
            << ": expectations checked</title></polygon>\n";
        }
    for (const auto& mk : l_.d.marks)
      for (std::size_t i = 0; i < l_.cols.size(); ++i)
        if (l_.cols[i].first <= mk.cycle && mk.cycle <= l_.cols[i].last) {
          o << "<rect class=\"mark\" x=\"" << num(l_.xs[i]) << "\" y=\"" << num(axis_top) << "\" width=\""
            << num(l_.xs[i + 1] - l_.xs[i]) << "\" height=\"" << num(rows_end - axis_top) << "\"><title>"
            << html_escape(mk.label) << "</title></rect>\n";
          o << "<line class=\"markline\" x1=\"" << num(l_.xs[i + 1]) << "\" y1=\"" << num(axis_top - 4)
            << "\" x2=\"" << num(l_.xs[i + 1]) << "\" y2=\"" << num(rows_end) << "\"/>\n";
        }
  }

  // Cycle numbers above the rows, times below, at "nice" steps far enough apart.
  void draw_axes(std::ostringstream& o, double axis_top, double rows_end) const {
    static const std::size_t nice[] = {1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000};
    std::size_t step = 10000;
    for (std::size_t s : nice)
      if (double(s) * l_.cell_w >= 40) {
        step = s;
        break;
      }
    o << "<text class=\"sub small\" x=\"10\" y=\"" << num(axis_top - 4) << "\">cycle</text>\n";
    o << "<text class=\"sub small\" x=\"10\" y=\"" << num(rows_end + 16) << "\">time</text>\n";
    double last_x = -1e9;
    for (std::size_t i = 0; i < l_.cols.size(); ++i) {
      if (l_.cols[i].folded) continue;
      std::size_t c = l_.cols[i].first;
      bool after_fold = i > 0 && l_.cols[i - 1].folded;
      bool wanted = c == 0 || (c + 1) % step == 0 || after_fold || (step == 1);
      double x = (l_.xs[i] + l_.xs[i + 1]) / 2;
      if (!wanted || x - last_x < 40) continue;
      last_x = x;
      o << "<line class=\"grid\" x1=\"" << num(x) << "\" y1=\"" << num(axis_top) << "\" x2=\"" << num(x)
        << "\" y2=\"" << num(rows_end) << "\"/>\n";
      o << "<text class=\"small\" text-anchor=\"middle\" x=\"" << num(x) << "\" y=\"" << num(axis_top - 4)
        << "\">" << c + 1 << "</text>\n";
      o << "<text class=\"small\" text-anchor=\"middle\" x=\"" << num(x) << "\" y=\"" << num(rows_end + 16)
        << "\">" << html_escape(time_text(double(c) * l_.m.cycle_ms)) << "</text>\n";
    }
  }

  Layout l_;
};

}  // namespace

std::string timing_svg(const model::Matrix& m, const checker::ConcreteTrace& trace, const TimingDiagram& d) {
  return Drawing(m, timing::rows_of(m, trace, d), trace.inputs.size(), d).svg();
}

TimingRecorder::TimingRecorder(const model::Matrix& m, TimingDiagram d)
    : m_(m), d_(std::make_unique<TimingDiagram>(std::move(d))), rows_(std::make_unique<timing::RowBuilder>(m, *d_)) {}

TimingRecorder::~TimingRecorder() = default;

void TimingRecorder::add(const model::CycleInput& in, const std::vector<int>& snapshot) { rows_->add(in, snapshot); }

std::string TimingRecorder::svg() const { return Drawing(m_, rows_->rows(), rows_->cycles(), *d_).svg(); }

TimingDiagram diagram_of(const checker::PropertyResult& p) {
  TimingDiagram d;
  bool witness = p.verdict == checker::PropertyVerdict::Reachable;
  d.title = std::string(witness ? "Witness of " : "Counterexample to ") + p.name;
  if (!p.description.empty()) d.title += ": " + p.description;
  d.shown = p.matters;
  if (p.violation_cycle >= 0)
    d.marks.push_back({static_cast<std::size_t>(p.violation_cycle),
                       std::string(witness ? "reached: " : "violated: ") + p.name});
  d.notes = explanation_lines(p);  // "why, per step", under the picture
  return d;
}

}  // namespace cemv::reports
