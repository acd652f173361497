// `cemv check MATRIX [PROPS...]`: prove or refute the properties of a matrix
// and report the verdicts as text, cemv-result/1 JSON, JUnit XML or SARIF
// (docs/checker.md). Exit 0 all proved/reachable, 1 something falsified,
// unreachable or vacuous, 2 invalid input, 3 unknown and nothing falsified,
// 4 internal error.
#include <charconv>
#include <chrono>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "checker/check.hpp"
#include "checker/prover.hpp"
#include "cli/check_gate.hpp"
#include "cli/commands.hpp"
#include "cli/explain_trace.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "cli/progress.hpp"
#include "cli/result_cache.hpp"
#include "cli/version.hpp"
#include "formats/matrix_json.hpp"
#include "properties/parser.hpp"
#include "properties/standard.hpp"
#include "reports/check_report.hpp"
#include "reports/timing_svg.hpp"
#include "reports/vcd.hpp"
#ifdef CEMV_WITH_VERIFICATION  // the product, not the CLI tests' checker double
#include "cli/counterexample_cells.hpp"
#endif

namespace cemv::cli {

namespace {

using checker::PropertyResult;
using checker::PropertyVerdict;

struct CheckArgs {
  std::string matrix_file;
  std::vector<std::string> property_files;
  bool standard = false;
  std::string format = "text";
  std::string out_dir;
  std::string vcd_file;  // --vcd: every counterexample and witness in one dump
  std::string report_file = "-";
  std::vector<std::string> extra_reports;  // --report FORMAT:FILE
  int jobs = 1;
  std::string shard;
  double timeout_s = 0.0;
  double total_timeout_s = 0.0;
  bool quiet = false;
  bool expect = false;        // --expect: verdicts against the `# expect:` comments
  std::string baseline_file;  // --baseline FILE: verdicts against an earlier cemv-result/1
  std::string cache_dir;      // --cache DIR: verdicts kept between runs
  std::string support = "core";  // --support full|core|off (docs/checker.md, "Support")
};

// --support's word as the checker's mode (CLI::IsMember checked it).
checker::SupportMode support_mode(const std::string& word) {
  if (word == "full") return checker::SupportMode::Full;
  if (word == "off") return checker::SupportMode::Off;
  return checker::SupportMode::Core;
}

// A usage error found after parsing (exit 2).
struct BadArguments : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "i/n" with 1 <= i <= n.
std::pair<int, int> parse_shard(const std::string& s) {
  auto slash = s.find('/');
  auto number = [&](std::string_view t, int& v) {
    auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    return ec == std::errc{} && end == t.data() + t.size();
  };
  int i = 0, n = 0;
  if (slash == std::string::npos || !number(std::string_view(s).substr(0, slash), i) ||
      !number(std::string_view(s).substr(slash + 1), n) || n < 1 || i < 1 || i > n)
    throw BadArguments("--shard '" + s + "': expected i/n with 1 <= i <= n, e.g. --shard 2/4");
  return {i, n};
}


// How many properties this run decides (files as given, then the standard
// set; shard i of n by position).
std::size_t planned_count(const std::vector<properties::PropertyFile>& files, int shard_index, int shard_count) {
  std::size_t n = 0, index = 0;
  for (const auto& f : files)
    for (std::size_t k = 0; k < f.properties.size(); ++k) n += checker::in_shard(index++, shard_index, shard_count);
  return n;
}

// One report to write: --format with -o, and each --report FORMAT:FILE.
struct Destination {
  reports::CheckFormat format;
  std::string format_name;
  std::string file;  // "-" = standard output
};

std::vector<Destination> destinations(const CheckArgs& a) {
  std::vector<Destination> out;
  auto add = [&](const std::string& format, const std::string& file, const std::string& option) {
    auto f = reports::check_format_from_string(format);
    if (!f) throw BadArguments(option + ": '" + format + "' is not a format; expected text, json, junit or sarif");
    if (file.empty()) throw BadArguments(option + ": no file");
    for (const auto& d : out)
      if (d.file == file) throw BadArguments(option + ": '" + file + "' is already a destination");
    out.push_back({*f, format, file});
  };
  add(a.format, a.report_file, "--format");
  for (const auto& spec : a.extra_reports) {
    auto colon = spec.find(':');
    if (colon == std::string::npos)
      throw BadArguments("--report '" + spec + "': expected FORMAT:FILE, e.g. --report sarif:cemv.sarif");
    add(spec.substr(0, colon), spec.substr(colon + 1), "--report '" + spec + "'");
  }
  return out;
}

// Beside each counterexample or witness scenario under --out, its timing
// diagram (NAME.svg) and its waveforms (NAME.vcd), named in the reports.
void write_pictures(const model::Matrix& m, checker::CheckResult& r) {
  const std::string suffix = ".scenario.json";
  for (auto& p : r.properties) {
    const std::string& f = p.scenario_file;
    if (!p.trace || f.size() <= suffix.size() || f.compare(f.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    std::string base = f.substr(0, f.size() - suffix.size());
    write_output(base + ".svg", reports::timing_svg(m, *p.trace, reports::diagram_of(p)));
    p.diagram_file = base + ".svg";
    std::string what = p.verdict == PropertyVerdict::Reachable ? "witness of " : "counterexample to ";
    write_output(base + ".vcd", reports::vcd(m, *p.trace, {"", CEMV_VERSION, what + p.name}));
    p.vcd_file = base + ".vcd";
  }
}

// Writes every report and, when none went to standard output, a one-line
// summary there.
void publish(const checker::CheckResult& r, const CheckArgs& a, const std::vector<Destination>& to,
             const reports::CheckReportInputs& in) {
  bool any_stdout = false;
  std::string written;
  for (const auto& d : to) {
    bool to_stdout = d.file == "-";
    any_stdout |= to_stdout;
    if (a.quiet && to_stdout && d.format == reports::CheckFormat::Text) continue;
    write_output(d.file, reports::check_report(r, in, d.format));
    if (!to_stdout) written += (written.empty() ? "" : ", ") + d.format_name + " to " + d.file;
  }
  // --quiet still names every property that did not pass (or not as
  // expected), a line each, so that a CI log is never empty on a failure.
  if (a.quiet) std::cerr << reports::check_findings(r, in) << std::flush;
  if (any_stdout || a.quiet) return;
  auto counts = reports::verdict_counts(r);
  std::string line = "cemv check: " + r.matrix_name + ": " + std::to_string(r.properties.size()) +
                     (r.properties.size() == 1 ? " property" : " properties");
  const char* sep = ": ";
  for (std::size_t v = 0; v < counts.size(); ++v)
    if (counts[v]) {
      line += sep + std::to_string(counts[v]) + " " +
              reports::verdict_name(static_cast<PropertyVerdict>(v));
      sep = ", ";
    }
  auto cached = std::count_if(r.properties.begin(), r.properties.end(), [](const PropertyResult& p) { return p.cached; });
  if (cached) line += "; " + std::to_string(cached) + " from the cache";
  line += std::string(r.interrupted ? "; interrupted" : "") + "; wrote " + written + "\n";
  write_output("-", line);
}

struct CheckedArguments {
  std::vector<Destination> outputs;
  std::pair<int, int> shard;  // index, count
};

// Arguments and destinations first: a mistake fails in milliseconds.
CheckedArguments checked_arguments(const CheckArgs& a) {
  std::vector<Destination> outputs = destinations(a);
  if (a.property_files.empty() && !a.standard)
    throw BadArguments("nothing to check: give property files, --standard, or both");
  if (a.jobs < 1) throw BadArguments("--jobs must be at least 1");
  if (a.timeout_s < 0 || a.total_timeout_s < 0) throw BadArguments("time limits must not be negative");
  int stdin_uses = (a.matrix_file == "-");
  for (const auto& f : a.property_files) stdin_uses += (f == "-");
  if (stdin_uses > 1) throw BadArguments("'-' (standard input) can be given only once");
  const std::pair<int, int> shard = a.shard.empty() ? std::pair{1, 1} : parse_shard(a.shard);
  for (const auto& d : outputs) check_writable(d.file);
  if (!a.out_dir.empty()) check_writable_directory(a.out_dir);
  if (!a.vcd_file.empty()) check_writable(a.vcd_file);
  return {std::move(outputs), shard};
}

std::vector<properties::PropertyFile> read_property_files(const CheckArgs& a, const model::Matrix& m) {
  std::vector<properties::PropertyFile> files;
  for (const auto& f : a.property_files)
    files.push_back(properties::parse_properties(read_input(f), m, input_name(f)));
  if (a.standard) files.push_back(properties::standard_properties(m));
  properties::check_distinct_names(files);  // reports and counterexample files are named after them
  if (!a.quiet)
    for (const auto& f : files)
      for (const auto& w : f.warnings) std::cerr << w << "\n";
  return files;
}

// What the report says of the run whatever the checker found: the files as
// given and the version of this binary.
checker::CheckResult run_description(const CheckArgs& a, const model::Matrix& m, int shard_count) {
  checker::CheckResult d;
  d.matrix_name = m.name;
  d.matrix_signature = formats::signature(m);
  d.tool_version = CEMV_VERSION;
  for (const auto& f : a.property_files) d.property_files.push_back(input_name(f));
  d.standard = a.standard;
  if (shard_count > 1) d.shard = a.shard;
  return d;
}

checker::CheckOptions check_options(const CheckArgs& a, std::pair<int, int> shard, checker::CancelToken& cancel) {
  const auto [shard_index, shard_count] = shard;
  checker::CheckOptions options;
  options.property_timeout_s = a.timeout_s;
  options.jobs = a.jobs;
  options.shard_index = shard_index;
  options.shard_count = shard_count;
  options.out_dir = a.out_dir;
  options.standard = a.standard;
  options.support_mode = support_mode(a.support);
  options.cancel = &cancel;
  return options;
}

std::optional<ResultCache> result_cache(const CheckArgs& a, const model::Matrix& m, const std::string& signature) {
  if (a.cache_dir.empty()) return std::nullopt;
  ResultCache::Confirm confirm;
#ifdef CEMV_WITH_VERIFICATION
  confirm = [&m](const properties::PropertyFile& f, const properties::Property& p, const PropertyResult& r) {
    return confirms(m, f, p, r);
  };
#endif
  // A result depends on the build and on how its support was found.
  return std::optional<ResultCache>(std::in_place, a.cache_dir, std::string(build_version()) + " --support " + a.support,
                                    m, signature, a.out_dir, confirm);
}

int internal_error(const std::string& what) {
  std::cerr << "internal error: " << what << "\n(a bug in cemv: please report it with the matrix and property files)\n";
  return 4;
}

// Counterexample files never overwrite each other: names are unique across
// the files (check_distinct_names), and each file is one property's.
std::optional<std::string> shared_scenario_file(const checker::CheckResult& result) {
  std::map<std::string, std::string> written;  // scenario file -> property
  for (const auto& p : result.properties)
    if (!p.scenario_file.empty())
      if (auto [it, fresh] = written.emplace(p.scenario_file, p.name); !fresh)
        return "properties " + it->second + " and " + p.name + " wrote one file " + p.scenario_file;
  return std::nullopt;
}

// --vcd: every counterexample and witness, a scope each; returns how many.
std::size_t write_waveforms(const CheckArgs& a, const model::Matrix& m, const checker::CheckResult& result) {
  std::vector<reports::VcdRun> runs;
  for (const auto& p : result.properties)
    if (p.trace) runs.push_back({p.name, &*p.trace});
  write_output(a.vcd_file, reports::vcd_runs(m, runs, {"", CEMV_VERSION, "counterexamples and witnesses of cemv check"}));
  return runs.size();
}

int run_check(const CheckArgs& a) {
  const auto [outputs, shard] = checked_arguments(a);
  reports::CheckReportInputs report_inputs{input_name(a.matrix_file), read_input(a.matrix_file)};
  const model::Matrix m = formats::parse_valid_matrix(report_inputs.matrix_text, report_inputs.matrix_file, "checked");
  const std::vector<properties::PropertyFile> files = read_property_files(a, m);
  const CheckGate gate(a.expect, a.baseline_file, files);  // a bad baseline fails before the work
  const checker::CheckResult description = run_description(a, m, shard.second);

  // --total-timeout cancels through the run's one token: every engine polls
  // it, the work queue starts nothing after it, and the checker returns with
  // what it decided; the rest is reported unknown ("time limit").
  checker::CancelToken cancel(a.total_timeout_s > 0
                                  ? checker::Clock::now() + std::chrono::duration_cast<checker::Clock::duration>(
                                                                std::chrono::duration<double>(a.total_timeout_s))
                                  : checker::Clock::time_point::max());
  checker::CheckOptions options = check_options(a, shard, cancel);
  // On a terminal (and not --quiet): properties done / total, elapsed, the running ones.
  Progress progress("cemv check", planned_count(files, options.shard_index, options.shard_count), "properties",
                    !a.quiet && Progress::terminal(), std::cerr);
  options.on_start = [&](const std::string& name) { progress.started(name); };
  options.on_result = [&](const PropertyResult& r) { progress.finished(r.name); };
  std::optional<ResultCache> cache = result_cache(a, m, description.matrix_signature);

  checker::CheckResult result;
  try {
    result = cache ? check_with_cache(*cache, m, files, options) : checker::check_properties(m, files, options);
  } catch (const OutputError&) {
    progress.stop();  // the cache's files: a failed write, exit 2
    throw;
  } catch (const std::exception& e) {
    progress.stop();
    // Inputs were checked above, so anything the checker throws is cemv's
    // fault: a re-check that refuted an answer (InternalError, whose message
    // carries both sides), or a failure of the engines themselves.
    bool refuted = dynamic_cast<const checker::InternalError*>(&e) != nullptr;
    return internal_error((refuted ? "" : "the checker failed: ") + std::string(e.what()));
  }
  progress.stop();
  if (result.interrupted && !a.quiet)
    std::cerr << "cemv check: the overall time limit of " << a.total_timeout_s
              << " s is up; properties not decided are reported unknown\n";

  // The checker fills these too; the CLI's values name the files as given.
  result.matrix_name = description.matrix_name;
  result.matrix_signature = description.matrix_signature;
  result.tool_version = description.tool_version;
  result.property_files = description.property_files;
  result.standard = description.standard;
  result.shard = description.shard;
  if (cache) cache->store(files, result);
#ifdef CEMV_WITH_VERIFICATION
  add_counterexample_cells(m, files, result);
#endif
  gate.annotate(result);
  if (auto shared = shared_scenario_file(result)) return internal_error(*shared);
  try {
    explain_results(m, files, result);  // "why, per step": the traces re-run with explanations
  } catch (const std::logic_error& e) {
    return internal_error(e.what());
  }
  write_pictures(m, result);
  const std::size_t runs = a.vcd_file.empty() ? 0 : write_waveforms(a, m, result);
  publish(result, a, outputs, report_inputs);
  bool machine_stdout = false;  // a JSON/JUnit/SARIF report on standard output takes no extra line
  for (const auto& d : outputs) machine_stdout |= d.file == "-" && d.format != reports::CheckFormat::Text;
  if (!a.vcd_file.empty() && !a.quiet && !machine_stdout)
    write_output("-", "waveforms: " + a.vcd_file + " (" + std::to_string(runs) + (runs == 1 ? " run" : " runs") +
                          ": every counterexample and witness)\n");
  if (gate.active() && !a.quiet) {
    if (machine_stdout) std::cerr << gate.summary(result) << std::flush;
    else write_output("-", gate.summary(result));
  }
  return gate.exit_code(result);
}

}  // namespace

void add_check_commands(CLI::App& app, Context& ctx) {
  auto* cmd = app.add_subcommand(
      "check", "Prove or refute the properties of a matrix (docs/checker.md)");
  static CheckArgs a;
  cmd->add_option("MATRIX", a.matrix_file, "cemv-matrix/1 file ('-' = standard input)")->required();
  cmd->add_option("PROPS", a.property_files, "property files (docs/properties.md)");
  cmd->add_flag("--standard", a.standard, "also check the standard properties derived from the matrix");
  cmd->add_option("--format", a.format, "report format: text, json (cemv-result/1), junit, sarif")
      ->capture_default_str();
  cmd->add_option("-o,--output", a.report_file, "write the report to FILE ('-' = standard output)")
      ->type_name("FILE");
  // One value per --report, so that a positional argument after it is not taken.
  cmd->add_option("--report", a.extra_reports,
                  "also write a report in FORMAT to FILE (repeatable), e.g. --report sarif:cemv.sarif")
      ->type_name("FORMAT:FILE")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--out", a.out_dir, "folder for counterexample scenarios, their timing diagrams (.svg) and waveforms (.vcd); created if missing")
      ->type_name("DIR");
  cmd->add_option("--vcd", a.vcd_file,
                  "write every counterexample and witness to FILE as one value change dump (VCD), a scope per property")
      ->type_name("FILE");
  cmd->add_option("--jobs", a.jobs, "worker threads over the properties")->capture_default_str();
  cmd->add_option("--shard", a.shard, "check only shard i of n (1 <= i <= n), for CI runners")
      ->type_name("i/n");
  cmd->add_option("--timeout", a.timeout_s, "wall-clock limit per property, seconds (0 = none)")
      ->type_name("S");
  cmd->add_option("--total-timeout", a.total_timeout_s,
                  "hard wall-clock limit for the whole run, seconds (0 = none)")
      ->type_name("S");
  cmd->add_flag("--expect", a.expect,
                "exit 0 when every verdict is the one its `# expect:` comment states (else a passing one), "
                "1 naming each that is not");
  cmd->add_option("--baseline", a.baseline_file,
                  "exit 0 when every verdict is the one an earlier run's cemv-result/1 FILE reports (else the "
                  "expected one), 1 naming each that is not")
      ->type_name("FILE");
  cmd->add_option("--cache", a.cache_dir,
                  "keep verdicts in DIR and skip properties decided there before (same matrix signature, "
                  "property text and cemv build)")
      ->type_name("DIR");
  cmd->add_option("--support", a.support,
                  "the cells each proof rests on: core (the proof's unsat core, re-checked; sound, maybe not "
                  "minimal), full (that core minimised by re-proving; minimal, costlier), off")
      ->check(CLI::IsMember({"full", "core", "off"}))
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", a.quiet, "print nothing but errors and a line per property that did not pass");
  cmd->footer(
      "Exit status: 0 every property proved or reachable; 1 some property falsified, unreachable\n"
      "or vacuous; 2 invalid input (matrix, property file, option, unwritable destination);\n"
      "3 some property unknown (time limit, bound) and nothing falsified; 4 internal error (an\n"
      "answer refuted by cemv's own re-check). With --expect or --baseline: 0 every verdict as\n"
      "expected, 1 some verdict not, 3 only unknown ones not.\n");
  cmd->callback([&ctx]() {
    try {
      ctx.exit_code = run_check(a);
    } catch (const BadArguments& e) {
      std::cerr << "error: check: " << e.what() << "\n";
      ctx.exit_code = 2;
    }
  });
}

}  // namespace cemv::cli
