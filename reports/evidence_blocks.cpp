// The blocks the evidence report's chapters are made of
// (reports/evidence_blocks.hpp).
#include "reports/evidence_blocks.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <regex>
#include <sstream>

#include "reports/check_report.hpp"
#include "reports/timing_svg.hpp"
#include "reports/xml_text.hpp"

namespace cemv::reports::evidence_detail {

using checker::PropertyResult;
using checker::PropertyVerdict;

namespace {

std::string base64(const std::string& s) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < s.size(); i += 3) {
    unsigned v = (unsigned char)s[i] << 16 | (unsigned char)s[i + 1] << 8 | (unsigned char)s[i + 2];
    out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], t[v & 63]};
  }
  if (i + 1 == s.size()) {
    unsigned v = (unsigned char)s[i] << 16;
    out += {t[v >> 18], t[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == s.size()) {
    unsigned v = (unsigned char)s[i] << 16 | (unsigned char)s[i + 1] << 8;
    out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], '='};
  }
  return out;
}

}  // namespace

const char* verdict_class(PropertyVerdict v) {
  switch (v) {
    case PropertyVerdict::Proved:
    case PropertyVerdict::Reachable: return "ok";
    case PropertyVerdict::Unknown: return "unk";
    default: return "bad";
  }
}

// A cell of text; line breaks in it are kept.
Cell text_cell(const std::string& text, const std::string& css, double pt) {
  std::string html = html_escape(text);
  for (std::size_t at = html.find('\n'); at != std::string::npos; at = html.find('\n', at))
    html.replace(at, 1, "<br>");
  return {html, text, css, pt};
}

// The timing diagram of a result without the explanation lines, which the
// report prints as a table beside it.
std::string report_diagram(const model::Matrix& m, const PropertyResult& p) {
  TimingDiagram d = diagram_of(p);
  d.notes.clear();
  return timing_svg(m, *p.trace, d);
}

std::string anchor(const std::string& name) {
  std::string s = "p-";
  for (char c : name) s += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return s;
}

// A key-value table of two columns.
Table pairs(const std::vector<std::pair<std::string, std::string>>& rows, double key_mm) {
  Table t;
  t.widths_mm = {key_mm, kPageWidthMm - key_mm};
  t.font_pt = 8.5;
  for (const auto& [k, v] : rows) t.rows.push_back({text_cell(k, "key"), text_cell(v)});
  return t;
}

// A timing diagram scaled to the page's width (and to at most 150 mm high),
// its size written out so that the layout knows it.
void diagram(Pages& pages, const std::string& svg, const std::string& alt) {
  double w = 600, h = 300;
  std::smatch mt;
  static const std::regex size(R"re(width="([0-9.]+)" height="([0-9.]+)")re");
  if (std::regex_search(svg, mt, size)) w = std::stod(mt[1].str()), h = std::stod(mt[2].str());
  double width_mm = w * 0.2646, height_mm = h * 0.2646;  // 96 px per inch
  const double scale = std::min({1.0, kPageWidthMm / width_mm, 150.0 / height_mm});
  width_mm *= scale;
  height_mm *= scale;
  char style[96];
  std::snprintf(style, sizeof style, "width:%.1fmm;height:%.1fmm", width_mm, height_mm);
  pages.block("<img class=\"diagram\" style=\"" + std::string(style) + "\" alt=\"" + html_escape(alt) +
                  "\" src=\"data:image/svg+xml;base64," + base64(svg) + "\">\n",
              height_mm + 3);
}

// A monospace text, split into blocks of whole lines so a long one can run
// over pages.
void preformatted(Pages& pages, const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  const double pt = 7.5;
  for (std::size_t i = 0; i < lines.size(); i += 40) {
    std::string chunk;
    int n = 0;
    for (std::size_t k = i; k < lines.size() && k < i + 40; ++k) {
      chunk += (chunk.empty() ? "" : "\n") + lines[k];
      n += lines_of(lines[k], kPageWidthMm - 4, pt);
    }
    pages.block("<pre>" + html_escape(chunk) + "</pre>\n", lines_height(n, pt) + 4);
  }
}

// "Why, per step" of a trace, captioned so that it names its property
// when it starts a page.
void why_table(Pages& pages, const PropertyResult& p) {
  if (p.explanation.empty()) return;
  pages.caption("Why, per step: " + p.name + " (the rules of docs/semantics.md the runtime applied)");
  Table why;
  why.widths_mm = {12, 44, 18, 112};
  why.head = {"Cycle", "Signal", "Change", "Why (docs/semantics.md)"};
  why.font_pt = 7.5;
  for (const auto& s : p.explanation)
    why.rows.push_back({text_cell(std::to_string(s.cycle), "num"), text_cell(s.signal),
                        text_cell((s.before.empty() ? "" : s.before + " → ") + s.after), text_cell(s.why)});
  pages.table(why);
}

}  // namespace cemv::reports::evidence_detail
