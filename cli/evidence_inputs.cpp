#include "cli/evidence_inputs.hpp"

#include <map>
#include <nlohmann/json.hpp>

#include "cli/matrix_input.hpp"
#include "formats/diagnostics.hpp"
#include "formats/matrix_json.hpp"
#include "response/paths.hpp"

namespace cemv::cli {

namespace {

using nlohmann::ordered_json;

// A JSON document with its file name: typed member access whose failures are
// load errors naming the file and the member.
class Doc {
 public:
  // `format_key`, `signature_key`: where the file states them (cemv-defeats/1
  // writes "schema" and "matrix_signature", as cemv-response/1 does).
  Doc(const std::string& file, const std::string& format, const model::Matrix& m,
      const std::string& format_key = "format", const std::string& signature_key = "signature")
      : name_(input_name(file)) {
    std::vector<formats::LoadIssue> issues;
    auto j = formats::parse_guarded_json(read_input(file), name_, issues, {256, format, 4});
    if (!j) throw formats::LoadError(issues);
    j_ = std::move(*j);
    if (!j_.is_object()) fail("", "expected a JSON object (" + format + ")");
    std::string got = str(j_, format_key, "");
    if (got != format) fail(format_key, "is '" + got + "', expected '" + format + "'");
    std::string sig = str(j_, signature_key, "");
    if (sig != formats::signature(m))
      fail(signature_key, "these results are for the matrix with signature " + sig + ", not for " + m.name +
                            " as given (" + formats::signature(m) + "): regenerate them");
  }
  const ordered_json& root() const { return j_; }

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw formats::LoadError({formats::LoadIssue{where, what, name_}});
  }
  const ordered_json& member(const ordered_json& o, const std::string& key, const std::string& at) const {
    auto it = o.find(key);
    if (it == o.end()) fail(formats::member_path(at, key), "missing");
    return *it;
  }
  std::string str(const ordered_json& o, const std::string& key, const std::string& at) const {
    const auto& v = member(o, key, at);
    if (!v.is_string()) fail(formats::member_path(at, key), "expected a string");
    return v.get<std::string>();
  }
  // Optional text (a missing or null member is "").
  std::string text(const ordered_json& o, const std::string& key) const {
    auto it = o.find(key);
    return it != o.end() && it->is_string() ? it->get<std::string>() : "";
  }
  long long num(const ordered_json& o, const std::string& key, const std::string& at) const {
    const auto& v = member(o, key, at);
    if (!v.is_number_integer()) fail(formats::member_path(at, key), "expected a whole number");
    return v.get<long long>();
  }
  const ordered_json& array(const ordered_json& o, const std::string& key, const std::string& at) const {
    const auto& v = member(o, key, at);
    if (!v.is_array()) fail(formats::member_path(at, key), "expected an array");
    return v;
  }
  const ordered_json& object(const ordered_json& v, const std::string& at) const {
    if (!v.is_object()) fail(at, "expected an object");
    return v;
  }

 private:
  std::string name_;
  ordered_json j_;
};

}  // namespace

reports::CoverageFigures read_coverage(const std::string& file, const model::Matrix& m) {
  Doc d(file, "cemv-coverage/1", m);
  reports::CoverageFigures c;
  c.file = input_name(file);
  const auto& s = d.object(d.member(d.root(), "summary", ""), "summary");
  c.objectives = d.num(s, "objectives", "summary");
  c.covered = d.num(s, "covered", "summary");
  c.infeasible = d.num(s, "infeasible", "summary");
  c.undecided = d.num(s, "undecided", "summary");
  c.tests = d.num(s, "tests", "summary");
  c.steps = d.num(s, "steps", "summary");
  c.cycles = d.num(s, "cycles", "summary");
  const auto& objectives = d.array(d.root(), "objectives", "");
  for (std::size_t i = 0; i < objectives.size(); ++i) {
    const std::string at = formats::element_path("objectives", i);
    const auto& o = d.object(objectives[i], at);
    c.list.push_back({d.str(o, "id", at), d.str(o, "kind", at), d.str(o, "text", at), d.text(o, "element"),
                      d.str(o, "status", at), d.text(o, "test"), d.text(o, "method")});
  }
  const auto& tests = d.array(d.root(), "tests", "");
  for (std::size_t i = 0; i < tests.size(); ++i) {
    const std::string at = formats::element_path("tests", i);
    const auto& t = d.object(tests[i], at);
    c.test_list.push_back({d.str(t, "id", at), d.str(t, "file", at), d.num(t, "sif", at), d.num(t, "steps", at),
                           d.num(t, "cycles", at), d.array(t, "objectives", at).size()});
  }
  return c;
}

reports::MutationFigures read_mutation(const std::string& file, const model::Matrix& m) {
  Doc d(file, "cemv-mutation-report/1", m);
  reports::MutationFigures f;
  f.file = input_name(file);
  const auto& s = d.object(d.member(d.root(), "summary", ""), "summary");
  f.mutants = d.num(s, "mutants", "summary");
  f.equivalent = d.num(s, "equivalent", "summary");
  f.detected = d.num(s, "detected", "summary");
  f.survived = d.num(s, "survived", "summary");
  f.undecided = d.num(s, "undecided", "summary");
  f.refused = d.num(s, "refused", "summary");
  const auto& mutants = d.array(d.root(), "mutants", "");
  for (std::size_t i = 0; i < mutants.size(); ++i) {
    const std::string at = formats::element_path("mutants", i);
    const auto& mu = d.object(mutants[i], at);
    std::string status = d.str(mu, "status", at);
    if (status == "survived" || status == "undecided")
      f.open.push_back({d.str(mu, "id", at), d.text(mu, "operator"), d.text(mu, "element"),
                        d.text(mu, "description"), status});
  }
  return f;
}

reports::DefeatFigures read_defeats(const std::string& file, const model::Matrix& m) {
  Doc d(file, "cemv-defeats/1", m, "schema", "matrix_signature");
  reports::DefeatFigures f;
  f.file = input_name(file);
  f.max_size = static_cast<int>(d.num(d.root(), "max_size", ""));
  const auto& paths = d.array(d.root(), "paths", "");
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const std::string at = formats::element_path("paths", i);
    const auto& p = d.object(paths[i], at);
    reports::DefeatFigures::Path row;
    row.sif = static_cast<int>(d.num(p, "sif", at));
    row.sil = static_cast<int>(d.num(p, "sil", at));
    const auto sif = m.sif_groups.find(row.sif);
    row.sif_name = sif == m.sif_groups.end() ? "" : sif->second;
    std::string causes;
    const auto& cs = d.array(p, "causes", at);
    for (std::size_t k = 0; k < cs.size(); ++k)
      causes += (k ? "," : "") + std::to_string(cs[k].is_number_integer() ? cs[k].get<long long>() : 0);
    row.path = (cs.size() > 1 ? "causes " : "cause ") + causes;
    if (cs.size() > 1) row.path += " (" + std::to_string(d.num(p, "needed", at)) + "oo" + std::to_string(cs.size()) + ")";
    row.path += " -> effect " + std::to_string(d.num(p, "effect", at));
    const auto& t = d.member(p, "requirement_cycles", at);
    row.requirement = t.is_number_integer() ? std::to_string(t.get<long long>()) + " cycles" : "-";
    row.status = d.str(p, "status", at);
    const auto& dist = d.member(p, "distance", at);
    row.distance = dist.is_number_integer() ? std::to_string(dist.get<long long>())
                   : row.status == "complete" ? "> " + std::to_string(f.max_size)
                                              : "unknown";
    // The actions by key: what each touches.
    std::map<std::string, const ordered_json*> actions;
    const auto& as = d.array(p, "actions", at);
    for (std::size_t k = 0; k < as.size(); ++k)
      actions[d.str(d.object(as[k], at + ".actions"), "key", at + ".actions")] = &as[k];
    const auto& sets = d.array(p, "sets", at);
    for (std::size_t k = 0; k < sets.size(); ++k) {
      const std::string sat = formats::element_path(at + ".sets", k);
      const auto& s = d.object(sets[k], sat);
      reports::DefeatFigures::Set set;
      set.set_class = d.str(s, "class", sat);
      set.counterexample = d.text(s, "counterexample");
      for (const auto& key : d.array(s, "actions", sat)) {
        if (!key.is_string() || !actions.count(key.get<std::string>())) d.fail(sat, "an action the path does not list");
        const ordered_json& a = *actions.at(key.get<std::string>());
        set.actions.push_back(d.text(a, "description"));
        if (a.contains("cause") && a["cause"].is_number_integer()) {
          set.causes.push_back(a["cause"].get<int>());
          set.touches.push_back("cause " + std::to_string(set.causes.back()));
        }
        if (a.contains("effect") && a["effect"].is_number_integer()) {
          set.effects.push_back(a["effect"].get<int>());
          set.touches.push_back("effect " + std::to_string(set.effects.back()));
        }
        if (!d.text(a, "tag").empty()) set.touches.push_back("tag " + d.text(a, "tag"));
      }
      row.sets.push_back(std::move(set));
    }
    f.paths.push_back(std::move(row));
  }
  return f;
}

std::map<std::string, response::Figure> read_response_figures(const std::string& file, const model::Matrix& m,
                                                              const std::map<std::string, std::string>& keys) {
  Doc d(file, "cemv-response/1", m, "schema", "matrix_signature");
  std::map<std::string, response::Figure> out;
  const auto& paths = d.array(d.root(), "paths", "");
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const std::string at = formats::element_path("paths", i);
    const auto& p = d.object(paths[i], at);
    std::string k;
    for (const auto& c : d.array(p, "causes", at)) {
      if (!c.is_number_integer()) d.fail(at + ".causes", "expected whole numbers");
      k += std::to_string(c.get<long long>()) + ",";
    }
    k += ">" + std::to_string(d.num(p, "effect", at));
    const auto key = keys.find(k);
    if (key == keys.end()) d.fail(at, "no path of the matrix has these causes and this effect");
    const auto& t = d.member(p, "logic_cycles", at);
    const std::string verdict = d.str(p, "verdict", at);
    response::Figure f;
    if (t.is_number_integer() && t.get<long long>() >= 0) {
      f.kind = response::Figure::Kind::Exact;
      f.cycles = t.get<long long>();
    } else if (!t.is_null()) {
      d.fail(formats::member_path(at, "logic_cycles"), "expected a whole number of cycles or null");
    } else if (verdict == "unbounded") {
      f.kind = response::Figure::Kind::Unbounded;
    } else {
      continue;  // unknown there: decided again
    }
    f.counterexample = d.text(p, "counterexample");
    f.method = "cemv response (" + input_name(file) + ")";
    out[key->second] = f;
  }
  return out;
}

}  // namespace cemv::cli
