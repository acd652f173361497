// The evidence report's chapters on the matrix itself: the cause & effect
// grid with every description and footnote printed and the cells coloured by
// what rests on them, the validation findings (11.5), and where the matrix
// came from (the source sheet, its warnings, the defaults adopted, every
// value a parameters file set).
#include <algorithm>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "reports/evidence_document.hpp"
#include "reports/evidence_pages.hpp"
#include "reports/xml_text.hpp"

namespace cemv::reports::evidence_detail {

namespace {

Cell text_cell(const std::string& text, const std::string& css = "") { return {html_escape(text), text, css, 0}; }

// "(1)" marks of a note: "(1) Override ...; (2)" -> "1,2".
std::string footnote_marks(const std::string& note) {
  static const std::regex mark(R"(\((\d{1,3})\))");
  std::string out;
  for (std::sregex_iterator it(note.begin(), note.end(), mark), end; it != end; ++it)
    out += (out.empty() ? "" : ",") + (*it)[1].str();
  return out;
}

// The footnotes of the matrix: from the parameters (text, modelled or not),
// else from the intersection notes themselves.
struct Footnote {
  std::string mark, text, modelled;
};
std::vector<Footnote> footnotes(const model::Matrix& m) {
  std::map<int, Footnote> out;
  for (const auto& rec : m.provenance.parameters)
    for (const auto& f : rec.footnotes) {
      int n = std::atoi(f.mark.c_str() + 1);
      out[n] = {f.mark, f.text, f.modelled.empty() ? "not modelled: " + f.not_modelled : "modelled: " + f.modelled};
    }
  static const std::regex piece(R"(^\((\d{1,3})\)\s*(.*)$)");
  for (const auto& x : m.intersections) {
    std::size_t start = 0;
    while (start <= x.note.size()) {
      std::size_t end = x.note.find("; ", start);
      std::string p = x.note.substr(start, end == std::string::npos ? std::string::npos : end - start);
      std::smatch mt;
      if (std::regex_match(p, mt, piece)) {
        int n = std::stoi(mt[1].str());
        if (!out.count(n)) out[n] = {"(" + mt[1].str() + ")", mt[2].str(), ""};
      }
      if (end == std::string::npos) break;
      start = end + 2;
    }
  }
  std::vector<Footnote> list;
  for (auto& [n, f] : out) list.push_back(std::move(f));
  return list;
}

// The acceptance class of an element ("a-accepted"), "" without a record.
std::string acceptance_css(const Document& d, const std::string& key) {
  if (!d.in.acceptance) return "";
  for (const auto& e : d.in.acceptance->elements)
    if (e.key() == key) return std::string(" a-") + formats::to_string(e.status);
  return "";
}

void grid_part(Pages& pages, const Document& d, std::size_t first, std::size_t last) {
  const model::Matrix& m = d.m;
  const std::size_t n = last - first;
  const double cell_mm = 6.0, id_mm = 10.0;
  // The head is vertical text (its height fixed), so the grid is laid out
  // here, in row chunks that fit a sheet, each with the head.
  Table t;
  t.widths_mm = {id_mm, kPageWidthMm - id_mm - cell_mm * static_cast<double>(n)};
  t.head_height_mm = 27;
  for (std::size_t k = 0; k < n; ++k) t.widths_mm.push_back(cell_mm);
  // The elements an indirect defeat set of one action touches (docs/defeats.md).
  std::set<int> defeat_causes, defeat_effects;
  if (d.in.defeats)
    for (const auto& p : d.in.defeats->paths)
      for (const auto& st : p.sets)
        if (st.set_class == "indirect" && st.actions.size() == 1) {
          defeat_causes.insert(st.causes.begin(), st.causes.end());
          defeat_effects.insert(st.effects.begin(), st.effects.end());
        }
  std::ostringstream head;
  for (std::size_t k = first; k < last; ++k) {
    const auto& e = m.effects[k];
    head << "<th class=\"effect" << (e.function == model::EffectFunction::Comment ? " comment" : "")
         << (defeat_effects.count(e.id) ? " defeat1" : "") << acceptance_css(d, "effect[" + std::to_string(e.id) + "]")
         << "\"><div>E" << e.id << " " << html_escape(e.name) << (defeat_effects.count(e.id) ? " \u26A0" : "")
         << "</div></th>";
  }
  std::vector<std::vector<Cell>> rows;
  for (const auto& c : m.causes) {
    std::vector<Cell> row;
    const bool comment = c.function == model::CauseFunction::Comment;
    const bool defeat1 = defeat_causes.count(c.id) > 0;
    row.push_back({"C" + std::to_string(c.id) + (defeat1 ? " \u26A0" : ""), "C" + std::to_string(c.id),
                   std::string(comment ? "cause comment" : "cause") + (defeat1 ? " defeat1" : "") +
                       acceptance_css(d, "cause[" + std::to_string(c.id) + "]"),
                   0});
    std::string desc = c.name + (c.description.empty() ? "" : ": " + c.description);
    row.push_back({"<b>" + html_escape(c.name) + "</b>" + (c.description.empty() ? "" : " " + html_escape(c.description)),
                   desc, comment ? "cause comment" : "cause", 0});
    for (std::size_t k = first; k < last; ++k) {
      const auto& e = m.effects[k];
      const auto* x = m.find_intersection(c.id, e.id);
      if (!x) {
        row.push_back({"", "", "", 0});
        continue;
      }
      std::string type = model::to_string(x->type);
      std::string css = "t-" + (x->type == model::IntersectionType::Note ? std::string("Note") : type);
      if (d.in.acceptance) {
        const std::string a = acceptance_css(d, "intersection cause[" + std::to_string(c.id) + "]/effect[" +
                                                    std::to_string(e.id) + "]");
        if (!a.empty()) css = a.substr(1);
      }
      if (d.support_cells.count({c.id, e.id})) css += " support";
      if (d.trace_cells.count({c.id, e.id})) css += " traced";
      std::string marks = footnote_marks(x->note);
      std::string html = html_escape(type);
      if (x->xoon) html += "<sub>" + std::to_string(*x->xoon) + "</sub>";
      if (!marks.empty()) html += "<sup>" + marks + "</sup>";
      row.push_back({html, type, css, 0});
    }
    rows.push_back(std::move(row));
  }
  // Lay the rows out in chunks that fit, each with the vertical head.
  const double row_mm = 4.2;
  std::size_t i = 0;
  while (i < rows.size()) {
    std::ostringstream o;
    o << "<table class=\"fixed grid\"><colgroup>";
    for (double w : t.widths_mm) o << "<col style=\"width:" << w << "mm\">";
    o << "</colgroup>\n<thead><tr><th class=\"cause\">Cause</th><th class=\"cause\">Name and description</th>"
      << head.str() << "</tr></thead>\n<tbody>\n";
    double h = t.head_height_mm;
    const std::size_t start = i;
    for (; i < rows.size(); ++i) {
      int lines = lines_of(rows[i][1].text, t.widths_mm[1] - 1.2, 7.0);
      double rh = std::max(row_mm, lines * 7.0 * 0.3528 * 1.25 + 1.0);
      if (i > start && h + rh > kPageHeightMm - 30) break;
      h += rh;
      o << "<tr>";
      for (const auto& cell : rows[i])
        o << "<td" << (cell.css.empty() ? "" : " class=\"" + cell.css + "\"") << ">" << cell.html << "</td>";
      o << "</tr>\n";
    }
    o << "</tbody></table>\n";
    pages.block(o.str(), h + 2);
  }
}

}  // namespace

void grid_chapter(Pages& pages, const Document& d, const std::string& number) {
  const model::Matrix& m = d.m;
  pages.chapter("grid", number, "Cause & effect matrix");
  if (d.in.acceptance) {  // the cells take the acceptance colours: the letters alone give the type
    pages.paragraph("Cells: N normal, S stored, V overridable, R resettable and overridable, X not specified, * note "
                    "only; superscripts: footnotes; coloured by field acceptance (below). \u26A0 on a cause or effect: an "
                    "indirect defeat set of one action touches it (docs/defeats.md).",
                    "legend");
  } else {
    pages.paragraph_html(
        "<span class=\"legend\">Cells: <span class=\"t-N\">N normal</span><span class=\"t-S\">S stored</span>"
        "<span class=\"t-V\">V overridable</span><span class=\"t-R\">R resettable and overridable</span>"
        "<span class=\"t-X\">X not specified</span>* note only; superscripts: footnotes. Outlined: "
        "<span style=\"outline:0.6mm solid #15803d\">a proved requirement rests on it</span>"
        "<span style=\"outline:0.6mm solid #dc2626\">a counterexample or witness runs through it</span>. Grey: comment "
        "only. <span class=\"defeat1\">\u26A0</span> on a cause or effect: an indirect defeat set of one action "
        "touches it (docs/defeats.md).</span>",
        "Cells: N normal S stored V overridable R resettable and overridable X not specified * note only; "
        "superscripts: footnotes. Outlined: a proved requirement rests on it a counterexample or witness runs "
        "through it. Grey: comment only. \u26A0 on a cause or effect: an indirect defeat set of one action touches it.",
        "legend", 11);
  }
  if (d.in.acceptance) {
    const auto& a = *d.in.acceptance;
    int n[3] = {0, 0, 0};
    for (const auto& e : a.elements) n[static_cast<int>(e.status)]++;
    pages.paragraph_html(
        "<span class=\"legend\">Field acceptance (" + html_escape(d.in.acceptance_file) +
            ", docs/acceptance.md), colouring the cause numbers, the effect heads and the cells: "
            "<span class=\"a-accepted\">accepted " + std::to_string(n[0]) + "</span><span class=\"a-deviation\">deviation " +
            std::to_string(n[1]) + "</span><span class=\"a-not-tested\">not tested " + std::to_string(n[2]) +
            "</span></span>",
        "Field acceptance (" + d.in.acceptance_file + "): accepted " + std::to_string(n[0]) + ", deviation " +
            std::to_string(n[1]) + ", not tested " + std::to_string(n[2]),
        "legend", 8);
    for (const auto& e : a.elements)
      for (const auto& dev : e.deviations) pages.paragraph("Deviation, " + e.key() + ": " + dev, "bad");
  }
  if (m.causes.empty() || m.effects.empty()) {
    pages.paragraph("The matrix has no causes or no effects: no grid.");
    return;
  }
  const std::size_t per_part = 22;  // effects per grid (6 mm each)
  for (std::size_t first = 0; first < m.effects.size(); first += per_part)
    grid_part(pages, d, first, std::min(m.effects.size(), first + per_part));
  pages.section("grid-effects", number + ".1", "Effects", true);
  Table e;
  e.widths_mm = {14, 40, 132};
  e.head = {"Effect", "Name", "Description"};
  e.font_pt = 8;
  for (const auto& x : m.effects)
    e.rows.push_back({text_cell("E" + std::to_string(x.id)), text_cell(x.name), text_cell(x.description)});
  pages.table(e);
  const auto notes = footnotes(m);
  if (!notes.empty()) {
    pages.section("grid-footnotes", number + ".2", "Footnotes of the sheet", true);
    Table f;
    f.widths_mm = {12, 70, 104};
    f.head = {"Mark", "Text", "In the model"};
    f.font_pt = 8;
    for (const auto& n : notes) f.rows.push_back({text_cell(n.mark), text_cell(n.text), text_cell(n.modelled)});
    pages.table(f);
  }
  if (!m.tag_descriptions.empty()) {
    pages.section("grid-tags", number + ".3", "Tags described", true);
    Table t;
    t.widths_mm = {50, 136};
    t.head = {"Tag", "Description"};
    t.font_pt = 8;
    for (const auto& [tag, text] : m.tag_descriptions) t.rows.push_back({text_cell(tag), text_cell(text)});
    pages.table(t);
  }
}

void validation_chapter(Pages& pages, const Document& d, const std::string& number) {
  pages.chapter("validation", number, "Validation (11.5)");
  if (d.in.validation.empty()) {
    pages.paragraph("No findings: the matrix passes every validation rule (docs/validation.md).", "ok");
    return;
  }
  pages.paragraph(std::to_string(d.errors) + " errors, " + std::to_string(d.warnings) +
                  " warnings (docs/validation.md explains every rule).",
                  d.errors ? "bad" : "warn");
  Table t;
  t.widths_mm = {15, 44, 34, 16, 77};
  t.head = {"Severity", "Rule", "Element", "Section", "Finding"};
  t.font_pt = 7.5;
  for (const auto& v : d.in.validation) {
    t.rows.push_back({text_cell(model::to_string(v.severity)), text_cell(v.rule), text_cell(v.element),
                      text_cell(v.section), text_cell(v.message)});
    t.row_css.push_back(v.severity == model::Severity::Error ? "bad" : "warn");
  }
  pages.table(t);
}

void provenance_chapter(Pages& pages, const Document& d, const std::string& number) {
  const auto& prov = d.m.provenance;
  pages.chapter("provenance", number, "Provenance: source and parameters");
  if (prov.empty()) {
    pages.paragraph("The matrix records no import and no parameters file: it was written in cemv-matrix/1 (or in a "
                    "lossless layout) and every field is its author's.");
    return;
  }
  int k = 0;
  for (const auto& rec : prov.imports) {
    ++k;
    pages.section("source-" + std::to_string(k), number + "." + std::to_string(k), "Source " + rec.file);
    Table t;
    t.widths_mm = {40, 146};
    t.font_pt = 8;
    for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
             {"File", rec.file}, {"SHA-256", rec.sha256}, {"Read by", rec.reader + ", " + rec.encoding},
             {"How it was read", rec.summary}})
      t.rows.push_back({text_cell(key, "key"), text_cell(value)});
    pages.table(t);
    if (!rec.warnings.empty()) {
      pages.paragraph(std::to_string(rec.warnings.size()) + " import warnings, as the import printed them:", "", 8.5);
      Table w;
      w.widths_mm = {kPageWidthMm};
      w.font_pt = 7.5;
      for (const auto& x : rec.warnings) w.rows.push_back({text_cell(x)});
      pages.table(w);
    }
    if (!rec.defaults.empty()) {
      pages.paragraph(std::to_string(rec.defaults.size()) +
                          " defaults adopted: fields the sheet does not state (nor the parameters), at the format's "
                          "default:",
                      "", 8.5);
      Table w;
      w.widths_mm = {kPageWidthMm};
      w.font_pt = 7.5;
      for (const auto& x : rec.defaults) w.rows.push_back({text_cell(x)});
      pages.table(w);
    }
  }
  for (const auto& rec : prov.parameters) {
    ++k;
    pages.section("params-" + std::to_string(k), number + "." + std::to_string(k), "Parameters " + rec.file);
    pages.paragraph("SHA-256 " + rec.sha256 + (rec.origin.empty() ? "" : ". Origin: " + rec.origin), "", 8.5);
    Table t;
    t.widths_mm = {40, 34, 42, 70};
    t.head = {"Element", "Field", "Value (was)", "Origin"};
    t.font_pt = 7.5;
    for (const auto& v : rec.values)
      t.rows.push_back({text_cell(v.element), text_cell(v.field), text_cell(v.value + "\n(was " + v.previous + ")"),
                        text_cell(v.origin)});
    pages.table(t);
  }
}

}  // namespace cemv::reports::evidence_detail
