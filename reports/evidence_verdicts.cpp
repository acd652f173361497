// The chapters of the evidence report on verdicts: the user's requirements,
// the standard set per element, and the appendix listing the standard set
// property by property with its counterexamples.
#include <map>
#include <regex>

#include "reports/check_report.hpp"
#include "reports/evidence_blocks.hpp"
#include "reports/evidence_document.hpp"

namespace cemv::reports::evidence_detail {

using checker::PropertyResult;
using checker::PropertyVerdict;

namespace {

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

void requirement(Pages& pages, const Document& d, const Requirement& r, const std::string& number) {
  const auto& p = *r.result;
  pages.section(anchor(p.name), number, p.name);
  if (!p.description.empty()) pages.paragraph(p.description, "desc");
  if (r.text) preformatted(pages, formal_text(*r.text));
  std::vector<std::pair<std::string, std::string>> rows;
  rows.push_back({"Source", p.file + ":" + std::to_string(p.line) + ":" + std::to_string(p.column)});
  rows.push_back({"SHA-256 of the file", r.file_sha256.empty() ? "(not recorded)" : r.file_sha256});
  rows.push_back({"Verdict", outcome_text(p)});
  for (const auto& note : p.notes) rows.push_back({"Note", note});
  if (p.verdict == PropertyVerdict::Proved) {
    std::string support;
    for (const auto& s : p.support) support += (support.empty() ? "" : "\n") + support_text(d.m, s);
    // Which mode found it (cemv check --support, docs/checker.md "Support").
    const bool core = d.in.check.support_mode == checker::SupportMode::Core;
    rows.push_back({core ? "Rests on (support: the proof's unsat core, re-checked)"
                    : p.support_minimal ? "Rests on (minimal support)"
                                        : "Rests on (support)",
                    support.empty() ? "not computed for this proof (docs/checker.md, \"Support\")" : support});
  }
  Table t = pairs(rows);
  t.rows[2][1].css = verdict_class(p.verdict);
  pages.table(t);
  if (!p.trace) return;
  const bool witness = p.verdict == PropertyVerdict::Reachable;
  pages.paragraph(std::string(witness ? "Witness" : "Counterexample") + ": " + std::to_string(p.trace->inputs.size()) +
                       (p.trace->inputs.size() == 1 ? " cycle" : " cycles") + " of " + std::to_string(d.m.cycle_ms) +
                       " ms" + (p.scenario_file.empty() ? "" : "; scenario " + p.scenario_file) +
                       ". Timing diagram (rows named cause/effect NUMBER NAME field):",
                   "", 8.5);
  diagram(pages, report_diagram(d.m, p), "timing diagram of " + p.name);
  why_table(pages, p);
}

}  // namespace

// ---- 1. the user's requirements ------------------------------------------

void requirements_chapter(Pages& pages, const Document& d, const std::string& n) {
  pages.chapter("requirements", n, "Requirements");
  if (d.requirements.empty()) {
    pages.paragraph(d.in.property_files.empty() ? "No requirement file was given (cemv evidence MATRIX PROPS...)."
                                                : "The requirement files hold no property.");
    return;
  }
  pages.paragraph("Each requirement with its formal text as checked, its source (file, line and the SHA-256 "
                   "of the file, which ties the verdict to one version of the text), the verdict and how it was "
                   "reached, the cells its proof rests on, or its counterexample or witness explained step by "
                   "step. Every answer was checked independently: counterexamples and witnesses replayed on the "
                   "reference runtime and judged by the concrete evaluator, proofs re-checked by a fresh solver "
                   "(docs/checker.md).");
  Table overview;
  overview.widths_mm = {8, 70, 22, 26, 60};
  overview.head = {"", "Requirement", "Kind", "Verdict", "Method"};
  int k = 0;
  for (const auto& r : d.requirements) {
    const auto& p = *r.result;
    overview.rows.push_back({text_cell(n + "." + std::to_string(++k)), text_cell(p.name), text_cell(p.kind),
                             text_cell(verdict_name(p.verdict), verdict_class(p.verdict)),
                             text_cell(p.method.empty() ? "-" : p.method)});
  }
  pages.table(overview);
  k = 0;
  for (const auto& r : d.requirements) requirement(pages, d, r, n + "." + std::to_string(++k));
}

// ---- 2. the standard set -------------------------------------------------

void standard_chapter(Pages& pages, const Document& d, const std::string& n) {
  pages.chapter("standard", n, "Standard properties");
  if (d.standard.empty()) {
    pages.paragraph("The standard property set was not checked (cemv evidence --standard adds it).");
    return;
  }
  pages.paragraph("The standard set restates rules of docs/semantics.md over the matrix's own wiring (every "
                   "intersection trips its effect, every effect can trip, stored effects can be reset, failed "
                   "sensors trip: docs/properties.md). " + std::to_string(d.standard.size()) +
                   " properties, summarised per element; each is listed in Appendix A.");
  Table t;
  t.widths_mm = {66, 20, 20, 20, 20, 20, 20};
  t.head = {"Element", "Properties", "Proved", "Reachable", "Falsified", "Unreach./vacuous", "Unknown"};
  for (const auto& e : d.standard_by_element) {
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
  pages.table(t);
}

void appendix_chapter(Pages& pages, const Document& d, const std::string& n) {
  if (d.standard.empty()) return;
  pages.chapter("appendix-standard", n, "Appendix: the standard properties");
  pages.paragraph("Every property of the standard set with its formal text and verdict, element by element "
                   "(docs/properties.md, \"Standard properties\").");
  std::map<std::pair<std::string, std::string>, const PropertyText*> texts;
  for (const auto& t : d.in.texts) texts[{t.file, t.name}] = &t;
  Table t;
  t.widths_mm = {28, 36, 86, 18, 18};
  t.head = {"Element", "Property", "Formal text", "Verdict", "Method"};
  t.font_pt = 7;
  for (const auto& e : d.standard_by_element)
    for (const auto* p : e.properties) {
      auto it = texts.find({p->file, p->name});
      std::string formal = it == texts.end() ? "" : formal_text(*it->second);
      t.rows.push_back({text_cell(e.label), text_cell(p->name), text_cell(formal, "mono"),
                        text_cell(verdict_name(p->verdict), verdict_class(p->verdict)),
                        text_cell(p->method.empty() ? p->reason : p->method)});
    }
  pages.table(t);
  // The counterexamples of the standard set in full; its witnesses (a
  // reachable effect, a resettable latch) are the table's "reachable".
  for (const auto& e : d.standard_by_element)
    for (const auto* p : e.properties)
      if (p->trace && !passed(p->verdict)) {
        pages.section("std-" + anchor(p->name), "", p->name, false);
        pages.paragraph(outcome_text(*p), "bad", 8.5);
        diagram(pages, report_diagram(d.m, *p), "timing diagram of " + p->name);
        why_table(pages, *p);
      }
}

}  // namespace cemv::reports::evidence_detail
