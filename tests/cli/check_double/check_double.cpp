// TEST DOUBLE of checker::check_properties and of the property parser (see README.md).
// in_shard and exit_code are the real ones (inline in checker/check.hpp and
// checker/result.hpp), so the CLI tests exercise the real rules.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <utility>

#include "checker/check.hpp"
#include "checker/prover.hpp"
#include "formats/diagnostics.hpp"
#include "formats/matrix_json.hpp"
#include "properties/parser.hpp"
#include "properties/print.hpp"
#include "properties/standard.hpp"
#include "cli/explain_trace.hpp"

namespace cemv::checker {

namespace {

bool has(const std::string& s, const char* word) { return s.find(word) != std::string::npos; }

PropertyResult decide(const properties::PropertyFile& f, const properties::Property& p,
                      const CheckOptions& o) {
  static const char* kinds[] = {"invariant", "never", "reachable", "response"};
  PropertyResult r;
  r.name = p.name;
  r.description = p.description;
  r.kind = kinds[static_cast<int>(p.kind)];
  r.file = f.file_name;
  r.line = p.loc.line;
  r.column = p.loc.column;
  r.matters = {"effect[1].active", "cause[1].active"};
  r.seconds = 0.001;
  if (has(p.name, "internal")) throw InternalError("replayed trace does not violate '" + p.name + "'");
  if (has(p.name, "crash")) throw std::runtime_error("solver exception: out of memory");
  // Like every engine, a property that never ends by itself polls the
  // run's cancel token: --total-timeout ends it.
  if (has(p.name, "hang")) {
    while (!(o.cancel && o.cancel->cancelled())) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    r.verdict = PropertyVerdict::Unknown;
    r.unknown = UnknownReason::TimeLimit;
    r.reason = "time limit";
    return r;
  }
  if (has(p.name, "nap")) std::this_thread::sleep_for(std::chrono::milliseconds(200));
  if (has(p.name, "falsified") || (has(p.name, "reachable") && !has(p.name, "unreachable"))) {
    r.verdict = has(p.name, "falsified") ? PropertyVerdict::Falsified : PropertyVerdict::Reachable;
    r.method = "bmc";
    r.depth = 3;
    r.violation_cycle = 2;
    r.timing_table = "timing:\n  effect[1].active  1:0  3:1\n";
    if (!o.out_dir.empty()) {
      r.scenario_file = (std::filesystem::path(o.out_dir) / (p.name + ".json")).string();
      std::ofstream(r.scenario_file) << "{\"format\": \"cemv-scenario/1\", \"steps\": []}\n";
    }
  } else if (has(p.name, "unreachable")) {
    r.verdict = PropertyVerdict::Unreachable;
    r.method = "pdr";
  } else if (has(p.name, "vacuous")) {
    r.verdict = PropertyVerdict::Vacuous;
    r.reason = "the assumptions cannot hold together";
  } else if (has(p.name, "unknown")) {
    r.verdict = PropertyVerdict::Unknown;
    r.reason = "bound reached";
  } else {
    r.verdict = PropertyVerdict::Proved;
    r.method = "k-induction";
    r.depth = 1;
    r.support = {{"intersection[1,1]", "cause 1 -> effect 1"}};
    r.support_minimal = true;
  }
  return r;
}

}  // namespace

CheckResult check_properties(const model::Matrix& m, const std::vector<properties::PropertyFile>& files,
                  const CheckOptions& options) {
  CheckResult result;
  result.matrix_name = m.name;
  result.matrix_signature = formats::signature(m);
  result.tool_version = "double";
  std::size_t index = 0;
  for (const auto& f : files)
    for (const auto& p : f.properties)
      if (in_shard(index++, options.shard_index, options.shard_count)) {
        if (options.cancel && options.cancel->cancelled()) {
          PropertyResult r;
          r.name = p.name;
          r.file = f.file_name;
          r.line = p.loc.line;
          r.column = p.loc.column;
          r.kind = properties::to_string(p.kind);
          r.verdict = PropertyVerdict::Unknown;
          r.unknown = UnknownReason::TimeLimit;
          r.reason = "time limit";
          result.properties.push_back(r);
          continue;
        }
        result.properties.push_back(decide(f, p, options));
        if (options.on_result) options.on_result(result.properties.back());
      }
  result.interrupted = options.cancel && options.cancel->cancelled();
  return result;
}

}  // namespace cemv::checker

namespace cemv::properties {

PropertyFile parse_properties(std::string_view text, const model::Matrix&, const std::string& file_name) {
  static const std::pair<const char*, PropertyKind> kinds[] = {{"invariant", PropertyKind::Invariant},
                                                               {"never", PropertyKind::Never},
                                                               {"reachable", PropertyKind::Reachable},
                                                               {"response", PropertyKind::Response}};
  PropertyFile f;
  f.file_name = file_name;
  std::istringstream in{std::string(text)};
  std::string line, expect;
  for (int n = 1; std::getline(in, line); ++n) {
    std::istringstream words(line);
    std::string kind, name;
    if (line.rfind("# expect: ", 0) == 0) expect = line.substr(10);
    if (!(words >> kind) || kind[0] == '#') continue;
    Property p;
    bool known = false;
    for (const auto& [word, k] : kinds)
      if (kind == word) p.kind = k, known = true;
    int column = static_cast<int>(line.find(kind)) + 1;
    if (!known)
      throw formats::LoadError({formats::LoadIssue{file_name + ":" + std::to_string(n) + ":" + std::to_string(column),
                               "expected invariant, never, reachable or response, found '" + kind + "'"}});
    words >> name;
    std::getline(words >> std::ws, p.description);
    p.name = name;
    p.loc = {n, static_cast<int>(line.find(name, column)) + 1};
    p.expect = std::exchange(expect, "");
    f.properties.push_back(std::move(p));
  }
  return f;
}

std::string to_text(const Expr&, const model::InputTable&) { return "true"; }

std::string statement_text(const Property& p, const model::InputTable&) {
  static const char* kinds[] = {"invariant", "never", "reachable", "response"};
  return std::string(kinds[static_cast<int>(p.kind)]) + " " + p.name + " " + p.description;
}
// A stand-in: the rule is tested on the real parser and binary
// (tests/properties, tests/cli), not on the double's made-up files.
void check_distinct_names(const std::vector<PropertyFile>&) {}

PropertyFile standard_properties(const model::Matrix& m) {
  PropertyFile f;
  for (const auto& e : m.effects) {
    Property p;
    p.name = "std.effect[" + std::to_string(e.id) + "].reachable";
    p.kind = PropertyKind::Reachable;
    f.properties.push_back(std::move(p));
  }
  return f;
}

}  // namespace cemv::properties

namespace cemv::cli {

// The double's traces are made up: "why, per step" needs the runtime, which
// the double does not link (tests/cli/test_explain* test the real one).
void explain_results(const model::Matrix&, const std::vector<properties::PropertyFile>&, checker::CheckResult&) {}

}  // namespace cemv::cli
