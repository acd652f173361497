// The evidence report's sections on response time (docs/response-time.md) and
// on test generation (docs/testgen.md, docs/mutation.md): tables an assessor
// reads, not the JSON they come from. The full objective list stays in the
// suite's checklist; here: the figures, the objectives by kind, the tests and
// every objective or mutant that is not settled.
#include <cstdio>
#include <map>

#include "reports/evidence_document.hpp"
#include "reports/evidence_pages.hpp"
#include "reports/xml_text.hpp"

namespace cemv::reports::evidence_detail {

namespace {

std::string ms(const std::optional<long long>& v) { return v ? std::to_string(*v) + " ms" : "-"; }

std::string percent(double part, double whole) {
  if (whole <= 0) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f %%", 100.0 * part / whole);
  return buf;
}

const char* verdict_css(const std::string& v) {
  if (v == "ok" || v == "covered" || v == "detected" || v == "equivalent") return "ok";
  if (v == "over" || v == "unbounded" || v == "survived" || v == "infeasible") return "bad";
  if (v == "no-pst") return "warn";
  return "unk";
}

Cell cell(const std::string& text, const std::string& css = "") { return {html_escape(text), text, css, 0}; }
Cell number(long long v, const std::string& extra = "") {
  return cell(std::to_string(v), extra.empty() ? "num" : "num " + extra);
}

void coverage(Pages& pages, const CoverageFigures& c, const std::string& n) {
  pages.section("coverage", n + ".1", "Coverage");
  pages.paragraph_html("From <code>" + html_escape(c.file) +
                           "</code> (cemv-coverage/1; the same matrix signature). Each covered objective is reached "
                           "by a generated test that was replayed on the reference runtime; an infeasible one was "
                           "proved unreachable.",
                       "From " + c.file + " (cemv-coverage/1; the same matrix signature). Each covered objective is "
                                          "reached by a generated test that was replayed on the reference runtime; an "
                                          "infeasible one was proved unreachable.");
  Table t;
  t.widths_mm = {22, 22, 22, 22, 30, 22, 22, 22};
  t.head = {"Objectives", "Covered", "Infeasible", "Undecided", "Coverage of the feasible", "Tests", "Steps", "Cycles"};
  t.rows.push_back({number(c.objectives), number(c.covered), number(c.infeasible), number(c.undecided),
                    cell(percent(double(c.covered), double(c.objectives - c.infeasible)),
                         c.undecided ? "num warn" : "num ok"),
                    number(c.tests), number(c.steps), number(c.cycles)});
  pages.table(t);

  std::map<std::string, std::map<std::string, long long>> by_kind;  // kind -> status -> count
  for (const auto& ob : c.list) by_kind[ob.kind][ob.status]++, by_kind[ob.kind]["all"]++;
  pages.section("coverage-kinds", n + ".2", "Objectives by kind");
  Table k;
  k.widths_mm = {66, 30, 30, 30, 30};
  k.head = {"Kind", "Objectives", "Covered", "Infeasible", "Undecided"};
  for (const auto& [kind, counts] : by_kind) {
    auto get = [&counts = counts](const char* key) {
      auto it = counts.find(key);
      return it == counts.end() ? 0LL : it->second;
    };
    k.rows.push_back({cell(kind), number(get("all")), number(get("covered")), number(get("infeasible")),
                      number(get("undecided"), get("undecided") ? "warn" : "")});
  }
  pages.table(k);

  pages.section("coverage-tests", n + ".3", "Tests");
  Table tt;
  tt.widths_mm = {20, 96, 14, 16, 16, 24};
  tt.head = {"Test", "File", "SIF", "Steps", "Cycles", "Objectives covered"};
  tt.font_pt = 8;
  for (const auto& x : c.test_list)
    tt.rows.push_back({cell(x.id), cell(x.file), number(x.sif), number(x.steps), number(x.cycles),
                       number(static_cast<long long>(x.objectives))});
  pages.table(tt);

  std::size_t open = 0;
  for (const auto& ob : c.list) open += ob.status != "covered";
  if (open == 0) {
    pages.paragraph("Every objective is covered.", "ok");
    return;
  }
  pages.section("coverage-open", n + ".4", "Objectives not covered");
  Table o;
  o.widths_mm = {30, 30, 22, 74, 30};
  o.head = {"Objective", "Element", "Status", "What it asks", "Method"};
  o.font_pt = 8;
  for (const auto& ob : c.list)
    if (ob.status != "covered")
      o.rows.push_back({cell(ob.id), cell(ob.element), cell(ob.status, verdict_css(ob.status)), cell(ob.text),
                        cell(ob.method.empty() ? "-" : ob.method)});
  pages.table(o);
}

void mutation(Pages& pages, const MutationFigures& f, const std::string& n) {
  pages.section("mutation", n + ".5", "Mutation adequacy");
  pages.paragraph("From " + f.file + " (cemv-mutation-report/1): every single-point change of the matrix, and whether "
                  "the suite notices it. A mutant that survives is a change the tests would let through.");
  Table t;
  t.widths_mm = {26, 26, 26, 26, 26, 26, 30};
  t.head = {"Mutants", "Equivalent", "Detected", "Survived", "Undecided", "Refused edits", "Mutation score"};
  t.rows.push_back({number(f.mutants), number(f.equivalent), number(f.detected),
                    number(f.survived, f.survived ? "bad" : ""), number(f.undecided, f.undecided ? "warn" : ""),
                    number(f.refused), cell(percent(double(f.detected), double(f.mutants - f.equivalent)), "num")});
  pages.table(t);
  if (f.open.empty()) return;
  Table o;
  o.widths_mm = {30, 36, 96, 24};
  o.head = {"Mutant", "Element", "Change", "Status"};
  o.font_pt = 8;
  for (const auto& mu : f.open)
    o.rows.push_back({cell(mu.id), cell(mu.element), cell(mu.description), cell(mu.status, verdict_css(mu.status))});
  pages.table(o);
}

}  // namespace

void defeats_section(Pages& pages, const EvidenceInputs& in);

namespace {

void response_tables(Pages& pages, const model::Matrix& m, const EvidenceInputs& in) {
  if (!in.response) {
    pages.paragraph("Not analysed (cemv evidence --response adds the worst-case response time of every SIF path, as "
                    "cemv response computes it).",
                    "warn");
    return;
  }
  const auto& r = *in.response;
  if (r.paths.empty()) {
    pages.paragraph("The matrix declares no SIF group with a path from a cause to an effect.");
    return;
  }
  pages.paragraph("Logic response: the least number of cycles T proved for \"whenever the trigger rises and holds, "
                  "the response holds within T\", with T - 1 falsified by a counterexample replayed on the runtime. "
                  "Total = sensor + T x cycle (" + std::to_string(m.cycle_ms) + " ms) + controller's share (" +
                  r.controller + ") + actuator (docs/response-time.md). Sensor and actuator times are declared in the "
                  "matrix, not measured.");
  std::size_t i = 0;
  while (i < r.paths.size()) {
    const int sif = r.paths[i].sif;
    const auto& first = r.paths[i];
    pages.section("sif-" + std::to_string(sif), "",
                  "SIF " + std::to_string(sif) + " " + first.sif_name + ": process safety time " +
                      (first.process_safety_time_ms ? ms(first.process_safety_time_ms) : std::string("not declared")),
                  false);
    Table t;
    t.widths_mm = {52, 34, 22, 30, 20, 28};
    t.head = {"Path", "Logic", "Total", "Margin", "Verdict", "Degraded total"};
    for (; i < r.paths.size() && r.paths[i].sif == sif; ++i) {
      const auto& p = r.paths[i];
      std::string margin = ms(p.margin_ms);
      if (p.margin_percent) {
        char buf[32];
        std::snprintf(buf, sizeof buf, " (%.1f %%)", *p.margin_percent);
        margin += buf;
      }
      t.rows.push_back({cell(p.path), cell(p.logic), cell(ms(p.total_ms), "num"), cell(margin, "num"),
                        cell(p.verdict, verdict_css(p.verdict)), cell(ms(p.degraded_total_ms), "num")});
    }
    pages.table(t);
  }
}

}  // namespace

// The chapter: the response-time tables, then the defeat sets per SIF.
void response_section(Pages& pages, const model::Matrix& m, const EvidenceInputs& in, const std::string& n) {
  pages.chapter("response", n, "Response time and defeats of the safety functions");
  response_tables(pages, m, in);
  defeats_section(pages, in);
}

void defeats_section(Pages& pages, const EvidenceInputs& in) {
  if (!in.defeats) {
    pages.paragraph("Defeat sets not given (cemv evidence --defeats FILE adds the minimal sets of maintenance "
                    "operations and faults that defeat each path, the JSON of cemv defeats).",
                    "warn");
    return;
  }
  const auto& r = *in.defeats;
  pages.paragraph("Minimal defeat sets (" + r.file + ", up to " + std::to_string(r.max_size) +
                  " actions): the smallest sets of maintenance operations and input faults under which a path no "
                  "longer responds within its logic response T, each shown by a counterexample replayed on the "
                  "runtime and proved minimal by proofs of its subsets (docs/defeats.md). Declared: operations on "
                  "the path's own cause or effect; indirect: through another element or a fault. Distance: the "
                  "size of the smallest indirect set.");
  std::size_t i = 0;
  while (i < r.paths.size()) {
    const int sif = r.paths[i].sif;
    const auto& first = r.paths[i];
    pages.section("defeats-sif-" + std::to_string(sif), "",
                  "Defeats of SIF " + std::to_string(sif) + " " + first.sif_name +
                      (first.sil ? ", SIL " + std::to_string(first.sil) : std::string()),
                  false);
    Table t;
    t.widths_mm = {40, 16, 60, 18, 52};
    t.head = {"Path (T, distance)", "Class", "Set", "Counter-example", "Touches"};
    for (; i < r.paths.size() && r.paths[i].sif == sif; ++i) {
      const auto& p = r.paths[i];
      const std::string label = p.path + " (T " + p.requirement + ", distance " + p.distance +
                                (p.status == "complete" ? "" : ", " + p.status) + ")";
      if (p.sets.empty()) {
        t.rows.push_back({cell(label), cell("-"), cell("none up to " + std::to_string(r.max_size)), cell("-"),
                          cell("-")});
        continue;
      }
      for (std::size_t k = 0; k < p.sets.size(); ++k) {
        const auto& s = p.sets[k];
        std::string set, touches;
        for (const auto& a : s.actions) set += (set.empty() ? "" : "; ") + a;
        for (const auto& x : s.touches) touches += (touches.empty() ? "" : ", ") + x;
        t.rows.push_back({cell(k ? "" : label),
                          cell(s.set_class, s.set_class == "indirect" && s.actions.size() == 1 ? "bad" : ""),
                          cell(set), cell(s.counterexample.empty() ? "-" : s.counterexample), cell(touches)});
      }
    }
    pages.table(t);
  }
}

void tests_section(Pages& pages, const EvidenceInputs& in, const std::string& n) {
  pages.chapter("tests", n, "Test generation: coverage and mutation figures");
  if (!in.coverage)
    pages.paragraph("No test generation results given (cemv evidence --coverage DIR/coverage.json adds those of cemv "
                    "testgen).",
                    "warn");
  else
    coverage(pages, *in.coverage, n);
  if (!in.mutation)
    pages.paragraph("No mutation figures given (cemv evidence --mutation DIR/mutation-report.json adds those of cemv "
                    "testgen --mutation-report).",
                    "warn");
  else
    mutation(pages, *in.mutation, n);
}

}  // namespace cemv::reports::evidence_detail
