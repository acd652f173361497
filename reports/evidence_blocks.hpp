// The blocks the evidence report's chapters are made of: cells, key-value
// tables, timing diagrams scaled to the page, monospace text, the table that
// explains a trace step by step. Internal to reports/evidence*.cpp.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "checker/result.hpp"
#include "model/matrix.hpp"
#include "reports/evidence_pages.hpp"

namespace cemv::reports::evidence_detail {

// A cell of text, escaped; line breaks in it are kept.
Cell text_cell(const std::string& text, const std::string& css = "", double pt = 0);

// A key-value table of two columns.
Table pairs(const std::vector<std::pair<std::string, std::string>>& rows, double key_mm = 52);

// A timing diagram scaled to the page's width (and to at most 150 mm high),
// its size written out so that the layout knows it.
void diagram(Pages& pages, const std::string& svg, const std::string& alt);

// A monospace text, split into blocks of whole lines so a long one can run
// over pages.
void preformatted(Pages& pages, const std::string& text);

// The css class of a verdict: ok, bad or unk.
const char* verdict_class(checker::PropertyVerdict v);

// The anchor of a property's section.
std::string anchor(const std::string& name);

// The timing diagram of a result without the explanation lines, which the
// report prints as a table beside it.
std::string report_diagram(const model::Matrix& m, const checker::PropertyResult& p);

// "Why, per step" of a trace, captioned so that it names its property when
// it starts a page.
void why_table(Pages& pages, const checker::PropertyResult& p);

}  // namespace cemv::reports::evidence_detail
