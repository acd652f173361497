// The human-readable check report: one line per property (verdict, name,
// method and depth or reason, time), then for each counterexample or witness
// its place, its scenario file and the timing table of the signals that matter.
// The only output with times in it.
#include "reports/check_text.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace cemv::reports {

namespace {

using checker::PropertyResult;
using checker::PropertyVerdict;

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f s", s);
  return buf;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
  return s;
}

std::string method_column(const PropertyResult& p) {
  if (p.verdict == PropertyVerdict::Unknown || p.verdict == PropertyVerdict::Vacuous)
    return p.reason.empty() ? std::string("-") : p.reason;
  std::string s = p.method.empty() ? std::string("-") : p.method;
  if (p.depth > 0) s += (p.verdict == PropertyVerdict::Proved || p.verdict == PropertyVerdict::Unreachable)
                            ? ", k=" + std::to_string(p.depth)
                            : ", " + std::to_string(p.depth) + (p.depth == 1 ? " cycle" : " cycles");
  return s;
}

void indented(std::ostringstream& out, const std::string& block, const char* indent) {
  std::istringstream in(block);
  std::string line;
  while (std::getline(in, line)) out << indent << line << "\n";
}

// How a support was found, as the reports say it (docs/checker.md, "Support").
std::string support_words(const PropertyResult& p, checker::SupportMode mode) {
  if (mode == checker::SupportMode::Core) return "core of the proof, re-checked";
  return p.support_minimal ? "minimal" : "not minimised";
}

void details(std::ostringstream& out, const PropertyResult& p, const CheckReportInputs& in,
             checker::SupportMode mode) {
  for (const auto& n : p.notes) out << "    note: " << n << "\n";
  // FILE:LINE:COL: error: ..., so editors and CI logs can jump there.
  if (std::string line = finding_line(p, in); !line.empty()) out << "    " << line << "\n";
  if (p.verdict == PropertyVerdict::Proved && !p.support.empty()) {
    out << "    support (" << support_words(p, mode) << "):";
    for (const auto& s : p.support) out << " " << s.key;
    out << "\n";
  }
  if (p.verdict == PropertyVerdict::Falsified || p.verdict == PropertyVerdict::Reachable) {
    if (p.verdict == PropertyVerdict::Reachable && p.violation_cycle >= 0)
      out << "    witnessed at cycle " << p.violation_cycle + 1 << "\n";
    if (!p.scenario_file.empty()) out << "    scenario: " << p.scenario_file << "\n";
    if (!p.diagram_file.empty()) out << "    diagram: " << p.diagram_file << "\n";
    if (!p.vcd_file.empty()) out << "    waveforms: " << p.vcd_file << "\n";
    if (!p.timing_table.empty()) indented(out, p.timing_table, "    ");
    if (!p.explanation.empty()) {
      out << "    why, per step (docs/semantics.md):\n";
      for (const auto& s : explanation_lines(p)) out << "      " << s << "\n";
    }
  }
}

}  // namespace

std::string check_text(const checker::CheckResult& r, const CheckReportInputs& in) {
  std::ostringstream out;
  out << "matrix " << r.matrix_name << " (" << in.matrix_file << ") signature "
      << r.matrix_signature << "\n";
  std::size_t name_width = 0, method_width = 0;
  for (const auto& p : r.properties) {
    name_width = std::max(name_width, p.name.size());
    method_width = std::max(method_width, method_column(p).size());
  }
  double total = 0.0;
  for (const auto& p : r.properties) {
    std::string verdict = upper(verdict_name(p.verdict));
    std::string method = method_column(p);
    out << verdict << std::string(12 - std::min<std::size_t>(verdict.size(), 11), ' ') << p.name
        << std::string(name_width - p.name.size() + 2, ' ') << method
        << std::string(method_width - method.size() + 2, ' ') << (p.cached ? "cached" : seconds_text(p.seconds))
        << "\n";
    details(out, p, in, r.support_mode);
    total += p.seconds;
  }
  if (r.standard && !r.unsupported.empty()) {
    out << "elements no property depends on (" << r.unsupported.size() << "):\n";
    for (const auto& e : r.unsupported)
      out << "  " << e.key << (e.description.empty() ? "" : "  " + e.description) << "\n";
  }
  auto counts = verdict_counts(r);
  out << r.properties.size() << (r.properties.size() == 1 ? " property" : " properties");
  const char* sep = ": ";
  for (std::size_t v = 0; v < counts.size(); ++v) {
    if (!counts[v]) continue;
    out << sep << counts[v] << " " << verdict_name(static_cast<PropertyVerdict>(v));
    sep = ", ";
  }
  out << "; " << seconds_text(total) << " of checking";
  auto cached = std::count_if(r.properties.begin(), r.properties.end(), [](const PropertyResult& p) { return p.cached; });
  if (cached) out << "; " << cached << " from the cache";
  if (!r.shard.empty()) out << "; shard " << r.shard;
  if (r.interrupted) out << "; INTERRUPTED by the overall time limit";
  out << "\n";
  return out.str();
}

}  // namespace cemv::reports
