#include "response/report.hpp"

#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "reports/check_report.hpp"

namespace cemv::response {

namespace {

using nlohmann::ordered_json;

std::string percent(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

std::string path_text(const PathResult& p) {
  std::string causes;
  for (std::size_t i = 0; i < p.path.causes.size(); ++i)
    causes += (i ? "," : "") + std::to_string(p.path.causes[i]);
  std::string s = "cause" + std::string(p.path.causes.size() > 1 ? "s " : " ") + causes;
  if (p.path.causes.size() > 1)
    s += " (" + std::to_string(p.path.needed) + "oo" + std::to_string(p.path.causes.size()) + ")";
  return s + " -> effect " + std::to_string(p.path.effect);
}

std::string figure_text(const Figure& f, long long cycle_ms) {
  switch (f.kind) {
    case Figure::Kind::Exact:
      return std::to_string(f.cycles) + " cycles (" + std::to_string(f.cycles * cycle_ms) + " ms)";
    case Figure::Kind::Unbounded:
      return "unbounded (held off " + std::to_string(f.cycles) + " cycles" + (f.reason.empty() ? "" : "; " + f.reason) +
             ")";
    case Figure::Kind::Unknown: return "unknown: " + f.reason;
  }
  return "";
}

std::string margin_text(const PathResult& p) {
  if (!p.margin_ms) return "-";
  return std::to_string(*p.margin_ms) + " ms (" + percent(*p.margin_percent) + " %)";
}

// One line saying what the figure means, for messages.
std::string summary(const ResponseResult& r, const PathResult& p) {
  std::string s = "SIF " + std::to_string(p.path.sif) + ", " + path_text(p) + ": ";
  s += "logic " + figure_text(p.logic, r.cycle_ms);
  if (p.total_ms) s += ", total " + std::to_string(*p.total_ms) + " ms";
  if (p.process_safety_time_ms) s += ", process safety time " + std::to_string(*p.process_safety_time_ms) + " ms";
  if (p.margin_ms) s += ", margin " + margin_text(p);
  if (p.degraded) s += "; degraded: " + figure_text(*p.degraded, r.cycle_ms);
  if (p.degraded_total_ms) s += ", total " + std::to_string(*p.degraded_total_ms) + " ms";
  return s + ": " + to_string(p.verdict);
}

std::string text(const ResponseResult& r) {
  std::ostringstream out;
  out << "cemv response: " << r.matrix_name << "\n";
  out << "signature: " << r.matrix_signature << "\n";
  out << "cycle " << r.cycle_ms << " ms; controller's share "
      << (r.conservative ? 2LL * *r.watchdog_ms : 2LL * r.cycle_ms) << " ms ("
      << (r.conservative ? "2 x watchdog_ms, --conservative" : "2 x cycle_ms") << ")\n";
  std::map<int, std::vector<const PathResult*>> by_sif;
  for (const auto& p : r.paths) by_sif[p.path.sif].push_back(&p);
  const std::vector<std::string> head = {"path", "logic", "total", "margin", "verdict", "degraded", "counterexample"};
  for (const auto& [sif, paths] : by_sif) {
    const PathResult& first = *paths.front();
    out << "\nSIF " << sif << " '" << first.sif_name << "': process safety time "
        << (first.process_safety_time_ms ? std::to_string(*first.process_safety_time_ms) + " ms" : "not declared")
        << "\n";
    std::vector<std::vector<std::string>> rows = {head};
    for (const PathResult* p : paths) {
      std::string degraded = "-";
      if (p->degraded)
        degraded = p->degraded_total_ms ? std::to_string(*p->degraded_total_ms) + " ms" : figure_text(*p->degraded, r.cycle_ms);
      rows.push_back({path_text(*p), figure_text(p->logic, r.cycle_ms),
                      p->total_ms ? std::to_string(*p->total_ms) + " ms" : "-", margin_text(*p),
                      to_string(p->verdict), degraded,
                      p->logic.counterexample.empty() ? "-" : p->logic.counterexample});
    }
    std::vector<std::size_t> width(head.size(), 0);
    for (const auto& row : rows)
      for (std::size_t i = 0; i < row.size(); ++i) width[i] = std::max(width[i], row[i].size());
    for (const auto& row : rows) {
      std::string line = " ";
      for (std::size_t i = 0; i < row.size(); ++i)
        line += " " + row[i] + (i + 1 < row.size() ? std::string(width[i] - row[i].size() + 1, ' ') : "");
      out << line << "\n";
    }
  }
  int counts[5] = {0, 0, 0, 0, 0};
  for (const auto& p : r.paths) ++counts[static_cast<int>(p.verdict)];
  out << "\n" << r.paths.size() << (r.paths.size() == 1 ? " path" : " paths");
  const char* sep = ": ";
  for (int v = 0; v < 5; ++v)
    if (counts[v]) {
      out << sep << counts[v] << " " << to_string(static_cast<Verdict>(v));
      sep = ", ";
    }
  out << "\n";
  for (const auto& p : r.paths)
    if (p.verdict == Verdict::Over || p.verdict == Verdict::Unbounded)
      out << to_string(p.verdict) << ": " << summary(r, p) << "\n";
  return out.str();
}

ordered_json optional_number(const std::optional<long long>& v) { return v ? ordered_json(*v) : ordered_json(nullptr); }

std::string json(const ResponseResult& r) {
  ordered_json j;
  j["schema"] = "cemv-response/1";
  j["matrix_signature"] = r.matrix_signature;
  ordered_json paths = ordered_json::array();
  for (const auto& p : r.paths) {
    ordered_json o;
    o["sif"] = p.path.sif;
    o["causes"] = p.path.causes;
    o["effect"] = p.path.effect;
    o["logic_cycles"] = p.logic.kind == Figure::Kind::Exact ? ordered_json(p.logic.cycles) : ordered_json(nullptr);
    o["logic_ms"] = optional_number(p.logic_ms);
    o["total_ms"] = optional_number(p.total_ms);
    o["process_safety_time_ms"] =
        p.process_safety_time_ms ? ordered_json(*p.process_safety_time_ms) : ordered_json(nullptr);
    o["margin_ms"] = optional_number(p.margin_ms);
    o["verdict"] = to_string(p.verdict);
    o["degraded_total_ms"] = optional_number(p.degraded_total_ms);
    o["counterexample"] = p.logic.counterexample.empty() ? ordered_json(nullptr) : ordered_json(p.logic.counterexample);
    paths.push_back(std::move(o));
  }
  j["paths"] = std::move(paths);
  return j.dump(2) + "\n";
}

// Each path as a property result of `cemv check`: ok and no-pst pass, over
// and unbounded fail (falsified), unknown is unknown.
checker::CheckResult as_check_result(const ResponseResult& r, const std::string& matrix_file,
                                     const std::string& out_dir) {
  checker::CheckResult c;
  c.matrix_name = r.matrix_name;
  c.matrix_signature = r.matrix_signature;
  c.tool_version = CEMV_VERSION;
  for (const auto& p : r.paths) {
    checker::PropertyResult pr;
    pr.name = "response.sif" + std::to_string(p.path.sif) + "." + p.path.key();
    pr.description = summary(r, p);
    pr.kind = "response";
    pr.file = matrix_file;  // where a CI view locates the finding
    switch (p.verdict) {
      case Verdict::Ok:
      case Verdict::NoPst:
        pr.verdict = checker::PropertyVerdict::Proved;
        pr.method = p.logic.method + ", exact response time " + std::to_string(p.logic.cycles) + " cycles" +
                    (p.logic.cycles > 0 ? " (one cycle less falsified)" : "");
        if (p.verdict == Verdict::NoPst) pr.notes.push_back("the SIF group declares no process safety time");
        break;
      case Verdict::Over:
        pr.verdict = checker::PropertyVerdict::Falsified;
        pr.method = "exact response time: total " + std::to_string(*p.total_ms) + " ms exceeds the process safety time " +
                    std::to_string(*p.process_safety_time_ms) + " ms by " + std::to_string(-*p.margin_ms) + " ms";
        break;
      case Verdict::Unbounded:
        pr.verdict = checker::PropertyVerdict::Falsified;
        pr.method = "response time: held off beyond " + std::to_string(p.logic.cycles) + " cycles (unbounded)";
        break;
      case Verdict::Unknown:
        pr.verdict = checker::PropertyVerdict::Unknown;
        pr.reason = p.logic.reason;
        break;
    }
    if (!p.logic.counterexample.empty())
      pr.scenario_file = out_dir.empty() ? p.logic.counterexample : out_dir + "/" + p.logic.counterexample;
    for (int id : p.path.causes) pr.matters.push_back("cause[" + std::to_string(id) + "].active");
    pr.matters.push_back("effect[" + std::to_string(p.path.effect) + "].active");
    c.properties.push_back(std::move(pr));
  }
  return c;
}

}  // namespace

std::string response_report(const ResponseResult& r, const std::string& matrix_file, Format format,
                            const std::string& out_dir) {
  switch (format) {
    case Format::Text: return text(r);
    case Format::Json: return json(r);
    case Format::Junit:
      return reports::check_report(as_check_result(r, matrix_file, out_dir), {matrix_file}, reports::CheckFormat::Junit);
    case Format::Sarif:
      return reports::check_report(as_check_result(r, matrix_file, out_dir), {matrix_file}, reports::CheckFormat::Sarif);
  }
  return "";
}

}  // namespace cemv::response
