// The evidence report as printable HTML (docs/reports.md, "Evidence report"):
// the cover, the contents with page numbers, the user's requirements first
// with their formal text and source, the standard set per element, the grid,
// validation, provenance, response time and tests, limitations, the
// conclusion with the sign-off block, and the standard set in detail as an
// appendix. The pages are laid out here (evidence_pages.hpp), so that the
// contents can name the page of each chapter.
#include "reports/evidence.hpp"

#include <cstdio>
#include <ctime>
#include <map>
#include <regex>
#include <sstream>

#include "reports/check_report.hpp"
#include "reports/evidence_document.hpp"
#include "reports/evidence_pages.hpp"
#include "reports/evidence_style.hpp"
#include "reports/timing_svg.hpp"
#include "reports/xml_text.hpp"

namespace cemv::reports {

namespace {

using checker::PropertyResult;
using checker::PropertyVerdict;
using evidence_detail::Cell;
using evidence_detail::Document;
using evidence_detail::Pages;
using evidence_detail::Table;
using evidence_detail::passed;

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

const char* verdict_class(PropertyVerdict v) {
  switch (v) {
    case PropertyVerdict::Proved:
    case PropertyVerdict::Reachable: return "ok";
    case PropertyVerdict::Unknown: return "unk";
    default: return "bad";
  }
}

// A cell of text; line breaks in it are kept.
Cell text_cell(const std::string& text, const std::string& css = "", double pt = 0) {
  std::string html = html_escape(text);
  for (std::size_t at = html.find('\n'); at != std::string::npos; at = html.find('\n', at))
    html.replace(at, 1, "<br>");
  return {html, text, css, pt};
}

// A support element as a reader finds it in the grid: "intersection[21,1]"
// -> "C21 TMA_D_21 -> E1 TMA_A_1 (N)".
std::string support_text(const model::Matrix& m, const checker::SupportElement& s) {
  static const std::regex cell(R"(intersection\[(\d+),(\d+)\])");
  std::smatch mt;
  if (!std::regex_match(s.key, mt, cell)) return s.key + (s.description.empty() ? "" : " (" + s.description + ")");
  const int c = std::stoi(mt[1].str()), e = std::stoi(mt[2].str());
  const auto* cause = m.find_cause(c);
  const auto* effect = m.find_effect(e);
  const auto* x = m.find_intersection(c, e);
  return "C" + std::to_string(c) + (cause ? " " + cause->name : "") + " \u2192 E" + std::to_string(e) +
         (effect ? " " + effect->name : "") + (x ? std::string(" (") + model::to_string(x->type) + ")" : "");
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
Table pairs(const std::vector<std::pair<std::string, std::string>>& rows, double key_mm = 52) {
  Table t;
  t.widths_mm = {key_mm, evidence_detail::kPageWidthMm - key_mm};
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
  const double scale = std::min({1.0, evidence_detail::kPageWidthMm / width_mm, 150.0 / height_mm});
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
      n += evidence_detail::lines_of(lines[k], evidence_detail::kPageWidthMm - 4, pt);
    }
    pages.block("<pre>" + html_escape(chunk) + "</pre>\n", evidence_detail::lines_height(n, pt) + 4);
  }
}

class Writer {
 public:
  Writer(const model::Matrix& m, const EvidenceInputs& in) : m_(m), in_(in), d_(evidence_detail::build_document(m, in)) {}

  std::string html() {
    if (!d_.valid) {
      chapter_banner();
      evidence_detail::validation_chapter(pages_, d_, "1");
      evidence_detail::grid_chapter(pages_, d_, "2");
      evidence_detail::provenance_chapter(pages_, d_, "3");
      limitations("4");
      conclusion("5");
    } else {
      requirements("1");
      standard("2");
      evidence_detail::grid_chapter(pages_, d_, "3");
      evidence_detail::validation_chapter(pages_, d_, "4");
      evidence_detail::provenance_chapter(pages_, d_, "5");
      evidence_detail::response_section(pages_, m_, in_, "6");
      evidence_detail::tests_section(pages_, in_, "7");
      int next = 8;
      if (in_.plc) evidence_detail::plc_chapter(pages_, *in_.plc, std::to_string(next++));
      limitations(std::to_string(next++));
      conclusion(std::to_string(next));
      appendix("A");
    }
    return assemble();
  }

 private:
  std::string stamp() const {
    return "matrix " + m_.name + " · signature " + in_.check.matrix_signature + " · cemv " + in_.check.tool_version +
           " · " + in_.date;
  }

  // ---- the cover and the contents ------------------------------------------

  std::string cover() const {
    std::ostringstream o;
    o << "<section class=\"sheet cover\">\n";
    if (!d_.valid)
      o << "<p class=\"banner\">This matrix has " << d_.errors
        << " validation errors: it cannot be executed, so nothing was checked. The validation findings come "
           "first (chapter 1).</p>\n";
    o << "<h1>Evidence report</h1>\n<p class=\"subtitle\">" << html_escape(m_.name)
      << (m_.title.empty() ? "" : ": " + html_escape(m_.title)) << "</p>\n";
    std::vector<std::pair<std::string, std::string>> rows = {
        {"Matrix file", in_.matrix_file},
        {"Matrix signature (SHA-256 of the canonical form)", in_.check.matrix_signature},
        {"Size", std::to_string(m_.causes.size()) + " causes, " + std::to_string(m_.effects.size()) + " effects, " +
                     std::to_string(m_.intersections.size()) + " intersections; scan cycle " +
                     std::to_string(m_.cycle_ms) + " ms"},
        {"Validation (11.5)", std::to_string(d_.errors) + " errors, " + std::to_string(d_.warnings) + " warnings"}};
    for (const auto& rec : m_.provenance.imports)
      rows.push_back({"Source", rec.file + " (" + rec.reader + ", " + rec.encoding + ")\nSHA-256 " + rec.sha256 +
                                    "\n" + std::to_string(rec.warnings.size()) + " import warnings, " +
                                    std::to_string(rec.defaults.size()) + " defaults adopted (chapter Provenance)"});
    for (const auto& rec : m_.provenance.parameters)
      rows.push_back({"Parameters", rec.file + "\nSHA-256 " + rec.sha256 + "\n" + std::to_string(rec.values.size()) +
                                        " values set, " + std::to_string(rec.footnotes.size()) +
                                        " footnotes explained, " + std::to_string(rec.limitations.size()) +
                                        " limitations stated" + (rec.origin.empty() ? "" : "\nOrigin: " + rec.origin)});
    if (m_.provenance.imports.empty() && m_.provenance.parameters.empty())
      rows.push_back({"Source", "no import or parameters recorded in the matrix: it was written as cemv-matrix/1"});
    for (const auto& f : in_.property_files)
      rows.push_back({"Requirements", f.file + "\nSHA-256 " + f.sha256 + "\n" +
                                          (d_.valid ? std::to_string(f.properties) + " properties"
                                                    : std::string("not read: nothing is checked on a matrix with "
                                                                  "validation errors"))});
    if (in_.check.standard && d_.valid)
      rows.push_back({"Standard properties", "derived from the matrix (docs/properties.md)"});
    std::string verdicts;
    for (std::size_t v = 0; v < d_.counts.size(); ++v)
      if (d_.counts[v])
        verdicts += (verdicts.empty() ? "" : ", ") + std::to_string(d_.counts[v]) + " " +
                    verdict_name(static_cast<PropertyVerdict>(v));
    rows.push_back({"Properties", d_.valid ? std::to_string(in_.check.properties.size()) +
                                                 (verdicts.empty() ? "" : ": " + verdicts)
                                           : "not checked"});
    if (d_.valid) {
      std::string resp = "not analysed (cemv evidence --response)";
      if (in_.response) {
        std::map<std::string, int> n;
        for (const auto& p : in_.response->paths) n[p.verdict]++;
        resp = std::to_string(in_.response->paths.size()) + " paths";
        const char* sep = ": ";
        for (const auto& [v, k] : n) resp += sep + std::to_string(k) + " " + v, sep = ", ";
      }
      rows.push_back({"Response time", resp});
      if (in_.coverage)
        rows.push_back({"Test generation", std::to_string(in_.coverage->covered) + " of " +
                                               std::to_string(in_.coverage->objectives) + " objectives covered, " +
                                               std::to_string(in_.coverage->infeasible) + " infeasible, " +
                                               std::to_string(in_.coverage->undecided) + " undecided; " +
                                               std::to_string(in_.coverage->tests) + " tests"});
      if (in_.mutation)
        rows.push_back({"Mutation", std::to_string(in_.mutation->mutants) + " mutants: " +
                                        std::to_string(in_.mutation->detected) + " detected, " +
                                        std::to_string(in_.mutation->equivalent) + " equivalent, " +
                                        std::to_string(in_.mutation->survived) + " survived, " +
                                        std::to_string(in_.mutation->undecided) + " undecided"});
    }
    rows.push_back({"Tool", "cemv " + in_.check.tool_version});
    rows.push_back({"Date", in_.date});
    o << "<table class=\"fixed cover-table\"><colgroup><col style=\"width:52mm\"><col style=\"width:134mm\"></colgroup>\n";
    for (const auto& [k, v] : rows) {
      std::string value = html_escape(v);
      value = std::regex_replace(value, std::regex("\n"), "<br>");
      o << "<tr><th>" << html_escape(k) << "</th><td>" << value << "</td></tr>\n";
    }
    o << "</table>\n<h3>Conclusion</h3>\n";
    for (const auto& s : d_.conclusion) o << "<p>" << html_escape(s) << "</p>\n";
    o << "</section>\n";
    return o.str();
  }

  // The contents: every chapter and listed section with its printed page.
  std::vector<std::string> contents(int first_page) const {
    const auto& toc = pages_.toc();
    const int per_sheet = 46;
    std::vector<std::string> sheets;
    for (std::size_t i = 0; i < toc.size(); i += per_sheet) {
      std::ostringstream o;
      o << "<section class=\"sheet toc\">\n";
      if (i == 0) o << "<h2 id=\"contents\">Contents</h2>\n";
      o << "<table class=\"toc\">\n";
      for (std::size_t k = i; k < toc.size() && k < i + per_sheet; ++k) {
        const auto& e = toc[k];
        o << "<tr class=\"l" << e.level << "\"><td class=\"n\">" << html_escape(e.number) << "</td><td><a href=\"#"
          << e.id << "\">" << html_escape(e.title) << "</a></td><td class=\"pg\">" << first_page + e.sheet - 1
          << "</td></tr>\n";
      }
      o << "</table>\n</section>\n";
      sheets.push_back(o.str());
    }
    return sheets;
  }

  std::string assemble() const {
    const int toc_sheets = std::max<int>(1, static_cast<int>((pages_.toc().size() + 45) / 46));
    const int first = 2 + toc_sheets;  // the cover is page 1
    std::ostringstream o;
    o << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Evidence: "
      << html_escape(m_.name) << "</title>\n<style>" << evidence_detail::kEvidenceCss
      << evidence_detail::page_boxes(stamp()) << "</style>\n</head>\n<body>\n";
    o << "<div class=\"pagehead screen\">" << html_escape(stamp()) << "</div>\n";
    o << cover();
    for (const auto& s : contents(first)) o << s;
    for (const auto& s : pages_.sheets()) o << "<section class=\"sheet\">\n" << s << "</section>\n";
    o << "<div class=\"pagefoot screen\">" << html_escape(stamp()) << "</div>\n</body>\n</html>\n";
    return o.str();
  }

  void chapter_banner() {}

  // ---- 1. the user's requirements ------------------------------------------

  void requirements(const std::string& n) {
    pages_.chapter("requirements", n, "Requirements");
    if (d_.requirements.empty()) {
      pages_.paragraph(in_.property_files.empty() ? "No requirement file was given (cemv evidence MATRIX PROPS...)."
                                                  : "The requirement files hold no property.");
      return;
    }
    pages_.paragraph("Each requirement with its formal text as checked, its source (file, line and the SHA-256 "
                     "of the file, which ties the verdict to one version of the text), the verdict and how it was "
                     "reached, the cells its proof rests on, or its counterexample or witness explained step by "
                     "step. Every answer was checked independently: counterexamples and witnesses replayed on the "
                     "reference runtime and judged by the concrete evaluator, proofs re-checked by a fresh solver "
                     "(docs/checker.md).");
    Table overview;
    overview.widths_mm = {8, 70, 22, 26, 60};
    overview.head = {"", "Requirement", "Kind", "Verdict", "Method"};
    int k = 0;
    for (const auto& r : d_.requirements) {
      const auto& p = *r.result;
      overview.rows.push_back({text_cell(n + "." + std::to_string(++k)), text_cell(p.name), text_cell(p.kind),
                               text_cell(verdict_name(p.verdict), verdict_class(p.verdict)),
                               text_cell(p.method.empty() ? "-" : p.method)});
    }
    pages_.table(overview);
    k = 0;
    for (const auto& r : d_.requirements) requirement(r, n + "." + std::to_string(++k));
  }

  void requirement(const evidence_detail::Requirement& r, const std::string& number) {
    const auto& p = *r.result;
    pages_.section(anchor(p.name), number, p.name);
    if (!p.description.empty()) pages_.paragraph(p.description, "desc");
    if (r.text) preformatted(pages_, evidence_detail::formal_text(*r.text));
    std::vector<std::pair<std::string, std::string>> rows;
    rows.push_back({"Source", p.file + ":" + std::to_string(p.line) + ":" + std::to_string(p.column)});
    rows.push_back({"SHA-256 of the file", r.file_sha256.empty() ? "(not recorded)" : r.file_sha256});
    rows.push_back({"Verdict", outcome_text(p)});
    for (const auto& note : p.notes) rows.push_back({"Note", note});
    if (p.verdict == PropertyVerdict::Proved) {
      std::string support;
      for (const auto& s : p.support) support += (support.empty() ? "" : "\n") + support_text(m_, s);
      // Which mode found it (cemv check --support, docs/checker.md "Support").
      const bool core = in_.check.support_mode == checker::SupportMode::Core;
      rows.push_back({core ? "Rests on (support: the proof's unsat core, re-checked)"
                      : p.support_minimal ? "Rests on (minimal support)"
                                          : "Rests on (support)",
                      support.empty() ? "not computed for this proof (docs/checker.md, \"Support\")" : support});
    }
    Table t = pairs(rows);
    t.rows[2][1].css = verdict_class(p.verdict);
    pages_.table(t);
    if (!p.trace) return;
    const bool witness = p.verdict == PropertyVerdict::Reachable;
    pages_.paragraph(std::string(witness ? "Witness" : "Counterexample") + ": " + std::to_string(p.trace->inputs.size()) +
                         (p.trace->inputs.size() == 1 ? " cycle" : " cycles") + " of " + std::to_string(m_.cycle_ms) +
                         " ms" + (p.scenario_file.empty() ? "" : "; scenario " + p.scenario_file) +
                         ". Timing diagram (rows named cause/effect NUMBER NAME field):",
                     "", 8.5);
    diagram(pages_, report_diagram(m_, p), "timing diagram of " + p.name);
    why_table(p);
  }

  // "Why, per step" of a trace, captioned so that it names its property
  // when it starts a page.
  void why_table(const PropertyResult& p) {
    if (p.explanation.empty()) return;
    pages_.caption("Why, per step: " + p.name + " (the rules of docs/semantics.md the runtime applied)");
    Table why;
    why.widths_mm = {12, 44, 18, 112};
    why.head = {"Cycle", "Signal", "Change", "Why (docs/semantics.md)"};
    why.font_pt = 7.5;
    for (const auto& s : p.explanation)
      why.rows.push_back({text_cell(std::to_string(s.cycle), "num"), text_cell(s.signal),
                          text_cell((s.before.empty() ? "" : s.before + " → ") + s.after), text_cell(s.why)});
    pages_.table(why);
  }

  // ---- 2. the standard set -------------------------------------------------

  void standard(const std::string& n) {
    pages_.chapter("standard", n, "Standard properties");
    if (d_.standard.empty()) {
      pages_.paragraph("The standard property set was not checked (cemv evidence --standard adds it).");
      return;
    }
    pages_.paragraph("The standard set restates rules of docs/semantics.md over the matrix's own wiring (every "
                     "intersection trips its effect, every effect can trip, stored effects can be reset, failed "
                     "sensors trip: docs/properties.md). " + std::to_string(d_.standard.size()) +
                     " properties, summarised per element; each is listed in Appendix A.");
    Table t;
    t.widths_mm = {66, 20, 20, 20, 20, 20, 20};
    t.head = {"Element", "Properties", "Proved", "Reachable", "Falsified", "Unreach./vacuous", "Unknown"};
    for (const auto& e : d_.standard_by_element) {
      const auto& v = e.verdicts;
      int total = 0;
      for (int x : v) total += x;
      const int bad = v[1] + v[3] + v[4];
      t.rows.push_back({text_cell(e.label), text_cell(std::to_string(total), "num"),
                        text_cell(std::to_string(v[0]), "num"), text_cell(std::to_string(v[2]), "num"),
                        text_cell(std::to_string(v[1]), v[1] ? "num bad" : "num"),
                        text_cell(std::to_string(v[3] + v[4]), v[3] + v[4] ? "num bad" : "num"),
                        text_cell(std::to_string(v[5]), v[5] ? "num unk" : "num")});
      t.row_css.push_back(bad ? "bad" : "");
    }
    pages_.table(t);
  }

  // ---- limitations, conclusion, appendix ------------------------------------

  void limitations(const std::string& n) {
    pages_.chapter("limitations", n, "Limitations");
    pages_.paragraph("What the source states that the model does not express, what the model assumes without the "
                     "source saying it (values supplied by the parameters, defaults the import adopted) and the "
                     "operations the requirements assume away. Every verdict holds only within these.");
    if (d_.limitations.empty()) {
      pages_.paragraph("None recorded.", "ok");
      return;
    }
    Table t;
    t.widths_mm = {30, 124, 32};
    t.head = {"Kind", "Limitation", "Source"};
    t.font_pt = 8;
    for (const auto& l : d_.limitations) t.rows.push_back({text_cell(l.kind), text_cell(l.text), text_cell(l.source)});
    pages_.table(t);
  }

  void conclusion(const std::string& n) {
    pages_.chapter("conclusion", n, "Conclusion and sign-off");
    for (const auto& s : d_.conclusion) pages_.paragraph(s);
    if (d_.valid && !d_.requirements.empty()) {
      Table t;
      t.widths_mm = {56, 20, 20, 20, 20, 25, 25};
      t.head = {"Properties", "Total", "Proved", "Reachable", "Falsified", "Unreach./vacuous", "Unknown"};
      auto row = [&](const std::string& what, const std::array<int, 6>& v) {
        int total = 0;
        for (int x : v) total += x;
        t.rows.push_back({text_cell(what), text_cell(std::to_string(total), "num"), text_cell(std::to_string(v[0]), "num"),
                          text_cell(std::to_string(v[2]), "num"), text_cell(std::to_string(v[1]), v[1] ? "num bad" : "num"),
                          text_cell(std::to_string(v[3] + v[4]), v[3] + v[4] ? "num bad" : "num"),
                          text_cell(std::to_string(v[5]), v[5] ? "num unk" : "num")});
      };
      row("Requirements", d_.requirement_counts);
      std::array<int, 6> standard{};
      for (const auto* p : d_.standard) standard[static_cast<int>(p->verdict)]++;
      if (!d_.standard.empty()) row("Standard set", standard);
      pages_.table(t);
    }
    pages_.section("signoff", "", "Assessment and sign-off", false);
    pages_.paragraph("The assessor records the conclusion of the functional safety assessment (IEC 61508-1, "
                     "clause 8) for the matrix version named by the signature above.");
    Table s;
    s.widths_mm = {52, 134};
    s.font_pt = 9;
    for (const char* k : {"Assessor's name", "Role / organisation", "Date", "Conclusion (accepted / accepted with "
                                                                            "conditions / not accepted)",
                          "Conditions, remarks", "Signature"})
      s.rows.push_back({text_cell(k, "key"), {"&nbsp;", "x\nx", "signfield", 0}});
    pages_.table(s);
  }

  void appendix(const std::string& n) {
    if (d_.standard.empty()) return;
    pages_.chapter("appendix-standard", n, "Appendix: the standard properties");
    pages_.paragraph("Every property of the standard set with its formal text and verdict, element by element "
                     "(docs/properties.md, \"Standard properties\").");
    std::map<std::pair<std::string, std::string>, const PropertyText*> texts;
    for (const auto& t : in_.texts) texts[{t.file, t.name}] = &t;
    Table t;
    t.widths_mm = {28, 36, 86, 18, 18};
    t.head = {"Element", "Property", "Formal text", "Verdict", "Method"};
    t.font_pt = 7;
    for (const auto& e : d_.standard_by_element)
      for (const auto* p : e.properties) {
        auto it = texts.find({p->file, p->name});
        std::string formal = it == texts.end() ? "" : evidence_detail::formal_text(*it->second);
        t.rows.push_back({text_cell(e.label), text_cell(p->name), text_cell(formal, "mono"),
                          text_cell(verdict_name(p->verdict), verdict_class(p->verdict)),
                          text_cell(p->method.empty() ? p->reason : p->method)});
      }
    pages_.table(t);
    // The counterexamples of the standard set in full; its witnesses (a
    // reachable effect, a resettable latch) are the table's "reachable".
    for (const auto& e : d_.standard_by_element)
      for (const auto* p : e.properties)
        if (p->trace && !passed(p->verdict)) {
          pages_.section("std-" + anchor(p->name), "", p->name, false);
          pages_.paragraph(outcome_text(*p), "bad", 8.5);
          diagram(pages_, report_diagram(m_, *p), "timing diagram of " + p->name);
          why_table(*p);
        }
  }

  const model::Matrix& m_;
  const EvidenceInputs& in_;
  Document d_;
  Pages pages_;
};

}  // namespace

std::string utc_date(long long epoch_seconds) {
  std::time_t t = static_cast<std::time_t>(epoch_seconds);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[40];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", &tm);
  return buf;
}

std::string evidence_html(const model::Matrix& m, const EvidenceInputs& in) { return Writer(m, in).html(); }

}  // namespace cemv::reports
