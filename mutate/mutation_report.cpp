#include "mutate/mutation_report.hpp"

#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "checker/work_queue.hpp"
#include "formats/matrix_json.hpp"

namespace cemv::mutate {

using checker::EquivalenceVerdict;

const char* to_string(MutantStatus s) {
  switch (s) {
    case MutantStatus::Equivalent: return "equivalent";
    case MutantStatus::Detected: return "detected";
    case MutantStatus::Survived: return "survived";
    case MutantStatus::Undecided: return "undecided";
  }
  return "undecided";
}

int MutationReport::exit_code() const {
  if (survived > 0) return 1;
  if (undecided > 0) return 3;
  return 0;
}

namespace {

// A mutant that differs only by interface (docs/mutation.md, "Interface-only
// mutants"): status fields that only one version has, e.g. a comment cause
// made `normal` whose cells are all `*`. No test of the original can expect
// a field the original does not have, so a suite cannot detect it by
// replay; what the original's tests can observe is the observables both
// versions have. When those are proved equal in every reachable state, the
// mutant is equivalent on the common observables: its only difference is
// its interface, which the structural comparison (`cemv diff`, the
// signature on the checklist) shows. A difference on them is a survivor as
// usual.
checker::GroupEquivalence common_observables(const model::Matrix& a, const model::Matrix& b,
                                             const checker::GroupEquivalence& by_interface,
                                             const checker::EquivalenceOptions& eo) {
  const checker::ObservableGroup ga = checker::whole_matrix(a, a), gb = checker::whole_matrix(b, b);
  const std::set<std::string> in_b(gb.keys.begin(), gb.keys.end());
  checker::ObservableGroup common;
  common.name = "common observables";
  for (const auto& k : ga.keys)
    if (in_b.count(k)) common.keys.push_back(k);
  checker::GroupEquivalence r = checker::decide_equivalence(a, b, common, eo);
  if (r.verdict != EquivalenceVerdict::Equivalent) return r;
  r.reason = "equivalent on every observable both versions have (" + r.method +
             "); the interface differs: " + by_interface.reason;
  r.rest_on(checker::EquivalenceBasis::InterfaceOnly);
  return r;
}

}  // namespace

MutationReport mutation_report(const model::Matrix& m, const testgen::TestSuite& suite,
                               const MutationOptions& options) {
  MutationReport r;
  r.matrix_name = m.name;
  r.signature = formats::signature(m);
  const MutantSet set = mutants(m);
  r.refused = set.refused.size();
  std::vector<std::pair<std::string, std::string>> texts;
  for (const auto& t : suite.tests) texts.emplace_back(t.file_name, t.scenario_json);
  checker::CancelToken own;
  checker::CancelToken& cancel = options.cancel ? *options.cancel : own;
  checker::EquivalenceOptions eo;
  eo.work = options.work;
  eo.timeout_s = options.timeout_s;
  eo.cancel = &cancel;
  // Each mutant undecided until its task decides it: the cancel token may
  // end the run first.
  for (const auto& mu : set.mutants) {
    MutantOutcome o{mu.id, mu.op, mu.element, mu.description, MutantStatus::Undecided, {}, {}};
    o.equivalence.unknown = checker::UnknownReason::TimeLimit;
    o.equivalence.reason = checker::to_string(o.equivalence.unknown);
    r.mutants.push_back(std::move(o));
  }
  checker::WorkQueue(options.jobs, cancel).run(set.mutants.size(), [&](std::size_t mi) {
    const auto& mu = set.mutants[mi];
    MutantOutcome o{mu.id, mu.op, mu.element, mu.description, MutantStatus::Undecided, {}, {}};
    const testgen::ReplayResult replay = testgen::replay_verdicts(mu.matrix, texts);  // only which tests fail
    bool by_expectation = false;
    for (const auto& t : replay.tests)
      if (!t.passed) {
        o.failing_tests.push_back(t.name);
        by_expectation |= t.load_error.empty();
      }
    if (by_expectation) {
      // The suite replays green on the original: a failed expectation on the
      // mutant is a runtime run on which the two differ.
      o.status = MutantStatus::Detected;
      o.equivalence.verdict = EquivalenceVerdict::Differs;
      o.equivalence.rest_on(checker::EquivalenceBasis::Suite);
    } else {
      // Not detected, or only because a test no longer loads (the mutant
      // lost a tag the test sets): the product decides.
      o.equivalence = checker::decide_equivalence(m, mu.matrix, checker::whole_matrix(m, mu.matrix), eo);
      const bool detected = !o.failing_tests.empty();
      if (!detected && o.equivalence.verdict == EquivalenceVerdict::Differs && o.equivalence.basis == checker::EquivalenceBasis::Interface)
        o.equivalence = common_observables(m, mu.matrix, o.equivalence, eo);
      o.status = o.equivalence.verdict == EquivalenceVerdict::Equivalent ? MutantStatus::Equivalent
                 : o.equivalence.verdict == EquivalenceVerdict::Unknown  ? MutantStatus::Undecided
                 : detected                                               ? MutantStatus::Detected
                                                                          : MutantStatus::Survived;
    }
    r.mutants[mi] = std::move(o);
  });
  for (const auto& o : r.mutants) switch (o.status) {
      case MutantStatus::Equivalent:
        ++r.equivalent;
        r.interface_only += o.equivalence.basis == checker::EquivalenceBasis::InterfaceOnly;
        break;
      case MutantStatus::Detected: ++r.detected; break;
      case MutantStatus::Survived: ++r.survived; break;
      case MutantStatus::Undecided: ++r.undecided; break;
    }
  return r;
}

std::string report_json(const MutationReport& r) {
  using json = nlohmann::ordered_json;
  json j;
  j["format"] = "cemv-mutation-report/1";
  j["matrix"] = r.matrix_name;
  j["signature"] = r.signature;
  j["summary"] = json{{"mutants", r.mutants.size()}, {"equivalent", r.equivalent}, {"detected", r.detected},
                      {"survived", r.survived}, {"undecided", r.undecided}, {"refused", r.refused},
                      {"interface_only", r.interface_only}};
  json list = json::array();
  for (const auto& o : r.mutants) {
    json x{{"id", o.id}, {"operator", o.op}, {"element", o.element}, {"description", o.description},
           {"status", to_string(o.status)}, {"method", o.equivalence.method}};
    if (!o.failing_tests.empty()) x["failing_tests"] = o.failing_tests;
    if (!o.equivalence.reason.empty()) x["reason"] = o.equivalence.reason;
    if (o.equivalence.distinction) {
      const auto& d = *o.equivalence.distinction;
      x["distinction"] = json{{"key", d.key}, {"cycle", d.cycle + 1}, {"original", d.value_a}, {"mutant", d.value_b}};
    }
    list.push_back(x);
  }
  j["mutants"] = list;
  return j.dump(1) + "\n";
}

std::string report_markdown(const MutationReport& r) {
  std::ostringstream o;
  o << "# Mutation report: " << r.matrix_name << "\n\nSignature `" << r.signature << "`\n\n";
  o << "| mutants | equivalent | detected | survived | undecided |\n| --- | --- | --- | --- | --- |\n";
  o << "| " << r.mutants.size() << " | " << r.equivalent << " | " << r.detected << " | " << r.survived << " | "
    << r.undecided << " |\n\n";
  if (r.interface_only)
    o << r.interface_only << " of the equivalent mutants differ only by interface: equal on every observable both "
                             "versions have, with status fields only one has (docs/mutation.md).\n\n";
  o << "| mutant | element | change | status | evidence |\n| --- | --- | --- | --- | --- |\n";
  for (const auto& m : r.mutants) {
    std::string ev;
    if (!m.failing_tests.empty()) ev = "fails " + m.failing_tests.front();
    else if (m.equivalence.distinction)
      ev = m.equivalence.distinction->key + " in cycle " + std::to_string(m.equivalence.distinction->cycle + 1);
    else ev = m.equivalence.method + (m.equivalence.reason.empty() ? "" : ": " + m.equivalence.reason);
    o << "| " << m.id << " | " << m.element << " | " << m.description << " | " << to_string(m.status) << " | " << ev
      << " |\n";
  }
  return o.str();
}

}  // namespace cemv::mutate
