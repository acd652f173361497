// The evidence report's chapter on the PLC program (docs/plc.md "Evidence
// with the program"): which program, the map with its assumptions, the
// relation per output tag, and each difference explained scan by scan.
#include "reports/evidence_document.hpp"
#include "reports/evidence_pages.hpp"
#include "reports/xml_text.hpp"

namespace cemv::reports::evidence_detail {

namespace {

Cell cell(const std::string& text, const std::string& css = "") { return {html_escape(text), text, css, 0}; }

const char* verdict_css(const std::string& v) {
  if (v == "related") return "ok";
  if (v == "differs") return "bad";
  return "unk";
}

std::string verdict_text(const PlcFigures& p, const PlcFigures::Output& o) {
  if (o.verdict == "related") return p.relation == "equal" ? "proved equal" : "proved safe-side";
  if (o.verdict == "differs") return "differs in scan " + std::to_string(o.scan);
  return "unknown" + (o.reason.empty() ? std::string() : " (" + o.reason + ")");
}

void difference(Pages& pages, const PlcFigures::Output& o, const std::string& number) {
  pages.section("plc-diff-" + o.tag, number, "Difference on " + o.tag);
  std::string text = "In scan " + std::to_string(o.scan) + " the matrix writes " + o.tag + " = " +
                     std::to_string(o.matrix_value) + " and the program writes " + o.variable + " = " +
                     std::to_string(o.program_value) + ". ";
  text += o.assigned_at.empty() ? "No statement of the program set " + o.variable + " in that scan (it kept its value). "
                                : "The program's statement at " + o.assigned_at + " set it in that scan. ";
  text += "The run was replayed on the matrix's reference runtime and on the program's interpreter, and both show the "
          "difference; the table gives both outputs in every scan and the program inputs that changed.";
  pages.paragraph(text);
  Table t;
  t.widths_mm = {16, 22, 22, 126};
  t.head = {"Scan", "Matrix", "Program", "Program inputs changed"};
  t.font_pt = 8;
  // Scans in which nothing changes (no input, both outputs as before and
  // equal) are one row: a run waiting for a 2 s delay is 20 such scans.
  auto quiet = [&](std::size_t i) {
    const auto& s = o.scans[i];
    return i > 0 && s.inputs.empty() && s.matrix == s.program && s.matrix == o.scans[i - 1].matrix &&
           s.program == o.scans[i - 1].program;
  };
  for (std::size_t i = 0; i < o.scans.size();) {
    const auto& s = o.scans[i];
    std::size_t end = i + 1;
    if (quiet(i))
      while (end < o.scans.size() && quiet(end)) ++end;
    const std::string scans = end - i > 1 ? std::to_string(s.scan) + "-" + std::to_string(o.scans[end - 1].scan)
                                          : std::to_string(s.scan);
    t.rows.push_back({cell(scans, "num"), cell(std::to_string(s.matrix), "num"),
                      cell(std::to_string(s.program), s.matrix == s.program ? "num" : "num bad"),
                      cell(quiet(i) ? "(no change)" : s.inputs)});
    i = end;
  }
  pages.table(t);
}

}  // namespace

void plc_chapter(Pages& pages, const PlcFigures& p, const std::string& n) {
  pages.chapter("plc", n, "The PLC program");
  pages.paragraph("Program " + p.pou + " in " + p.file + ", SHA-256 " + p.sha256 + ". Relation checked: " + p.relation +
                  (p.relation == "equal" ? " (the program's output equals the matrix's in every scan)"
                                         : " (the program's output is safe whenever the matrix's is)") +
                  ", for every input sequence the map allows, scan time " + std::to_string(p.scan_ms) +
                  " ms. Map: " + p.map_source + ". Every difference was replayed on both the matrix's runtime and "
                  "the program's interpreter (docs/plc.md).");
  pages.section("plc-outputs", n + ".1", "Relation per output tag");
  Table t;
  t.widths_mm = {40, 16, 40, 50, 40};
  t.head = {"Output tag", "Effect", "Program variable", "Verdict", "Method"};
  for (const auto& o : p.outputs)
    t.rows.push_back({cell(o.tag), cell(std::to_string(o.effect), "num"), cell(o.variable),
                      cell(verdict_text(p, o), verdict_css(o.verdict)),
                      cell(o.method.empty() ? "-" : o.method + (o.k ? ", k = " + std::to_string(o.k) : ""))});
  pages.table(t);
  if (p.interrupted) pages.paragraph("The total time limit ended the check: the outputs it did not decide are unknown.");
  pages.section("plc-assumptions", n + ".2", "Assumptions");
  pages.paragraph(p.assumptions.empty() ? "None: every input, bad quality and command of the matrix is a program input."
                                        : "A proof holds for the input sequences these allow, and only for them:");
  for (const auto& a : p.assumptions) pages.paragraph("- " + a);
  pages.section("plc-map", n + ".3", "The map");
  Table m;
  m.widths_mm = {80, 50, 56};
  m.head = {"Matrix", "Program variable", "Note"};
  m.font_pt = 8;
  for (const auto& b : p.map) m.rows.push_back({cell(b.what), cell(b.variable.empty() ? "-" : b.variable), cell(b.note)});
  pages.table(m);
  int i = 4;
  for (const auto& o : p.outputs)
    if (o.verdict == "differs") difference(pages, o, n + "." + std::to_string(i++));
}

}  // namespace cemv::reports::evidence_detail
