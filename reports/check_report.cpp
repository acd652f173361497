// Shared pieces of the check printers (check_report.hpp).
#include "reports/check_report.hpp"

#include <algorithm>

#include "reports/check_json.hpp"
#include "reports/check_junit.hpp"
#include "reports/check_sarif.hpp"
#include "reports/check_text.hpp"
#include "reports/sarif.hpp"

namespace cemv::reports {

using checker::PropertyVerdict;

std::optional<CheckFormat> check_format_from_string(std::string_view name) {
  if (name == "text") return CheckFormat::Text;
  if (name == "json") return CheckFormat::Json;
  if (name == "junit") return CheckFormat::Junit;
  if (name == "sarif") return CheckFormat::Sarif;
  return std::nullopt;
}

std::string check_report(const checker::CheckResult& r, const CheckReportInputs& in,
                         CheckFormat format) {
  switch (format) {
    case CheckFormat::Text: return check_text(r, in);
    case CheckFormat::Json: return check_json(r, in);
    case CheckFormat::Junit: return check_junit(r, in);
    case CheckFormat::Sarif: return check_sarif(r, in);
  }
  return {};
}

const char* verdict_name(PropertyVerdict v) { return checker::to_string(v); }

bool is_failure(PropertyVerdict v) {
  return v == PropertyVerdict::Falsified || v == PropertyVerdict::Unreachable || v == PropertyVerdict::Vacuous;
}

std::array<int, 6> verdict_counts(const checker::CheckResult& r) {
  std::array<int, 6> counts{};
  for (const auto& p : r.properties) ++counts[static_cast<std::size_t>(p.verdict)];
  return counts;
}

std::vector<std::string> property_elements(const checker::PropertyResult& p) {
  std::vector<std::string> out;
  for (const auto& key : p.matters) {
    std::string element = key.substr(0, key.find('.'));
    if (std::find(out.begin(), out.end(), element) == out.end()) out.push_back(element);
  }
  return out;
}

namespace {

std::string by_method(const checker::PropertyResult& p) {
  if (p.method.empty()) return "";
  std::string s = " by " + p.method;
  if (p.depth > 0) s += " (k = " + std::to_string(p.depth) + ")";
  return s;
}

std::string with_reason(const checker::PropertyResult& p) {
  return p.reason.empty() ? std::string() : ": " + p.reason;
}

}  // namespace

std::string outcome_text(const checker::PropertyResult& p) {
  // Cycles are shown 1-based, as in the timing tables of `cemv simulate`.
  std::string at = p.violation_cycle >= 0 ? " at cycle " + std::to_string(p.violation_cycle + 1)
                                          : std::string();
  switch (p.verdict) {
    case PropertyVerdict::Proved: return "proved" + by_method(p);
    case PropertyVerdict::Falsified:
      return "falsified" + at + (p.method.empty() ? "" : " (found by " + p.method + ")");
    case PropertyVerdict::Reachable:
      return "reachable, witness" + at + (p.method.empty() ? "" : " (found by " + p.method + ")");
    case PropertyVerdict::Unreachable: return "unreachable" + by_method(p) + with_reason(p);
    case PropertyVerdict::Vacuous: return "vacuous" + with_reason(p);
    case PropertyVerdict::Unknown: return "unknown" + with_reason(p);
  }
  return "unknown";
}

bool is_standard(const checker::PropertyResult& p) { return p.file.empty() || p.file == "<standard>"; }

bool as_expected(const checker::PropertyResult& p) {
  if (p.expected.empty()) return !is_failure(p.verdict) && p.verdict != PropertyVerdict::Unknown;
  return p.expected == verdict_name(p.verdict);
}

std::string finding_line(const checker::PropertyResult& p, const CheckReportInputs& in) {
  const bool expected = as_expected(p);
  const bool negative = is_failure(p.verdict) || p.verdict == PropertyVerdict::Unknown;
  if (expected && !negative) return "";
  std::string place = is_standard(p) ? in.matrix_file : p.file;
  if (p.line > 0) {
    place += ":" + std::to_string(p.line) + ":" + std::to_string(std::max(p.column, 1));
  } else if (is_standard(p)) {
    // A standard property is derived from its element: placed at its line.
    auto elements = property_elements(p);
    if (!elements.empty())
      if (auto at = MatrixLines(in.matrix_text).find(elements.front()))
        place += ":" + std::to_string(at->first) + ":" + std::to_string(at->second);
  }
  const char* severity = expected ? "note" : p.verdict == PropertyVerdict::Unknown ? "warning" : "error";
  std::string line = place + ": " + severity + ": property '" + p.name + "' " + outcome_text(p);
  if (expected)
    line += " (as expected)";
  else if (!p.expected.empty())
    line += ", expected " + p.expected + (p.expected_from.empty() ? "" : " (" + p.expected_from + ")");
  return line;
}

std::string check_findings(const checker::CheckResult& r, const CheckReportInputs& in) {
  std::string out;
  for (const auto& p : r.properties)
    if (std::string line = finding_line(p, in); !line.empty()) out += line + "\n";
  return out;
}

std::vector<std::string> explanation_lines(const checker::PropertyResult& p) {
  std::vector<std::string> out;
  for (const auto& s : p.explanation)
    out.push_back("cycle " + std::to_string(s.cycle) + ": " + s.signal + " " + (s.before.empty() ? "" : s.before + " -> ") +
                  s.after + ": " + s.why);
  return out;
}

}  // namespace cemv::reports
