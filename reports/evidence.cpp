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
#include "reports/evidence_blocks.hpp"
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
using evidence_detail::text_cell;

class Writer {
 public:
  Writer(const model::Matrix& m, const EvidenceInputs& in) : m_(m), in_(in), d_(evidence_detail::build_document(m, in)) {}

  std::string html() {
    if (!d_.valid) {
      evidence_detail::validation_chapter(pages_, d_, "1");
      evidence_detail::grid_chapter(pages_, d_, "2");
      evidence_detail::provenance_chapter(pages_, d_, "3");
      limitations("4");
      conclusion("5");
    } else {
      evidence_detail::requirements_chapter(pages_, d_, "1");
      evidence_detail::standard_chapter(pages_, d_, "2");
      evidence_detail::grid_chapter(pages_, d_, "3");
      evidence_detail::validation_chapter(pages_, d_, "4");
      evidence_detail::provenance_chapter(pages_, d_, "5");
      evidence_detail::response_section(pages_, m_, in_, "6");
      evidence_detail::tests_section(pages_, in_, "7");
      int next = 8;
      if (in_.plc) evidence_detail::plc_chapter(pages_, *in_.plc, std::to_string(next++));
      limitations(std::to_string(next++));
      conclusion(std::to_string(next));
      evidence_detail::appendix_chapter(pages_, d_, "A");
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
