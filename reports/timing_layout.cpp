// The geometry of a timing diagram (timing_layout.hpp).
#include "reports/timing_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cemv::reports::timing {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  std::string s = buf;
  if (s.size() > 2 && s.compare(s.size() - 2, 2, ".0") == 0) s.resize(s.size() - 2);
  return s == "-0" ? "0" : s;
}

double text_width(const std::string& s, double size) { return s.size() * size * 0.6; }

std::vector<std::string> wrap(const std::string& s, double size, double width, double factor) {
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

double row_height(RowKind k) {
  switch (k) {
    case RowKind::Analog: return 96;
    case RowKind::Commands: return 40;
    default: return 30;
  }
}

Layout::Layout(const model::Matrix& m_, std::vector<Row> rows_, std::size_t cycles_, const TimingDiagram& d_)
    : m(m_), cycles(cycles_), d(d_), rows(std::move(rows_)), cols(columns_of(rows, cycles_, d_.marks)) {
  label_w = 150;
  for (const auto& r : rows) label_w = std::max(label_w, text_width(r.label) + 24);
  std::size_t single = 0;
  for (const auto& c : cols) single += !c.folded;
  cell_w = std::clamp(std::floor(960.0 / std::max<std::size_t>(single, 1)), 3.0, 28.0);
  double x = label_w;
  for (const auto& c : cols) {
    xs.push_back(x);
    x += c.folded ? kFoldWidth : cell_w;
  }
  xs.push_back(x);
  bool levels = false;
  for (const auto& r : rows) levels |= !r.levels.empty();
  // At least wide enough for a readable line of title and legend.
  width = std::max(x + (levels ? 190 : 24), 560.0);
}

}  // namespace cemv::reports::timing
