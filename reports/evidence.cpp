#include "reports/evidence.hpp"

#include <cstdio>
#include <ctime>
#include <map>
#include <set>
#include <type_traits>
#include <sstream>

#include "reports/check_report.hpp"
#include "reports/timing_svg.hpp"
#include "reports/xml_text.hpp"

namespace cemv::reports {

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

// Colours after the manual's online view (10.6.1): red for "Active - Alarm
// profile" (here: stored trips and elements a counterexample involves),
// yellow for "Bypass, simulation", orange for "Override", grey where nothing
// is processed ("Comment only", "X", "*").
const char* kCss = R"(
body{font-family:"DejaVu Sans",Arial,Helvetica,sans-serif;font-size:11pt;color:#111827;margin:24px}
h1{font-size:18pt;margin:0 0 4px}h2{font-size:14pt;border-bottom:2px solid #1f2937;padding-bottom:2px;margin-top:28px}
h3{font-size:12pt;margin:18px 0 6px}.meta{color:#374151}
table{border-collapse:collapse;margin:6px 0}th,td{border:1px solid #9ca3af;padding:3px 6px;vertical-align:top;text-align:left}
th{background:#f3f4f6}.num{text-align:right}
.pagehead,.pagefoot{font-size:8.5pt;color:#4b5563}
.pagehead{border-bottom:1px solid #d1d5db;margin-bottom:12px;padding-bottom:4px}
.pagefoot{border-top:1px solid #d1d5db;margin-top:24px;padding-top:4px}
.ok{background:#dcfce7}.bad{background:#fee2e2}.warn{background:#fef3c7}.unk{background:#e5e7eb}
table.grid td,table.grid th{text-align:center;min-width:22px;padding:2px 4px;font-size:9.5pt}
table.grid td.cause,table.grid th.effect{text-align:left}
th.effect{writing-mode:vertical-rl;transform:rotate(180deg);white-space:nowrap;height:auto}
.t-N{background:#dbeafe}.t-S{background:#fecaca}.t-V{background:#fed7aa}.t-R{background:#bbf7d0}
.t-X,.comment{background:#e5e7eb;color:#6b7280}.t-Note{color:#6b7280}
.bypass{box-shadow:inset 4px 0 0 #facc15}.involved{outline:2px solid #dc2626;outline-offset:-2px}
.legend span{display:inline-block;padding:1px 6px;margin-right:6px;border:1px solid #9ca3af}
img.diagram{max-width:100%;border:1px solid #d1d5db}
pre{white-space:pre-wrap;font-size:9pt;background:#f9fafb;border:1px solid #e5e7eb;padding:6px}
@media print{
 @page{size:A4;margin:18mm 12mm 16mm 12mm}
 body{margin:0;font-size:9.5pt}
 .pagehead.screen,.pagefoot.screen{display:none}
 section.page{break-before:page}
 h2,h3{break-after:avoid}tr,img,.cex{break-inside:avoid}
}
)";

const char* verdict_class(checker::PropertyVerdict v) {
  switch (v) {
    case checker::PropertyVerdict::Proved:
    case checker::PropertyVerdict::Reachable: return "ok";
    case checker::PropertyVerdict::Unknown: return "unk";
    default: return "bad";
  }
}

// A CSS string literal of `s`: quotes and backslashes escaped, control
// characters and '<' (which could end the <style> element) as hex escapes.
std::string css_string(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c == 0x7f || c == '<') {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\%X ", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

// The header and footer of every printed page, in the page margins (CSS
// paged media margin boxes), so they never cover the text: position:fixed
// blocks were drawn over the first and last lines of each page's content.
std::string page_boxes(const std::string& stamp) {
  const char* box = "font-family:\"DejaVu Sans\",Arial,Helvetica,sans-serif;font-size:7.5pt;color:#4b5563;";
  return std::string("@media print{@page{\n @top-left{content:") + css_string("Evidence report · " + stamp) + ";" +
         box + "vertical-align:bottom;padding-bottom:3mm}\n @bottom-left{content:" + css_string(stamp) + ";" + box +
         "vertical-align:top;padding-top:3mm}\n @bottom-right{content:\"page \" counter(page) \" of \" counter(pages);" +
         box + "vertical-align:top;padding-top:3mm;white-space:nowrap}}}\n";
}

class Writer {
 public:
  Writer(const model::Matrix& m, const EvidenceInputs& in) : m_(m), in_(in) {
    for (const auto& p : in.check.properties)
      if (p.verdict == checker::PropertyVerdict::Falsified)
        for (const auto& e : property_elements(p)) involved_.insert(e);
  }

  std::string html() {
    std::string stamp = "matrix " + m_.name + " · signature " + in_.check.matrix_signature + " · cemv " +
                        in_.check.tool_version + " · " + in_.date;
    o_ << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Evidence: "
       << html_escape(m_.name) << "</title>\n<style>" << kCss << page_boxes(stamp) << "</style>\n</head>\n<body>\n";
    o_ << "<div class=\"pagehead screen\">" << html_escape(stamp) << "</div>\n";
    summary();
    grid();
    validation();
    properties();
    evidence_detail::response_section(o_, m_, in_);
    evidence_detail::tests_section(o_, in_);
    o_ << "<div class=\"pagefoot screen\">" << html_escape(stamp) << "</div>\n</body>\n</html>\n";
    return o_.str();
  }

 private:
  void summary() {
    o_ << "<section>\n<h1>Evidence report: " << html_escape(m_.name) << "</h1>\n";
    if (!m_.title.empty()) o_ << "<p class=\"meta\">" << html_escape(m_.title) << "</p>\n";
    std::size_t errors = 0, warnings = 0;
    for (const auto& d : in_.validation) (d.severity == model::Severity::Error ? errors : warnings)++;
    auto counts = verdict_counts(in_.check);
    o_ << "<table>\n";
    row("Matrix file", html_escape(in_.matrix_file));
    row("Matrix signature (SHA-256 of the canonical form)", "<code>" + html_escape(in_.check.matrix_signature) + "</code>");
    row("Size", std::to_string(m_.causes.size()) + " causes, " + std::to_string(m_.effects.size()) +
                    " effects, " + std::to_string(m_.intersections.size()) + " intersections; cycle " +
                    std::to_string(m_.cycle_ms) + " ms");
    row("Validation (11.5)", std::to_string(errors) + " errors, " + std::to_string(warnings) + " warnings");
    std::string v;
    for (std::size_t i = 0; i < counts.size(); ++i)
      if (counts[i])
        v += (v.empty() ? "" : ", ") + std::to_string(counts[i]) + " " +
             verdict_name(static_cast<checker::PropertyVerdict>(i));
    row("Properties", std::to_string(in_.check.properties.size()) + (v.empty() ? "" : ": " + v));
    std::string files;
    for (const auto& f : in_.check.property_files) files += (files.empty() ? "" : ", ") + html_escape(f);
    if (in_.check.standard) files += std::string(files.empty() ? "" : ", ") + "the standard properties";
    row("Property sources", files.empty() ? "none given" : files);
    std::string resp = "not analysed";
    if (in_.response) {
      std::map<std::string, int> n;
      for (const auto& p : in_.response->paths) n[p.verdict]++;
      resp = std::to_string(in_.response->paths.size()) + " paths";
      const char* sep = ": ";
      for (const auto& [v, k] : n) resp += sep + std::to_string(k) + " " + v, sep = ", ";
    }
    row("Response time", html_escape(resp));
    std::string cov = "no test generation results given";
    if (in_.coverage)
      cov = std::to_string(in_.coverage->covered) + " of " + std::to_string(in_.coverage->objectives) +
            " objectives covered, " + std::to_string(in_.coverage->infeasible) + " infeasible, " +
            std::to_string(in_.coverage->undecided) + " undecided; " + std::to_string(in_.coverage->tests) + " tests";
    row("Test generation", html_escape(cov));
    std::string mut = "no mutation figures given";
    if (in_.mutation)
      mut = std::to_string(in_.mutation->mutants) + " mutants: " + std::to_string(in_.mutation->detected) +
            " detected, " + std::to_string(in_.mutation->equivalent) + " equivalent, " +
            std::to_string(in_.mutation->survived) + " survived, " + std::to_string(in_.mutation->undecided) +
            " undecided";
    row("Mutation", html_escape(mut));
    row("Tool", "cemv " + html_escape(in_.check.tool_version));
    row("Date", html_escape(in_.date));
    o_ << "</table>\n</section>\n";
  }

  void row(const std::string& k, const std::string& v) { o_ << "<tr><th>" << k << "</th><td>" << v << "</td></tr>\n"; }

  void grid() {
    o_ << "<section class=\"page\">\n<h2>1. Cause &amp; effect matrix</h2>\n";
    o_ << "<p class=\"legend\">Intersections: <span class=\"t-N\">N normal</span><span class=\"t-S\">S stored"
          "</span><span class=\"t-V\">V override</span><span class=\"t-R\">R reset</span><span class=\"t-X\">X "
          "not specified</span>* note only. Rows and columns: <span class=\"bypass\">bypass possible</span>"
          "<span class=\"comment\">comment only</span><span class=\"involved\">in a counterexample</span></p>\n";
    o_ << "<table class=\"grid\">\n<thead><tr><th>Cause</th><th>Tags</th>";
    for (const auto& e : m_.effects)
      o_ << "<th class=\"effect " << element_class(e) << "\" title=\"" << html_escape(e.description) << "\">E"
         << e.id << " " << html_escape(e.name) << "</th>";
    o_ << "</tr></thead>\n";
    for (const auto& c : m_.causes) {
      o_ << "<tr><td class=\"cause " << element_class(c) << "\" title=\"" << html_escape(c.description) << "\">C" << c.id
         << " " << html_escape(c.name) << "</td><td>";
      for (std::size_t i = 0; i < c.tags.size(); ++i) o_ << (i ? ", " : "") << html_escape(c.tags[i].name);
      o_ << "</td>";
      for (const auto& e : m_.effects) {
        const auto* x = m_.find_intersection(c.id, e.id);
        if (!x) {
          o_ << "<td></td>";
          continue;
        }
        std::string t = model::to_string(x->type);
        o_ << "<td class=\"t-" << (x->type == model::IntersectionType::Note ? "Note" : t) << "\">" << html_escape(t);
        if (x->xoon) o_ << "<sub>" << *x->xoon << "</sub>";
        o_ << "</td>";
      }
      o_ << "</tr>\n";
    }
    o_ << "</table>\n</section>\n";
  }

  template <class E>
  std::string element_class(const E& e) const {
    std::string cls;
    std::string key = (std::is_same_v<E, model::Cause> ? "cause[" : "effect[") + std::to_string(e.id) + "]";
    if constexpr (std::is_same_v<E, model::Cause>) {
      if (e.function == model::CauseFunction::Comment) cls += " comment";
      if (e.bypass_tag || e.soft_bypass.allowed) cls += " bypass";
    } else {
      if (e.function == model::EffectFunction::Comment) cls += " comment";
      if (e.bypass_tag || e.soft_bypass_allowed) cls += " bypass";
    }
    if (involved_.count(key)) cls += " involved";
    return cls;
  }

  void validation() {
    o_ << "<section class=\"page\">\n<h2>2. Validation (11.5)</h2>\n";
    if (in_.validation.empty()) {
      o_ << "<p class=\"ok\">No findings: the matrix passes every validation rule.</p>\n</section>\n";
      return;
    }
    o_ << "<table>\n<thead><tr><th>Severity</th><th>Rule</th><th>Element</th><th>Section</th><th>Finding</th>"
          "</tr></thead>\n";
    for (const auto& d : in_.validation)
      o_ << "<tr class=\"" << (d.severity == model::Severity::Error ? "bad" : "warn") << "\"><td>"
         << model::to_string(d.severity) << "</td><td>" << html_escape(d.rule) << "</td><td>" << html_escape(d.element)
         << "</td><td>" << html_escape(d.section) << "</td><td>" << html_escape(d.message) << "</td></tr>\n";
    o_ << "</table>\n</section>\n";
  }

  void properties() {
    o_ << "<section class=\"page\">\n<h2>3. Properties</h2>\n";
    if (in_.check.properties.empty()) {
      o_ << "<p>No properties given.</p>\n</section>\n";
      return;
    }
    o_ << "<p>Every answer is checked independently before it is reported: counterexamples and witnesses are "
          "replayed on the reference runtime and judged by the concrete property evaluator; proofs are "
          "re-proved by a fresh solver (docs/checker.md).</p>\n";
    o_ << "<table>\n<thead><tr><th>Property</th><th>Kind</th><th>Verdict</th><th>Method</th><th>Source</th>"
          "</tr></thead>\n";
    for (const auto& p : in_.check.properties) {
      o_ << "<tr><td><b>" << html_escape(p.name) << "</b>";
      if (!p.description.empty()) o_ << "<br>" << html_escape(p.description);
      o_ << "</td><td>" << html_escape(p.kind) << "</td><td class=\"" << verdict_class(p.verdict) << "\">"
         << html_escape(outcome_text(p)) << "</td><td>" << html_escape(p.method.empty() ? "-" : p.method) << "</td><td>"
         << html_escape(p.file.empty() ? "standard" : p.file + ":" + std::to_string(p.line)) << "</td></tr>\n";
    }
    o_ << "</table>\n";
    for (const auto& p : in_.check.properties) {
      if (!p.trace) continue;
      o_ << "<div class=\"cex\">\n<h3>" << html_escape(p.name) << ": "
         << (p.verdict == checker::PropertyVerdict::Reachable ? "witness" : "counterexample") << "</h3>\n";
      o_ << "<p>" << html_escape(outcome_text(p)) << ", " << p.trace->inputs.size()
         << (p.trace->inputs.size() == 1 ? " cycle" : " cycles") << ".</p>\n";
      o_ << "<img class=\"diagram\" alt=\"timing diagram of " << html_escape(p.name)
         << "\" src=\"data:image/svg+xml;base64," << base64(timing_svg(m_, *p.trace, diagram_of(p))) << "\">\n";
      if (!p.timing_table.empty()) o_ << "<pre>" << html_escape(p.timing_table) << "</pre>\n";
      o_ << "</div>\n";
    }
    o_ << "</section>\n";
  }

  const model::Matrix& m_;
  const EvidenceInputs& in_;
  std::set<std::string> involved_;
  std::ostringstream o_;
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
