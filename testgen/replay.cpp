// `cemv replay`: scenarios run on the reference runtime, every expectation
// checked by the one expectation loop of formats/scenario.hpp, pass or fail
// per test and per step.
#include <algorithm>
#include <map>

#include "formats/diagnostics.hpp"
#include "formats/scenario.hpp"
#include "runtime/runtime.hpp"
#include "testgen/testgen.hpp"

namespace cemv::testgen {

namespace {

// A scenario on another implementation (ReplayTarget): only the expectations
// it has values for are checked, the others counted as skipped.
TestOutcome replay_on_target(const model::Matrix& m, formats::Scenario sc, TestOutcome out, ReplayTarget& target) {
  for (auto& step : sc.steps) {
    std::vector<formats::Expectation> kept;
    for (auto& x : step.expect)
      if (target.observes(x.target)) kept.push_back(x);
      else ++out.skipped;
    step.expect = std::move(kept);
  }
  formats::ExpandedScenario ex = formats::expand_scenario(sc, m);
  for (const auto& in : ex.cycles)
    if (std::string why = target.cannot_run(in); !why.empty()) {
      out.not_run = why;
      return out;
    }
  target.start();
  formats::ExpectationChecker checker(ex);
  out.steps.resize(sc.steps.size());
  for (std::size_t s = 0; s < sc.steps.size(); ++s) out.steps[s].step = s;
  for (std::size_t k = 0; k < ex.cycles.size(); ++k) {
    target.step(ex.cycles[k]);
    out.steps[ex.step_of_cycle[k]].cycle = k;
    for (const auto& r : checker.after_cycle(k, [&](const formats::ExpectTarget& t) { return target.value(t); }))
      if (!r.ok) {
        out.steps[r.step].passed = false;
        out.steps[r.step].failures.push_back(r.failure_text(m.cycle_ms));
      }
  }
  out.cycles = ex.cycles.size();
  out.expectations = checker.checked();
  out.failed = checker.failed();
  out.passed = out.failed == 0;
  return out;
}

TestOutcome replay_one(const model::Matrix& m, const std::string& name, const std::string& text,
                       const std::vector<model::Observable>& obs, const std::map<std::string, std::size_t>& index,
                       ReplayTarget* target, bool stop_at_failure) {
  TestOutcome out;
  out.name = name;
  formats::Scenario sc;
  try {
    sc = formats::parse_scenario(text, m, name);
  } catch (const formats::LoadError& e) {
    for (const auto& issue : e.issues()) out.load_error += (out.load_error.empty() ? "" : "\n") + issue.str();
    return out;
  }
  if (target) return replay_on_target(m, std::move(sc), std::move(out), *target);
  formats::ExpandedScenario ex = formats::expand_scenario(sc, m);
  runtime::Runtime rt(m);
  formats::ExpectationChecker checker(ex);
  out.steps.resize(sc.steps.size());
  for (std::size_t s = 0; s < sc.steps.size(); ++s) out.steps[s].step = s;
  // Observables are read where an expectation asks for them, not snapshot
  // every cycle: a suite of 8 h tests is 1.15 M cycles, replayed on every
  // mutant (cemv mutate --suite).
  for (std::size_t k = 0; k < ex.cycles.size(); ++k) {
    rt.step(ex.cycles[k]);
    out.steps[ex.step_of_cycle[k]].cycle = k;
    auto actual = [&](const formats::ExpectTarget& t) -> std::optional<int> {
      if (t.kind == formats::ExpectTarget::Kind::OutputTag) {
        auto v = rt.output(t.output_tag);
        if (!v) return std::nullopt;
        return static_cast<int>(*v);
      }
      auto it = index.find(t.observable.key);
      if (it == index.end()) return std::nullopt;
      return rt.value(obs[it->second]);
    };
    for (const auto& r : checker.after_cycle(k, actual))
      if (!r.ok) {
        out.steps[r.step].passed = false;
        out.steps[r.step].failures.push_back(r.failure_text(m.cycle_ms));
      }
    out.cycles = k + 1;
    if (stop_at_failure && checker.failed() > 0) break;
  }
  out.expectations = checker.checked();
  out.failed = checker.failed();
  out.passed = out.failed == 0;
  return out;
}

ReplayResult replay_all(const model::Matrix& m, const std::vector<std::pair<std::string, std::string>>& scenarios,
                        ReplayTarget* target, bool stop_at_failure) {
  const auto obs = model::observables(m);
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < obs.size(); ++i) index[obs[i].key] = i;
  ReplayResult r;
  for (const auto& [name, text] : scenarios)
    r.tests.push_back(replay_one(m, name, text, obs, index, target, stop_at_failure));
  return r;
}

}  // namespace

bool ReplayResult::all_passed() const {
  return std::all_of(tests.begin(), tests.end(), [](const TestOutcome& t) { return t.passed; });
}

std::size_t ReplayResult::passed() const {
  return static_cast<std::size_t>(std::count_if(tests.begin(), tests.end(), [](const TestOutcome& t) { return t.passed; }));
}

ReplayResult replay_texts(const model::Matrix& m, const std::vector<std::pair<std::string, std::string>>& scenarios,
                          ReplayTarget* target) {
  return replay_all(m, scenarios, target, false);
}

ReplayResult replay_verdicts(const model::Matrix& m,
                             const std::vector<std::pair<std::string, std::string>>& scenarios) {
  return replay_all(m, scenarios, nullptr, true);
}

ReplayResult replay_suite(const model::Matrix& m, const TestSuite& suite) {
  std::vector<std::pair<std::string, std::string>> texts;
  for (const auto& t : suite.tests) texts.push_back({t.file_name, t.scenario_json});
  return replay_texts(m, texts);
}

ReplayResult replay_files(const model::Matrix& m, const std::vector<std::filesystem::path>& paths,
                          ReplayTarget* target) {
  std::vector<std::filesystem::path> files;
  for (const auto& p : paths) {
    std::error_code ec;
    if (std::filesystem::is_directory(p, ec)) {
      std::vector<std::filesystem::path> in;
      for (const auto& e : std::filesystem::directory_iterator(p, ec))
        if (e.is_regular_file() && e.path().extension() == ".json" &&
            e.path().filename().string().find(".scenario.") != std::string::npos)
          in.push_back(e.path());
      std::sort(in.begin(), in.end());
      if (in.empty()) throw formats::LoadError({{p.string(), "no *.scenario.json files in this folder"}});
      files.insert(files.end(), in.begin(), in.end());
    } else {
      files.push_back(p);
    }
  }
  std::vector<std::pair<std::string, std::string>> texts;
  for (const auto& f : files) texts.push_back({f.string(), formats::read_text_file(f)});
  return replay_texts(m, texts, target);
}

}  // namespace cemv::testgen
