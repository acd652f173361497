// JUnit XML as CI servers read it (Jenkins, GitLab, the GitHub test-report
// actions): one <testsuite>, one <testcase> per property. A failing verdict
// (falsified, unreachable, vacuous) is a <failure> whose text is the
// counterexample's timing table; unknown is an <error>. No times, no
// timestamps, so the file is the same on every run.
#include "reports/check_junit.hpp"

#include <cstdint>
#include <sstream>

namespace cemv::reports {

namespace {

using checker::PropertyResult;
using checker::PropertyVerdict;

// Length of the valid UTF-8 sequence at s[i] and its code point, or 0.
std::size_t utf8_sequence(std::string_view s, std::size_t i, std::uint32_t& cp) {
  auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  unsigned char b = byte(i);
  std::size_t n = b < 0x80 ? 1 : (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xE ? 3 : (b >> 3) == 0x1E ? 4 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  cp = n == 1 ? b : n == 2 ? (b & 0x1F) : n == 3 ? (b & 0x0F) : (b & 0x07);
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3F);
  }
  static const std::uint32_t min_for_length[] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < min_for_length[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  return n;
}

// XML 1.0 character data: markup characters escaped; characters XML forbids
// (most controls, U+FFFE/U+FFFF) and invalid UTF-8 become U+FFFD, so the file
// always parses. In attributes, line breaks and tabs become character
// references (attribute-value normalisation would otherwise turn them into spaces).
std::string xml_escape(std::string_view s, bool attribute) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    std::uint32_t cp = 0;
    std::size_t n = utf8_sequence(s, i, cp);
    bool allowed = n != 0 && (cp >= 0x20 || cp == '\t' || cp == '\n' || cp == '\r') &&
                   cp != 0xFFFE && cp != 0xFFFF;
    if (!allowed) {
      out += "\xEF\xBF\xBD";
      i += n ? n : 1;
      continue;
    }
    switch (cp) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += attribute ? "&quot;" : "\""; break;
      case '\'': out += attribute ? "&apos;" : "'"; break;
      case '\n': out += attribute ? "&#10;" : "\n"; break;
      case '\r': out += "&#13;"; break;
      case '\t': out += attribute ? "&#9;" : "\t"; break;
      default: out.append(s.substr(i, n));
    }
    i += n;
  }
  return out;
}

std::string attr(std::string_view s) { return xml_escape(s, true); }
std::string text(std::string_view s) { return xml_escape(s, false); }

std::string class_name(const checker::CheckResult& r, const PropertyResult& p) {
  if (p.file.empty()) return r.matrix_name + ".standard";
  std::string stem = p.file.substr(p.file.find_last_of('/') + 1);
  return r.matrix_name + "." + stem.substr(0, stem.find('.'));
}

// The body of a <failure>/<error> or of <system-out>: what a reviewer needs
// without opening another file.
std::string detail_text(const PropertyResult& p) {
  std::ostringstream s;
  s << p.name << ": " << outcome_text(p) << "\n";
  if (!p.description.empty()) s << "requirement: " << p.description << "\n";
  for (const auto& n : p.notes) s << "note: " << n << "\n";
  if (!p.scenario_file.empty()) s << "scenario: " << p.scenario_file << "\n";
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
  auto counts = verdict_counts(r);
  int failures = counts[static_cast<std::size_t>(PropertyVerdict::Falsified)] +
                 counts[static_cast<std::size_t>(PropertyVerdict::Unreachable)] +
                 counts[static_cast<std::size_t>(PropertyVerdict::Vacuous)];
  int errors = counts[static_cast<std::size_t>(PropertyVerdict::Unknown)];
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
    if (!p.file.empty()) out << " file=\"" << attr(p.file) << "\"";
    if (p.line > 0) out << " line=\"" << p.line << "\"";
    out << ">\n";
    std::string body = text(detail_text(p));
    std::string message = attr(outcome_text(p));
    if (is_failure(p.verdict))
      out << "      <failure type=\"" << verdict_name(p.verdict) << "\" message=\"" << message
          << "\">" << body << "</failure>\n";
    else if (p.verdict == PropertyVerdict::Unknown)
      out << "      <error type=\"unknown\" message=\"" << message << "\">" << body << "</error>\n";
    else
      out << "      <system-out>" << body << "</system-out>\n";
    out << "    </testcase>\n";
  }
  out << "  </testsuite>\n</testsuites>\n";
  return out.str();
}

}  // namespace cemv::reports
