#include "defeats/report.hpp"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "reports/check_report.hpp"

namespace cemv::defeats {

namespace {

using nlohmann::ordered_json;

std::string path_text(const PathDefeats& p) {
  std::string causes;
  for (std::size_t i = 0; i < p.path.causes.size(); ++i)
    causes += (i ? "," : "") + std::to_string(p.path.causes[i]);
  std::string s = "cause" + std::string(p.path.causes.size() > 1 ? "s " : " ") + causes;
  if (p.path.causes.size() > 1)
    s += " (" + std::to_string(p.path.needed) + "oo" + std::to_string(p.path.causes.size()) + ")";
  return s + " -> effect " + std::to_string(p.path.effect);
}

std::string distance_text(const PathDefeats& p, int max_size) {
  if (p.distance) return std::to_string(*p.distance);
  if (p.status == PathStatus::Complete) return "> " + std::to_string(max_size);
  return "unknown";
}

std::string keys(const PathDefeats& p, const std::vector<int>& s) {
  std::string out = "{";
  for (std::size_t i = 0; i < s.size(); ++i) out += (i ? ", " : "") + p.actions[s[i]].key();
  return out + "}";
}

std::string table(const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> width(rows.front().size(), 0);
  for (const auto& row : rows)
    for (std::size_t i = 0; i < row.size(); ++i) width[i] = std::max(width[i], row[i].size());
  std::string out;
  for (const auto& row : rows) {
    std::string line = " ";
    for (std::size_t i = 0; i < row.size(); ++i)
      line += " " + row[i] + (i + 1 < row.size() ? std::string(width[i] - row[i].size() + 1, ' ') : "");
    out += line + "\n";
  }
  return out;
}

std::string summary(const DefeatsResult& r, const PathDefeats& p) {
  std::size_t declared = 0, indirect = 0;
  for (const auto& s : p.sets) (s.set_class == SetClass::Declared ? declared : indirect)++;
  std::string s = "SIF " + std::to_string(p.path.sif) + ", " + path_text(p) + ": ";
  if (p.status == PathStatus::Unbounded) return s + "the trip requirement fails with no action (response unbounded)";
  s += std::to_string(p.sets.size()) + " minimal defeat set" + (p.sets.size() == 1 ? "" : "s") + " up to size " +
       std::to_string(r.max_size) + " (" + std::to_string(declared) + " declared, " + std::to_string(indirect) +
       " indirect); defeat distance " + distance_text(p, r.max_size);
  if (p.status == PathStatus::Unknown) s += "; incomplete: " + p.reason;
  return s;
}

std::string text(const DefeatsResult& r, int require_distance) {
  std::ostringstream out;
  out << "cemv defeats: " << r.matrix_name << "\n";
  out << "signature: " << r.matrix_signature << "\n";
  out << "minimal defeat sets up to size " << r.max_size << "\n";
  std::map<int, std::vector<const PathDefeats*>> by_sif;
  for (const auto& p : r.paths) by_sif[p.path.sif].push_back(&p);
  for (const auto& [sif, paths] : by_sif) {
    const PathDefeats& first = *paths.front();
    out << "\nSIF " << sif << " '" << first.sif_name << "'" << (first.sil ? ", SIL " + std::to_string(first.sil) : "")
        << "\n";
    std::vector<std::vector<std::string>> rows = {{"path", "T", "actions", "distance", "set", "class", "counterexample"}};
    for (const PathDefeats* p : paths) {
      const std::string t = p->requirement ? std::to_string(*p->requirement) : "-";
      const std::string status = p->status == PathStatus::Complete ? "" : " (" + std::string(to_string(p->status)) + ")";
      if (p->sets.empty()) {
        rows.push_back({path_text(*p), t, std::to_string(p->actions.size()), distance_text(*p, r.max_size) + status,
                        p->status == PathStatus::Unbounded ? "{} (no action needed)" : "none", "-", "-"});
        continue;
      }
      for (std::size_t i = 0; i < p->sets.size(); ++i) {
        const DefeatSet& s = p->sets[i];
        const std::string& cx = p->questions[s.question].scenario;
        rows.push_back({i ? "" : path_text(*p), i ? "" : t, i ? "" : std::to_string(p->actions.size()),
                        i ? "" : distance_text(*p, r.max_size) + status, keys(*p, s.actions), to_string(s.set_class),
                        cx.empty() ? "-" : cx});
      }
    }
    out << table(rows);
  }
  std::size_t sets = 0, indirect1 = 0, incomplete = 0;
  for (const auto& p : r.paths) {
    sets += p.sets.size();
    for (const auto& s : p.sets) indirect1 += s.set_class == SetClass::Indirect && s.actions.size() == 1;
    incomplete += p.status != PathStatus::Complete;
  }
  out << "\n" << r.paths.size() << (r.paths.size() == 1 ? " path" : " paths") << ": " << sets
      << " minimal defeat sets, " << indirect1 << " indirect of size 1";
  if (incomplete) out << ", " << incomplete << " incomplete";
  out << "\n";
  for (const auto& p : r.paths)
    if (p.status != PathStatus::Complete) out << to_string(p.status) << ": " << summary(r, p) << "\n";
  for (const PathDefeats* p : gate_failures(r, require_distance))
    out << "gate: " << summary(r, *p) << ", below --require-distance " << require_distance << " (SIL " << p->sil
        << ")\n";
  return out.str();
}

ordered_json set_json(const PathDefeats& p, const std::vector<int>& s) {
  ordered_json a = ordered_json::array();
  for (int i : s) a.push_back(p.actions[i].key());
  return a;
}

std::string json(const model::Matrix& m, const DefeatsResult& r, int require_distance) {
  ordered_json j;
  j["schema"] = "cemv-defeats/1";
  j["matrix_signature"] = r.matrix_signature;
  j["max_size"] = r.max_size;
  j["require_distance"] = require_distance > 0 ? ordered_json(require_distance) : ordered_json(nullptr);
  ordered_json paths = ordered_json::array();
  const auto gate = gate_failures(r, require_distance);
  for (const auto& p : r.paths) {
    ordered_json o;
    o["sif"] = p.path.sif;
    o["sil"] = p.sil;
    o["key"] = p.path.key();
    o["causes"] = p.path.causes;
    o["needed"] = p.path.needed;
    o["effect"] = p.path.effect;
    o["requirement_cycles"] = p.requirement ? ordered_json(*p.requirement) : ordered_json(nullptr);
    o["status"] = to_string(p.status);
    o["reason"] = p.reason.empty() ? ordered_json(nullptr) : ordered_json(p.reason);
    o["distance"] = p.distance ? ordered_json(*p.distance) : ordered_json(nullptr);
    o["gate_failed"] = std::find(gate.begin(), gate.end(), &p) != gate.end();
    ordered_json actions = ordered_json::array();
    for (const auto& a : p.actions) {
      ordered_json x;
      x["key"] = a.key();
      x["kind"] = to_string(a.kind);
      x["description"] = a.description(m);
      x["declared"] = declared_for(m, p.path, a);
      x["cause"] = a.cause ? ordered_json(a.cause) : ordered_json(nullptr);
      x["effect"] = a.effect ? ordered_json(a.effect) : ordered_json(nullptr);
      x["tag"] = a.tag.empty() ? ordered_json(nullptr) : ordered_json(a.tag);
      actions.push_back(std::move(x));
    }
    o["actions"] = std::move(actions);
    ordered_json sets = ordered_json::array();
    for (const auto& s : p.sets) {
      const Question& q = p.questions[s.question];
      ordered_json x;
      x["actions"] = set_json(p, s.actions);
      x["class"] = to_string(s.set_class);
      x["property"] = q.property;
      x["counterexample"] = q.scenario.empty() ? ordered_json(nullptr) : ordered_json(q.scenario);
      x["method"] = q.method;
      x["violation_cycle"] = q.violation_cycle;
      ordered_json subsets = ordered_json::array();
      for (const auto& [sub, proof] : s.subsets) {
        ordered_json y;
        y["actions"] = set_json(p, sub);
        y["proved_by"] = p.questions[proof].property;
        subsets.push_back(std::move(y));
      }
      x["minimality"] = std::move(subsets);
      sets.push_back(std::move(x));
    }
    o["sets"] = std::move(sets);
    ordered_json questions = ordered_json::array();
    for (const auto& q : p.questions) {
      ordered_json x;
      x["property"] = q.property;
      x["actions"] = set_json(p, q.actions);
      x["verdict"] = checker::to_string(q.verdict);
      x["method"] = q.method;
      x["work"] = q.work;
      if (!q.reason.empty()) x["reason"] = q.reason;
      questions.push_back(std::move(x));
    }
    o["questions"] = std::move(questions);
    paths.push_back(std::move(o));
  }
  j["paths"] = std::move(paths);
  return j.dump(2) + "\n";
}

// Each path as a property result of `cemv check`: a path whose enumeration
// is complete passes unless the gate fails it or it is unbounded.
checker::CheckResult as_check_result(const model::Matrix& m, const DefeatsResult& r, const std::string& matrix_file,
                                     const std::string& out_dir, int require_distance) {
  checker::CheckResult c;
  c.matrix_name = r.matrix_name;
  c.matrix_signature = r.matrix_signature;
  c.tool_version = CEMV_VERSION;
  const auto gate = gate_failures(r, require_distance);
  for (const auto& p : r.paths) {
    checker::PropertyResult pr;
    pr.name = "defeats.sif" + std::to_string(p.path.sif) + "." + p.path.key();
    pr.description = summary(r, p);
    pr.kind = "defeats";
    pr.file = matrix_file;
    const bool gated = std::find(gate.begin(), gate.end(), &p) != gate.end();
    if (p.status == PathStatus::Unbounded || gated) {
      pr.verdict = checker::PropertyVerdict::Falsified;
      pr.method = gated ? "defeat distance " + distance_text(p, r.max_size) + " below --require-distance " +
                              std::to_string(require_distance)
                        : "the trip requirement fails with no action";
    } else if (p.status == PathStatus::Unknown) {
      pr.verdict = checker::PropertyVerdict::Unknown;
      pr.reason = p.reason;
    } else {
      pr.verdict = checker::PropertyVerdict::Proved;
      pr.method = "minimal defeat sets enumerated up to size " + std::to_string(r.max_size);
    }
    for (const auto& s : p.sets) {
      pr.notes.push_back(std::string(to_string(s.set_class)) + " " + set_text(m, p, s));
      const std::string& cx = p.questions[s.question].scenario;
      if (gated && pr.scenario_file.empty() && s.set_class == SetClass::Indirect && !cx.empty())
        pr.scenario_file = out_dir.empty() ? cx : out_dir + "/" + cx;
    }
    for (int id : p.path.causes) pr.matters.push_back("cause[" + std::to_string(id) + "].active");
    pr.matters.push_back("effect[" + std::to_string(p.path.effect) + "].active");
    c.properties.push_back(std::move(pr));
  }
  return c;
}

}  // namespace

std::string set_text(const model::Matrix& m, const PathDefeats& p, const DefeatSet& s) {
  std::string out = "{";
  for (std::size_t i = 0; i < s.actions.size(); ++i) out += (i ? ", " : "") + p.actions[s.actions[i]].description(m);
  return out + "}";
}

std::string defeats_report(const model::Matrix& m, const DefeatsResult& r, const std::string& matrix_file,
                           Format format, const std::string& out_dir, int require_distance) {
  switch (format) {
    case Format::Text: return text(r, require_distance);
    case Format::Json: return json(m, r, require_distance);
    case Format::Junit:
      return reports::check_report(as_check_result(m, r, matrix_file, out_dir, require_distance), {matrix_file},
                                   reports::CheckFormat::Junit);
    case Format::Sarif:
      return reports::check_report(as_check_result(m, r, matrix_file, out_dir, require_distance), {matrix_file},
                                   reports::CheckFormat::Sarif);
  }
  return "";
}

}  // namespace cemv::defeats
