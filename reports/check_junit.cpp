// JUnit XML as CI servers read it (Jenkins, GitLab, the GitHub test-report
// actions): one <testsuite>, one <testcase> per property. A failing verdict
// (falsified, unreachable, vacuous) is a <failure> whose text is the
// counterexample's timing table; unknown is an <error>. No times, no
// timestamps, so the file is the same on every run.
#include "reports/check_junit.hpp"
#include "reports/xml_text.hpp"

#include <cstdint>
#include <sstream>

namespace cemv::reports {

namespace {

using checker::PropertyResult;
using checker::PropertyVerdict;

std::string attr(std::string_view s) { return xml_escape(s, true); }
std::string text(std::string_view s) { return xml_escape(s, false); }

std::string class_name(const checker::CheckResult& r, const PropertyResult& p) {
  if (is_standard(p)) return r.matrix_name + ".standard";
  std::string stem = p.file.substr(p.file.find_last_of('/') + 1);
  return r.matrix_name + "." + stem.substr(0, stem.find('.'));
}

// The body of a <failure>/<error> or of <system-out>: what a reviewer needs
// without opening another file.
std::string detail_text(const PropertyResult& p) {
  std::ostringstream s;
  s << p.name << ": " << outcome_text(p) << "\n";
  if (!p.expected.empty())
    s << "expected: " << p.expected << (p.expected_from.empty() ? "" : " (" + p.expected_from + ")")
      << (as_expected(p) ? ", as expected" : "") << "\n";
  if (!p.description.empty()) s << "requirement: " << p.description << "\n";
  for (const auto& n : p.notes) s << "note: " << n << "\n";
  if (!p.scenario_file.empty()) s << "scenario: " << p.scenario_file << "\n";
  if (!p.diagram_file.empty()) s << "diagram: " << p.diagram_file << "\n";
  if (!p.vcd_file.empty()) s << "waveforms: " << p.vcd_file << "\n";
  if (!p.timing_table.empty()) s << p.timing_table << (p.timing_table.back() == '\n' ? "" : "\n");
  if (!p.support.empty()) {
    s << "support" << (p.support_minimal ? " (minimal)" : "") << ":";
    for (const auto& e : p.support) s << " " << e.key;
    s << "\n";
  }
  return s.str();
}

}  // namespace

std::string check_junit(const checker::CheckResult& r, const CheckReportInputs& in) {
  // A test fails when its verdict is not the one expected: a negative
  // verdict, or with a gate (--expect, --baseline) any other than the gate's.
  int failures = 0, errors = 0;
  for (const auto& p : r.properties) {
    if (p.verdict == PropertyVerdict::Unknown) ++errors;
    else if (!as_expected(p)) ++failures;
  }
  std::string totals = " tests=\"" + std::to_string(r.properties.size()) + "\" failures=\"" +
                       std::to_string(failures) + "\" errors=\"" + std::to_string(errors) + "\"";
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out << "<testsuites name=\"cemv check\"" << totals << ">\n";
  std::string suite = "cemv check " + r.matrix_name + (r.shard.empty() ? "" : " shard " + r.shard);
  out << "  <testsuite name=\"" << attr(suite) << "\"" << totals << " skipped=\"0\">\n";
  out << "    <properties>\n";
  out << "      <property name=\"matrix\" value=\"" << attr(r.matrix_name) << "\"/>\n";
  out << "      <property name=\"matrix_file\" value=\"" << attr(in.matrix_file) << "\"/>\n";
  out << "      <property name=\"signature\" value=\"" << attr(r.matrix_signature) << "\"/>\n";
  out << "      <property name=\"tool_version\" value=\"" << attr(r.tool_version) << "\"/>\n";
  out << "      <property name=\"interrupted\" value=\"" << (r.interrupted ? "true" : "false")
      << "\"/>\n";
  out << "    </properties>\n";
  for (const auto& p : r.properties) {
    out << "    <testcase name=\"" << attr(p.name) << "\" classname=\"" << attr(class_name(r, p))
        << "\"";
    if (!is_standard(p)) out << " file=\"" << attr(p.file) << "\"";
    if (p.line > 0) out << " line=\"" << p.line << "\"";
    out << ">\n";
    std::string body = text(detail_text(p));
    std::string message = attr(outcome_text(p));
    if (p.verdict == PropertyVerdict::Unknown)
      out << "      <error type=\"unknown\" message=\"" << message << "\">" << body << "</error>\n";
    else if (!as_expected(p))
      out << "      <failure type=\"" << verdict_name(p.verdict) << "\" message=\"" << message
          << (p.expected.empty() ? "" : ", expected " + attr(p.expected)) << "\">" << body << "</failure>\n";
    else
      out << "      <system-out>" << body << "</system-out>\n";
    out << "    </testcase>\n";
  }
  out << "  </testsuite>\n</testsuites>\n";
  return out.str();
}

}  // namespace cemv::reports
