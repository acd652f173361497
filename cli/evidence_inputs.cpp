#include "cli/evidence_inputs.hpp"

#include <nlohmann/json.hpp>

#include "cli/matrix_input.hpp"
#include "formats/diagnostics.hpp"
#include "formats/matrix_json.hpp"

namespace cemv::cli {

namespace {

using nlohmann::ordered_json;

// A JSON document with its file name: typed member access whose failures are
// load errors naming the file and the member.
class Doc {
 public:
  Doc(const std::string& file, const std::string& format, const model::Matrix& m) : name_(input_name(file)) {
    std::vector<formats::LoadIssue> issues;
    auto j = formats::parse_guarded_json(read_input(file), name_, issues, {256, format, 4});
    if (!j) throw formats::LoadError(issues);
    j_ = std::move(*j);
    if (!j_.is_object()) fail("", "expected a JSON object (" + format + ")");
    std::string got = str(j_, "format", "");
    if (got != format) fail("format", "is '" + got + "', expected '" + format + "'");
    std::string sig = str(j_, "signature", "");
    if (sig != formats::signature(m))
      fail("signature", "these results are for the matrix with signature " + sig + ", not for " + m.name +
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

}  // namespace cemv::cli
