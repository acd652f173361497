// `cemv evidence MATRIX [PROPS...] --out report.html`: the evidence report for
// an assessor (docs/reports.md, "Evidence report"): the matrix, its validation,
// every property checked as `cemv check` checks it (with the timing diagram of
// each counterexample), the response time of every SIF path with --response
// (response/analysis.hpp, as `cemv response` computes it), the test-generation
// and mutation figures when given, the signature, version and date on every
// page. The date is SOURCE_DATE_EPOCH when set (the
// reproducible-builds convention), else now. Exit 0 when the report is
// written, whatever the verdicts (the report says them); 2 invalid input;
// 4 internal error (an answer refuted by the re-check).
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "checker/check.hpp"
#include "checker/prover.hpp"
#include "cli/commands.hpp"
#ifdef CEMV_WITH_PLC
#include "cli/plc_program.hpp"
#include "model/text.hpp"
#include "plc_check/check.hpp"
#endif
#include "cli/matrix_input.hpp"
#include "cli/evidence_inputs.hpp"
#include "cli/explain_trace.hpp"
#include "cli/output.hpp"
#include "cli/progress.hpp"
#include "formats/acceptance.hpp"
#include "formats/diagnostics.hpp"
#include "formats/matrix_json.hpp"
#include "model/validate.hpp"
#include "properties/parser.hpp"
#include "properties/print.hpp"
#include "properties/standard.hpp"
#include "reports/evidence.hpp"
#ifdef CEMV_WITH_RESPONSE
#include "response/analysis.hpp"
#endif

namespace cemv::cli {

namespace {

struct EvidenceArgs {
  std::string matrix_file;
  std::vector<std::string> property_files;
  bool standard = false;
  std::string out_file;
  std::string coverage_file;
  std::string acceptance_file;
  std::string mutation_file;
  std::string defeats_file;
  std::string json_file;
  bool response = false;
  double timeout_s = 0.0;  // --timeout: per property (0 = none, as `cemv check`: the clock bounds only what the user asks)
  double total_timeout_s = 0.0;  // --total-timeout: the whole run (0 = none)
  std::string support = "core";  // --support full|core|off, as `cemv check`
  int jobs = 1;
  bool quiet = false;
  std::string plc, map, pou;  // --plc: the program proved against the matrix (docs/plc.md)
};

struct BadArguments : std::runtime_error {
  using std::runtime_error::runtime_error;
};

#ifdef CEMV_WITH_RESPONSE
// The paths of `cemv response` as the report's plain rows (reports/ cannot
// use response/, which sits above it).
reports::ResponseFigures response_figures(const model::Matrix& m, const response::ResponseResult& r) {
  reports::ResponseFigures f;
  f.controller = std::to_string(r.paths.empty() ? 2 * m.cycle_ms : r.paths.front().controller_ms) + " ms, 2 x " +
                 (r.conservative ? "watchdog_ms" : "cycle_ms");
  for (const auto& p : r.paths) {
    reports::ResponseFigures::Path row;
    row.sif = p.path.sif;
    row.sif_name = p.sif_name;
    std::string causes;
    for (std::size_t i = 0; i < p.path.causes.size(); ++i) causes += (i ? "," : "") + std::to_string(p.path.causes[i]);
    row.path = (p.path.causes.size() > 1 ? "causes " : "cause ") + causes;
    if (p.path.causes.size() > 1)
      row.path += " (" + std::to_string(p.path.needed) + "oo" + std::to_string(p.path.causes.size()) + ")";
    row.path += " -> effect " + std::to_string(p.path.effect);
    switch (p.logic.kind) {
      case response::Figure::Kind::Exact:
        row.logic = std::to_string(p.logic.cycles) + " cycles (" + std::to_string(p.logic.cycles * m.cycle_ms) + " ms)";
        break;
      case response::Figure::Kind::Unbounded:
        row.logic = "unbounded (held off " + std::to_string(p.logic.cycles) + " cycles)";
        break;
      case response::Figure::Kind::Unknown: row.logic = "unknown: " + p.logic.reason; break;
    }
    row.total_ms = p.total_ms;
    if (p.process_safety_time_ms) row.process_safety_time_ms = *p.process_safety_time_ms;
    row.margin_ms = p.margin_ms;
    row.margin_percent = p.margin_percent;
    row.degraded_total_ms = p.degraded_total_ms;
    row.verdict = response::to_string(p.verdict);
    f.paths.push_back(std::move(row));
  }
  return f;
}
#endif

std::string report_date() {
  if (const char* e = std::getenv("SOURCE_DATE_EPOCH"); e && *e) {
    char* end = nullptr;
    long long v = std::strtoll(e, &end, 10);
    if (*end != '\0' || v < 0) throw std::runtime_error("SOURCE_DATE_EPOCH '" + std::string(e) + "' is not a Unix time");
    return reports::utc_date(v);
  }
  auto now = std::chrono::system_clock::now().time_since_epoch();
  return reports::utc_date(std::chrono::duration_cast<std::chrono::seconds>(now).count());
}

#ifdef CEMV_WITH_PLC
std::string value_text(const plc::Value& v) {
  if (v.type == plc::Type::Bool) return v.integer ? "TRUE" : "FALSE";
  return plc::literal_text(v);
}

// The chapter's data from the program, its completed map and plc_check's results.
reports::PlcFigures plc_figures(const PlcProgram& p, const plc_check::PlcCheckReport& r) {
  reports::PlcFigures f;
  f.file = p.file;
  f.sha256 = p.sha256;
  f.pou = p.pou;
  f.relation = r.relation == plc_check::Relation::Equal ? "equal" : "safe-side";
  f.map_source = p.map_source;
  f.scan_ms = p.map.scan_ms;
  f.assumptions = p.map.assumptions;
  const auto& map = p.map.map;
  for (const auto& b : map.inputs)
    f.map.push_back({"input tag " + b.tag, b.variable,
                     !b.variable.empty()
                         ? (!b.bad_quality.empty() ? "bad quality: " + b.bad_quality
                            : b.good_quality       ? "good quality declared"
                                                   : "")
                         : "held at " + model::float_text(static_cast<float>(b.value.value_or(0.0)))});
  for (const auto& b : map.outputs)
    f.map.push_back({"output tag " + b.tag + (b.effect ? " of effect " + std::to_string(b.effect) : ""), b.variable, ""});
  for (const auto& b : map.commands) {
    std::string what = std::string("command ") + model::to_string(b.op);
    if (b.cause) what += " cause " + std::to_string(b.cause);
    if (b.effect) what += " effect " + std::to_string(b.effect);
    if (b.tag) what += " tag " + std::to_string(b.tag);
    if (!b.tag_name.empty()) what += " " + b.tag_name;
    if (b.on) what += *b.on ? " on" : " off";
    f.map.push_back({what, b.variable, b.variable.empty() ? "declared unused: never issued" : "TRUE in the scan issued"});
  }
  for (const auto& h : map.program_inputs)
    f.map.push_back({"program input", h.variable, "held at " + model::float_text(static_cast<float>(h.value))});
  for (const auto& o : r.outputs) {
    reports::PlcFigures::Output x;
    x.tag = o.question.tag;
    x.effect = o.question.effect;
    x.variable = o.question.variable;
    x.verdict = plc_check::to_string(o.verdict);
    x.method = o.method;
    x.reason = o.reason;
    x.k = o.k;
    if (o.difference) {
      const auto& d = *o.difference;
      x.scan = d.scan + 1;
      x.matrix_value = d.matrix_values.back();
      x.program_value = d.program_values.back();
      if (d.assigned_at)
        x.assigned_at = p.file + ":" + std::to_string(d.assigned_at->line) + ":" + std::to_string(d.assigned_at->column);
      for (std::size_t k = 0; k < d.program_values.size(); ++k) {
        std::string changed;
        for (const auto& [name, v] : d.program_inputs[k]) {
          const bool same = k > 0 && d.program_inputs[k - 1].count(name) && d.program_inputs[k - 1].at(name) == v;
          if (!same) changed += (changed.empty() ? "" : ", ") + name + " = " + value_text(v);
        }
        x.scans.push_back({static_cast<int>(k + 1), d.matrix_values[k], d.program_values[k], changed});
      }
    }
    f.outputs.push_back(std::move(x));
  }
  f.interrupted = r.interrupted;
  return f;
}
#endif

// The property files (parsed only for a valid matrix) and the standard set;
// the report lists each file with its hash.
std::vector<properties::PropertyFile> read_property_files(const EvidenceArgs& a, const model::Matrix& m, bool valid,
                                                          reports::EvidenceInputs& in) {
  std::vector<properties::PropertyFile> files;
  const model::InputTable inputs(m);
  for (const auto& f : a.property_files) {
    const std::string text = read_input(f);
    reports::PropertyFileInfo info{input_name(f), formats::sha256_hex(text), 0, {}, {}};
    if (valid) {
      files.push_back(properties::parse_properties(text, m, input_name(f)));
      info.properties = files.back().properties.size();
      for (const auto& as : files.back().assumptions) info.assumptions.push_back("assume " + properties::to_text(as.expr, inputs));
      info.warnings = files.back().warnings;
    }
    in.property_files.push_back(std::move(info));
  }
  if (valid && a.standard) files.push_back(properties::standard_properties(m));
  properties::check_distinct_names(files);  // reports and counterexample files are named after them
  if (!a.quiet)
    for (const auto& f : files)
      for (const auto& w : f.warnings) std::cerr << w << "\n";
  return files;
}

// The formal text of every property, as the report prints it.
void add_property_texts(const model::Matrix& m, const std::vector<properties::PropertyFile>& files,
                        reports::EvidenceInputs& in) {
  const model::InputTable inputs(m);
  for (const auto& f : files)
    for (const auto& p : f.properties) {
      reports::PropertyText t{f.file_name, p.name, properties::statement_text(p, inputs), {}};
      for (const auto& as : f.assumptions)
        t.assumptions.push_back("assume " + properties::to_text(as.expr, inputs) + " (every property of the file)");
      for (const auto& as : p.assumptions) t.assumptions.push_back("assume " + properties::to_text(as.expr, inputs));
      in.texts.push_back(std::move(t));
    }
}

// The records other commands wrote: coverage, the signed acceptance record
// (of this matrix version only), mutation and defeat sets.
void read_records(const EvidenceArgs& a, const model::Matrix& m, bool valid, reports::EvidenceInputs& in) {
  if (!a.coverage_file.empty()) in.coverage = read_coverage(a.coverage_file, m);
  if (!a.acceptance_file.empty()) {
    in.acceptance = formats::read_acceptance(read_input(a.acceptance_file), input_name(a.acceptance_file));
    in.acceptance_file = input_name(a.acceptance_file);
    if (in.acceptance->signature != formats::signature(m))
      throw formats::LoadError({{input_name(a.acceptance_file),
                                 "the acceptance record is for the matrix with signature " + in.acceptance->signature +
                                     ", not " + formats::signature(m) + " (record the checklists of this version)"}});
  }
  if (!a.mutation_file.empty()) in.mutation = read_mutation(a.mutation_file, m);
  if (!a.defeats_file.empty() && valid) in.defeats = read_defeats(a.defeats_file, m);
}

checker::CheckOptions check_options(const EvidenceArgs& a, checker::CancelToken& cancel) {
  checker::CheckOptions options;
  options.property_timeout_s = a.timeout_s;
  options.cancel = &cancel;
  options.support_mode = a.support == "full"  ? checker::SupportMode::Full
                         : a.support == "off" ? checker::SupportMode::Off
                                              : checker::SupportMode::Core;
  options.jobs = a.jobs;
  options.standard = a.standard;
  return options;
}

// What is left of --total-timeout, for a later phase (0: no bound).
double seconds_left(const EvidenceArgs& a, checker::Clock::time_point deadline) {
  if (a.total_timeout_s <= 0) return 0.0;
  return std::max(1e-3, std::chrono::duration<double>(deadline - checker::Clock::now()).count());
}

#ifdef CEMV_WITH_RESPONSE
// The response time of every SIF path; true when the time limit cut it short.
bool add_response(const EvidenceArgs& a, const model::Matrix& m, checker::Clock::time_point deadline,
                  Progress& progress, reports::EvidenceInputs& in) {
  progress.phase("cemv evidence: response time", response::response_paths(m, {}).size(), "paths");
  progress.started("every SIF path");
  response::ResponseOptions ro;
  ro.timeout_s = a.timeout_s;
  ro.total_timeout_s = seconds_left(a, deadline);
  ro.jobs = a.jobs;
  const response::ResponseResult rr = response::analyse(m, ro);
  in.response = response_figures(m, rr);
  return rr.interrupted;
}
#endif

#ifdef CEMV_WITH_PLC
// The PLC program's chapter: every output decided as `cemv plc-check` does;
// true when the time limit cut it short.
bool add_plc(const EvidenceArgs& a, const model::Matrix& m, const PlcProgram& program,
             checker::Clock::time_point deadline, Progress& progress, reports::EvidenceInputs& in) {
  progress.phase("cemv evidence: PLC program", 1, "programs");
  progress.started(program.pou);
  plc_check::PlcCheckReport r;
  r.program_file = program.file;
  r.program_sha256 = program.sha256;
  r.pou = program.pou;
  r.map = program.map;
  r.map_source = program.map_source;
  const plc::Pou& pou = *plc::find_pou(program.program, program.pou);
  decide_outputs(m, program.program, pou, r, a.timeout_s, seconds_left(a, deadline), a.jobs);
  in.plc = plc_figures(program, r);
  return r.interrupted;
}
#endif

void print_summary(const EvidenceArgs& a, const model::Matrix& m, bool valid, const reports::EvidenceInputs& in) {
  std::cout << "cemv evidence: " << m.name << ": "
            << (valid ? std::to_string(in.check.properties.size()) +
                            (in.check.properties.size() == 1 ? " property" : " properties")
                      : std::string("validation errors, nothing checked"))
            << "; wrote " << a.out_file << (a.json_file.empty() ? "" : " and " + a.json_file) << "\n";
}

int run_evidence(const EvidenceArgs& a) {
  if (a.jobs < 1) throw BadArguments("--jobs must be at least 1");
  if (a.timeout_s < 0 || a.total_timeout_s < 0) throw BadArguments("time limits must not be negative");
  // --total-timeout: one deadline for the checks and the response analysis;
  // what it leaves is reported unknown ("time limit"), the report written.
  const checker::Clock::time_point deadline =
      a.total_timeout_s > 0 ? checker::Clock::now() + std::chrono::duration_cast<checker::Clock::duration>(
                                                          std::chrono::duration<double>(a.total_timeout_s))
                            : checker::Clock::time_point::max();
  checker::CancelToken cancel(deadline);
#ifndef CEMV_WITH_RESPONSE
  if (a.response) throw BadArguments("--response: this cemv is built without `cemv response`");
#endif
  check_writable(a.out_file);
  if (!a.json_file.empty()) check_writable(a.json_file);
  const std::string date = report_date();
  // A matrix with validation errors is reported too (a banner, its findings
  // first), but nothing is checked: it cannot be executed or encoded.
  const model::Matrix m = load_matrix_input(a.matrix_file);
  reports::EvidenceInputs in;
  in.matrix_file = input_name(a.matrix_file);
  in.validation = model::validate(m);
  in.date = date;
  const bool valid = !model::has_errors(in.validation);
  const std::vector<properties::PropertyFile> files = read_property_files(a, m, valid, in);
  add_property_texts(m, files, in);
  read_records(a, m, valid, in);
  if (a.plc.empty() && (!a.map.empty() || !a.pou.empty())) throw BadArguments("--map and --pou apply to --plc PROGRAM");
#ifdef CEMV_WITH_PLC
  std::unique_ptr<PlcProgram> program;
  if (!a.plc.empty() && valid) program = load_plc_program(m, a.plc, a.map, a.pou);
#else
  if (!a.plc.empty()) throw BadArguments("--plc: this cemv is built without the PLC front end");
#endif
  checker::CheckOptions options = check_options(a, cancel);
  std::size_t total = 0;
  for (const auto& f : files) total += f.properties.size();
  // On a terminal (and not --quiet): properties, then paths, done / total.
  Progress progress("cemv evidence", total, "properties", !a.quiet && Progress::terminal(), std::cerr);
  options.on_start = [&](const std::string& name) { progress.started(name); };
  options.on_result = [&](const checker::PropertyResult& r) { progress.finished(r.name); };
  bool interrupted = false;
  try {
    if (!files.empty()) {
      in.check = checker::check_properties(m, files, options);
      explain_results(m, files, in.check);  // "why, per step" of every counterexample and witness
    }
#ifdef CEMV_WITH_RESPONSE
    if (a.response && valid) interrupted = add_response(a, m, deadline, progress, in) || interrupted;
#endif
#ifdef CEMV_WITH_PLC
    if (program) interrupted = add_plc(a, m, *program, deadline, progress, in) || interrupted;
#endif
  } catch (const std::exception& e) {
    progress.stop();
    bool refuted = dynamic_cast<const checker::InternalError*>(&e) != nullptr;
    std::cerr << "internal error: " << (refuted ? "" : "the checker failed: ") << e.what()
              << "\n(a bug in cemv: please report it with the matrix and property files)\n";
    return 4;
  }
  progress.stop();
  in.check.matrix_name = m.name;
  in.check.matrix_signature = formats::signature(m);
  in.check.tool_version = CEMV_VERSION;
  in.check.property_files.clear();
  for (const auto& f : a.property_files) in.check.property_files.push_back(input_name(f));
  in.check.standard = a.standard;
  write_output(a.out_file, reports::evidence_html(m, in));
  if (!a.json_file.empty()) write_output(a.json_file, reports::evidence_json(m, in));
  if (!a.quiet) print_summary(a, m, valid, in);
  if (!valid) return 1;
  // The report is complete but for what the time limit left unknown.
  interrupted = interrupted || in.check.interrupted;
  if (interrupted && !a.quiet)
    std::cerr << "cemv evidence: the overall time limit of " << a.total_timeout_s
              << " s is up; what was not decided is reported unknown\n";
  return interrupted ? 3 : 0;
}

}  // namespace

void add_evidence_commands(CLI::App& app, Context& ctx) {
  auto* cmd = app.add_subcommand(
      "evidence", "Write the evidence report of a matrix for an assessor, as one HTML file (docs/reports.md)");
  static EvidenceArgs a;
  cmd->add_option("MATRIX", a.matrix_file, "cemv-matrix/1 file ('-' = standard input)")->required();
  cmd->add_option("PROPS", a.property_files, "property files (docs/properties.md)");
  cmd->add_flag("--standard", a.standard, "also check the standard properties derived from the matrix");
  cmd->add_option("--out", a.out_file, "the HTML report to write")->type_name("FILE")->required();
  cmd->add_option("--coverage", a.coverage_file, "test generation results to include (DIR/coverage.json of cemv testgen)")
      ->type_name("FILE");
  cmd->add_option("--acceptance", a.acceptance_file,
                  "colour the grid by field acceptance status (cemv-acceptance/1 of cemv record, docs/acceptance.md)")
      ->type_name("FILE");
  cmd->add_option("--mutation", a.mutation_file,
                  "mutation figures to include (DIR/mutation-report.json of cemv testgen --mutation-report)")
      ->type_name("FILE");
  cmd->add_option("--defeats", a.defeats_file,
                  "minimal defeat sets to include (the cemv-defeats/1 JSON of cemv defeats --format json)")
      ->type_name("FILE");
  cmd->add_option("--plc", a.plc,
                  "add a chapter on this PLC program (Structured Text or PLCopen XML) proved against the matrix "
                  "(docs/plc.md)")
      ->type_name("PROGRAM");
  cmd->add_option("--map", a.map, "with --plc: the map (cemv-plc-map/1); without it, found by name")->type_name("MAP");
  cmd->add_option("--pou", a.pou, "with --plc: the PROGRAM (default: the map's, or the file's only one)")
      ->type_name("NAME");
  cmd->add_option("--json", a.json_file, "also write the report's content as cemv-evidence/1 JSON (docs/reports.md)")
      ->type_name("FILE");
  cmd->add_flag("--response", a.response,
                "also compute the worst-case response time of every SIF path (as cemv response does)");
  cmd->add_option("--timeout", a.timeout_s, "wall-clock limit per property, seconds (0 = none)")
      ->type_name("S");
  cmd->add_option("--total-timeout", a.total_timeout_s,
                  "wall-clock limit of the whole run, seconds (0 = none; what it leaves is reported unknown, exit 3)")
      ->type_name("S");
  cmd->add_option("--support", a.support,
                  "the cells each proof rests on, as cemv check --support: core (sound, maybe not minimal), "
                  "full (minimal), off")
      ->check(CLI::IsMember({"full", "core", "off"}))
      ->capture_default_str();
  cmd->add_option("--jobs", a.jobs, "worker threads over the properties")->capture_default_str();
  cmd->add_flag("-q,--quiet", a.quiet, "print nothing but errors");
  cmd->footer("Exit status: 0 report written (the verdicts are in the report); 1 report written for a matrix\n"
              "with validation errors (nothing checked); 2 invalid input; 3 report written, --total-timeout\n"
              "left some property or path unknown; 4 internal error. The date is\n"
              "SOURCE_DATE_EPOCH (UTC) when set, else now.\n");
  cmd->callback([&ctx]() {
    try {
      ctx.exit_code = run_evidence(a);
    } catch (const BadArguments& e) {
      std::cerr << "error: evidence: " << e.what() << "\n";
      ctx.exit_code = 2;
    }
  });
}

}  // namespace cemv::cli
