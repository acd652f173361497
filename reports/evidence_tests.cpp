// The evidence report's sections on response time (docs/response-time.md) and
// on test generation (docs/testgen.md, docs/mutation.md): tables an assessor
// reads, not the JSON they come from. The full objective list stays in the
// suite's checklist; here: the figures, the objectives by kind, the tests and
// every objective or mutant that is not settled.
#include <cstdio>
#include <map>
#include <ostream>

#include "reports/evidence.hpp"
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

void cell(std::ostream& o, const std::string& text, const char* cls = nullptr) {
  o << "<td" << (cls ? std::string(" class=\"") + cls + "\"" : "") << ">" << html_escape(text) << "</td>";
}

void coverage(std::ostream& o, const CoverageFigures& c) {
  o << "<h3>Coverage</h3>\n<p>From <code>" << html_escape(c.file) << "</code> (cemv-coverage/1; the same matrix "
    << "signature). Each covered objective is reached by a generated test that was replayed on the reference "
       "runtime; an infeasible one was proved unreachable.</p>\n";
  o << "<table>\n<tr><th>Objectives</th><th>Covered</th><th>Infeasible</th><th>Undecided</th><th>Coverage of the "
       "feasible</th><th>Tests</th><th>Steps</th><th>Cycles</th></tr>\n<tr>";
  for (long long v : {c.objectives, c.covered, c.infeasible, c.undecided}) o << "<td class=\"num\">" << v << "</td>";
  o << "<td class=\"num " << (c.undecided ? "warn" : "ok") << "\">"
    << percent(double(c.covered), double(c.objectives - c.infeasible)) << "</td>";
  for (long long v : {c.tests, c.steps, c.cycles}) o << "<td class=\"num\">" << v << "</td>";
  o << "</tr>\n</table>\n";

  std::map<std::string, std::map<std::string, long long>> by_kind;  // kind -> status -> count
  for (const auto& ob : c.list) by_kind[ob.kind][ob.status]++, by_kind[ob.kind]["all"]++;
  o << "<h3>Objectives by kind</h3>\n<table>\n<thead><tr><th>Kind</th><th>Objectives</th><th>Covered</th>"
       "<th>Infeasible</th><th>Undecided</th></tr></thead>\n";
  for (const auto& [kind, n] : by_kind) {
    auto get = [&n = n](const char* k) { auto it = n.find(k); return it == n.end() ? 0LL : it->second; };
    o << "<tr>";
    cell(o, kind);
    o << "<td class=\"num\">" << get("all") << "</td><td class=\"num\">" << get("covered")
      << "</td><td class=\"num\">" << get("infeasible") << "</td><td class=\"num" << (get("undecided") ? " warn" : "")
      << "\">" << get("undecided") << "</td></tr>\n";
  }
  o << "</table>\n";

  o << "<h3>Tests</h3>\n<table>\n<thead><tr><th>Test</th><th>File</th><th>SIF</th><th>Steps</th><th>Cycles</th>"
       "<th>Objectives covered</th></tr></thead>\n";
  for (const auto& t : c.test_list) {
    o << "<tr>";
    cell(o, t.id);
    cell(o, t.file);
    o << "<td class=\"num\">" << t.sif << "</td><td class=\"num\">" << t.steps << "</td><td class=\"num\">" << t.cycles
      << "</td><td class=\"num\">" << t.objectives << "</td></tr>\n";
  }
  o << "</table>\n";

  std::size_t open = 0;
  for (const auto& ob : c.list) open += ob.status != "covered";
  if (open == 0) {
    o << "<p class=\"ok\">Every objective is covered.</p>\n";
    return;
  }
  o << "<h3>Objectives not covered</h3>\n<table>\n<thead><tr><th>Objective</th><th>Element</th><th>Status</th>"
       "<th>What it asks</th><th>Method</th></tr></thead>\n";
  for (const auto& ob : c.list) {
    if (ob.status == "covered") continue;
    o << "<tr>";
    cell(o, ob.id);
    cell(o, ob.element);
    cell(o, ob.status, verdict_css(ob.status));
    cell(o, ob.text);
    cell(o, ob.method.empty() ? "-" : ob.method);
    o << "</tr>\n";
  }
  o << "</table>\n";
}

void mutation(std::ostream& o, const MutationFigures& f) {
  o << "<h3>Mutation adequacy</h3>\n<p>From <code>" << html_escape(f.file) << "</code> (cemv-mutation-report/1): "
    << "every single-point change of the matrix, and whether the suite notices it. A mutant that survives is a "
       "change the tests would let through.</p>\n";
  o << "<table>\n<tr><th>Mutants</th><th>Equivalent</th><th>Detected</th><th>Survived</th><th>Undecided</th>"
       "<th>Refused edits</th><th>Mutation score</th></tr>\n<tr>";
  for (long long v : {f.mutants, f.equivalent, f.detected}) o << "<td class=\"num\">" << v << "</td>";
  o << "<td class=\"num" << (f.survived ? " bad" : "") << "\">" << f.survived << "</td><td class=\"num"
    << (f.undecided ? " warn" : "") << "\">" << f.undecided << "</td><td class=\"num\">" << f.refused << "</td>";
  o << "<td class=\"num\">" << percent(double(f.detected), double(f.mutants - f.equivalent)) << "</td></tr>\n</table>\n";
  if (f.open.empty()) return;
  o << "<table>\n<thead><tr><th>Mutant</th><th>Element</th><th>Change</th><th>Status</th></tr></thead>\n";
  for (const auto& mu : f.open) {
    o << "<tr>";
    cell(o, mu.id);
    cell(o, mu.element);
    cell(o, mu.description);
    cell(o, mu.status, verdict_css(mu.status));
    o << "</tr>\n";
  }
  o << "</table>\n";
}

}  // namespace

void response_section(std::ostream& o, const model::Matrix& m, const EvidenceInputs& in) {
  o << "<section class=\"page\">\n<h2>4. Response time of the safety functions</h2>\n";
  if (!in.response) {
    o << "<p class=\"warn\">Not analysed (<code>cemv evidence --response</code> adds the worst-case response "
         "time of every SIF path, as <code>cemv response</code> computes it).</p>\n</section>\n";
    return;
  }
  const auto& r = *in.response;
  if (r.paths.empty()) {
    o << "<p>The matrix declares no SIF group with a path from a cause to an effect.</p>\n</section>\n";
    return;
  }
  o << "<p>Logic response: the least number of cycles T proved for \"whenever the trigger rises and holds, the "
       "response holds within T\", with T - 1 falsified by a counterexample replayed on the runtime. Total = "
       "sensor + T x cycle (" << m.cycle_ms << " ms) + controller's share (" << html_escape(r.controller)
    << ") + actuator (docs/response-time.md). Sensor and actuator times are declared in the matrix, not "
       "measured.</p>\n";
  int sif = -1;
  for (const auto& p : r.paths) {
    if (p.sif != sif) {
      if (sif != -1) o << "</table>\n";
      sif = p.sif;
      o << "<h3>SIF " << p.sif << " " << html_escape(p.sif_name) << ": process safety time "
        << (p.process_safety_time_ms ? html_escape(ms(p.process_safety_time_ms)) : "not declared")
        << "</h3>\n<table>\n<thead><tr><th>Path</th><th>Logic</th><th>Total</th><th>Margin</th><th>Verdict</th>"
           "<th>Degraded total</th></tr></thead>\n";
    }
    std::string margin = ms(p.margin_ms);
    if (p.margin_percent) {
      char buf[32];
      std::snprintf(buf, sizeof buf, " (%.1f %%)", *p.margin_percent);
      margin += buf;
    }
    o << "<tr>";
    cell(o, p.path);
    cell(o, p.logic);
    o << "<td class=\"num\">" << html_escape(ms(p.total_ms)) << "</td><td class=\"num\">" << html_escape(margin)
      << "</td>";
    cell(o, p.verdict, verdict_css(p.verdict));
    o << "<td class=\"num\">" << html_escape(ms(p.degraded_total_ms)) << "</td></tr>\n";
  }
  o << "</table>\n</section>\n";
}

void tests_section(std::ostream& o, const EvidenceInputs& in) {
  o << "<section class=\"page\">\n<h2>5. Test generation: coverage and mutation figures</h2>\n";
  if (!in.coverage)
    o << "<p class=\"warn\">No test generation results given (<code>cemv evidence --coverage "
         "DIR/coverage.json</code> adds those of <code>cemv testgen</code>).</p>\n";
  else
    coverage(o, *in.coverage);
  if (!in.mutation)
    o << "<p class=\"warn\">No mutation figures given (<code>cemv evidence --mutation "
         "DIR/mutation-report.json</code> adds those of <code>cemv testgen --mutation-report</code>).</p>\n";
  else
    mutation(o, *in.mutation);
  o << "</section>\n";
}

}  // namespace cemv::reports::evidence_detail
