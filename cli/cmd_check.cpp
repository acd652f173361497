// `cemv check MATRIX [PROPS...]`: prove or refute the properties of a matrix
// and report the verdicts as text, cemv-result/1 JSON, JUnit XML or SARIF
// (docs/checker.md). Exit 0 all proved/reachable, 1 something falsified,
// unreachable or vacuous, 2 invalid input, 3 unknown and nothing falsified,
// 4 internal error.
#include <atomic>
#include <charconv>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <iostream>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include "checker/check.hpp"
#include "checker/prover.hpp"
#include "cli/commands.hpp"
#include "cli/explain_trace.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "cli/progress.hpp"
#include "formats/matrix_json.hpp"
#include "properties/parser.hpp"
#include "properties/standard.hpp"
#include "reports/check_report.hpp"
#include "reports/timing_svg.hpp"
#include "reports/vcd.hpp"

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
};

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

const char* kind_name(properties::PropertyKind k) {
  switch (k) {
    case properties::PropertyKind::Invariant: return "invariant";
    case properties::PropertyKind::Never: return "never";
    case properties::PropertyKind::Reachable: return "reachable";
    case properties::PropertyKind::Response: return "response";
  }
  return "invariant";
}

// The properties this run decides, in the checker's order (files as given,
// then the standard set; shard i of n by position): what a report must list
// even when the run is cut short.
std::vector<PropertyResult> planned_properties(const std::vector<properties::PropertyFile>& files,
                                               int shard_index, int shard_count) {
  std::vector<PropertyResult> planned;
  std::size_t index = 0;
  for (const auto& f : files)
    for (const auto& p : f.properties) {
      if (!checker::in_shard(index++, shard_index, shard_count)) continue;
      PropertyResult r;
      r.name = p.name;
      r.description = p.description;
      r.kind = kind_name(p.kind);
      r.file = f.file_name;
      r.line = p.loc.line;
      r.column = p.loc.column;
      r.notes = p.notes;
      r.verdict = PropertyVerdict::Unknown;
      r.reason = "time limit";
      planned.push_back(std::move(r));
    }
  return planned;
}

std::vector<PropertyVerdict> verdicts_of(const checker::CheckResult& r) {
  std::vector<PropertyVerdict> v;
  for (const auto& p : r.properties) v.push_back(p.verdict);
  return v;
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
void publish(const checker::CheckResult& r, const CheckArgs& a, const std::vector<Destination>& to) {
  bool any_stdout = false;
  std::string written;
  for (const auto& d : to) {
    bool to_stdout = d.file == "-";
    any_stdout |= to_stdout;
    if (a.quiet && to_stdout && d.format == reports::CheckFormat::Text) continue;
    write_output(d.file, reports::check_report(r, {input_name(a.matrix_file)}, d.format));
    if (!to_stdout) written += (written.empty() ? "" : ", ") + d.format_name + " to " + d.file;
  }
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
  line += std::string(r.interrupted ? "; interrupted" : "") + "; wrote " + written + "\n";
  write_output("-", line);
}

// The hard wall-clock limit of --total-timeout. The checker gets a little less
// time and normally returns by itself; if it has not returned when the limit
// is up, this thread writes the result so far (the finished properties, the
// others unknown with reason "time limit", interrupted) and ends the process.
// Whoever reports first (the main thread after check() or this thread) is the
// only one that writes, so an output is never written twice or interleaved.
class Watchdog {
 public:
  Watchdog(double seconds, std::function<void()> on_expiry)
      : on_expiry_(std::move(on_expiry)),
        thread_([this, seconds] {
          std::unique_lock<std::mutex> lock(mutex_);
          if (!cv_.wait_for(lock, std::chrono::duration<double>(seconds), [this] { return cancelled_; }))
            on_expiry_();
        }) {}
  ~Watchdog() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      cancelled_ = true;
    }
    cv_.notify_all();
    thread_.join();
  }

 private:
  std::function<void()> on_expiry_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool cancelled_ = false;
  std::thread thread_;
};

int run_check(const CheckArgs& a) {
  // Arguments and destinations first: a mistake fails in milliseconds.
  const std::vector<Destination> outputs = destinations(a);
  if (a.property_files.empty() && !a.standard)
    throw BadArguments("nothing to check: give property files, --standard, or both");
  if (a.jobs < 1) throw BadArguments("--jobs must be at least 1");
  if (a.timeout_s < 0 || a.total_timeout_s < 0) throw BadArguments("time limits must not be negative");
  int stdin_uses = (a.matrix_file == "-");
  for (const auto& f : a.property_files) stdin_uses += (f == "-");
  if (stdin_uses > 1) throw BadArguments("'-' (standard input) can be given only once");
  auto [shard_index, shard_count] = a.shard.empty() ? std::pair{1, 1} : parse_shard(a.shard);
  for (const auto& d : outputs) check_writable(d.file);
  if (!a.out_dir.empty()) check_writable_directory(a.out_dir);
  if (!a.vcd_file.empty()) check_writable(a.vcd_file);

  const model::Matrix m = load_valid_matrix(a.matrix_file, "checked");
  std::vector<properties::PropertyFile> files;
  for (const auto& f : a.property_files)
    files.push_back(properties::parse_properties(read_input(f), m, input_name(f)));
  if (a.standard) files.push_back(properties::standard_properties(m));
  properties::check_distinct_names(files);  // reports and counterexample files are named after them
  if (!a.quiet)
    for (const auto& f : files)
      for (const auto& w : f.warnings) std::cerr << w << "\n";

  checker::CheckResult skeleton;
  skeleton.matrix_name = m.name;
  skeleton.matrix_signature = formats::signature(m);
  skeleton.tool_version = CEMV_VERSION;
  for (const auto& f : a.property_files) skeleton.property_files.push_back(input_name(f));
  skeleton.standard = a.standard;
  if (shard_count > 1) skeleton.shard = a.shard;

  checker::CheckOptions options;
  options.property_timeout_s = a.timeout_s;
  options.jobs = a.jobs;
  options.shard_index = shard_index;
  options.shard_count = shard_count;
  options.out_dir = a.out_dir;
  options.standard = a.standard;

  std::atomic<bool> reporting{false};  // set by whoever writes the report
  std::mutex finished_mutex;
  std::map<std::pair<std::string, std::string>, PropertyResult> finished;  // by (file, name)
  // On a terminal (and not --quiet): properties done / total, elapsed, the running ones.
  Progress progress("cemv check", planned_properties(files, shard_index, shard_count).size(), "properties",
                    !a.quiet && Progress::terminal(), std::cerr);
  options.on_start = [&](const std::string& name) { progress.started(name); };
  options.on_result = [&](const PropertyResult& r) {
    progress.finished(r.name);
    std::lock_guard<std::mutex> lock(finished_mutex);
    finished[{r.file, r.name}] = r;
  };

  std::optional<Watchdog> watchdog;
  if (a.total_timeout_s > 0) {
    double grace = std::min(0.5, a.total_timeout_s / 10);
    options.total_timeout_s = a.total_timeout_s - grace;
    watchdog.emplace(a.total_timeout_s, [&, shard_index = shard_index,
                                         shard_count = shard_count] {
      if (reporting.exchange(true)) return;  // the main thread is already reporting
      progress.stop();
      checker::CheckResult partial = skeleton;
      partial.interrupted = true;
      partial.properties = planned_properties(files, shard_index, shard_count);
      {
        std::lock_guard<std::mutex> lock(finished_mutex);
        for (auto& p : partial.properties)
          if (auto it = finished.find({p.file, p.name}); it != finished.end()) p = it->second;
      }
      int code = checker::exit_code(verdicts_of(partial));
      try {
        std::cerr << "cemv check: the overall time limit of " << a.total_timeout_s
                  << " s is up; properties not decided are reported unknown\n";
        publish(partial, a, outputs);
      } catch (const ClosedPipe&) {
      } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        code = 2;
      }
      ::_exit(code);  // the checker's threads cannot be stopped from here
    });
  }

  checker::CheckResult result;
  try {
    result = checker::check_properties(m, files, options);
  } catch (const std::exception& e) {
    progress.stop();
    // Inputs were checked above, so anything the checker throws is cemv's
    // fault: a re-check that refuted an answer (InternalError, whose message
    // carries both sides), or a failure of the engines themselves.
    if (reporting.exchange(true)) for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
    bool refuted = dynamic_cast<const checker::InternalError*>(&e) != nullptr;
    std::cerr << "internal error: " << (refuted ? "" : "the checker failed: ") << e.what()
              << "\n(a bug in cemv: please report it with the matrix and property files)\n";
    return 4;
  }
  // The watchdog fired while check() was returning: it writes and exits.
  if (reporting.exchange(true)) for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
  watchdog.reset();
  progress.stop();

  // The checker fills these too; the CLI's values name the files as given and
  // carry the version of this binary.
  result.matrix_name = skeleton.matrix_name;
  result.matrix_signature = skeleton.matrix_signature;
  result.tool_version = skeleton.tool_version;
  result.property_files = skeleton.property_files;
  result.standard = skeleton.standard;
  result.shard = skeleton.shard;
  // Counterexample files never overwrite each other: names are unique across
  // the files (check_distinct_names), and each file is one property's.
  std::map<std::string, std::string> written;  // scenario file -> property
  for (const auto& p : result.properties)
    if (!p.scenario_file.empty())
      if (auto [it, fresh] = written.emplace(p.scenario_file, p.name); !fresh) {
        std::cerr << "internal error: properties " << it->second << " and " << p.name << " wrote one file "
                  << p.scenario_file << "\n(a bug in cemv: please report it with the matrix and property files)\n";
        return 4;
      }
  try {
    explain_results(m, files, result);  // "why, per step": the traces re-run with explanations
  } catch (const std::logic_error& e) {
    std::cerr << "internal error: " << e.what() << "\n(a bug in cemv: please report it with the matrix and property files)\n";
    return 4;
  }
  write_pictures(m, result);
  std::vector<reports::VcdRun> runs;  // --vcd: every counterexample and witness, a scope each
  for (const auto& p : result.properties)
    if (p.trace) runs.push_back({p.name, &*p.trace});
  if (!a.vcd_file.empty())
    write_output(a.vcd_file, reports::vcd_runs(m, runs, {"", CEMV_VERSION, "counterexamples and witnesses of cemv check"}));
  publish(result, a, outputs);
  bool machine_stdout = false;  // a JSON/JUnit/SARIF report on standard output takes no extra line
  for (const auto& d : outputs) machine_stdout |= d.file == "-" && d.format != reports::CheckFormat::Text;
  if (!a.vcd_file.empty() && !a.quiet && !machine_stdout)
    write_output("-", "waveforms: " + a.vcd_file + " (" + std::to_string(runs.size()) +
                          (runs.size() == 1 ? " run" : " runs") + ": every counterexample and witness)\n");
  return checker::exit_code(verdicts_of(result));
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
  cmd->add_flag("-q,--quiet", a.quiet, "print nothing but errors");
  cmd->footer(
      "Exit status: 0 every property proved or reachable; 1 some property falsified, unreachable\n"
      "or vacuous; 2 invalid input (matrix, property file, option, unwritable destination);\n"
      "3 some property unknown (time limit, bound) and nothing falsified; 4 internal error (an\n"
      "answer refuted by cemv's own re-check).\n");
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
