// `cemv evidence MATRIX [PROPS...] --out report.html`: the evidence report for
// an assessor (docs/reports.md, "Evidence report"): the matrix, its validation,
// every property checked as `cemv check` checks it (with the timing diagram of
// each counterexample), the test-generation figures when given, the signature,
// version and date on every page. The date is SOURCE_DATE_EPOCH when set (the
// reproducible-builds convention), else now. Exit 0 when the report is
// written, whatever the verdicts (the report says them); 2 invalid input;
// 4 internal error (an answer refuted by the re-check).
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "checker/check.hpp"
#include "checker/prover.hpp"
#include "cli/commands.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "formats/matrix_json.hpp"
#include "model/validate.hpp"
#include "properties/parser.hpp"
#include "properties/standard.hpp"
#include "reports/evidence.hpp"

namespace cemv::cli {

namespace {

struct EvidenceArgs {
  std::string matrix_file;
  std::vector<std::string> property_files;
  bool standard = false;
  std::string out_file;
  std::string coverage_file;
  double timeout_s = 60.0;
  int jobs = 1;
};

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

int run_evidence(const EvidenceArgs& a) {
  check_writable(a.out_file);
  const std::string date = report_date();
  const model::Matrix m = load_valid_matrix(a.matrix_file, "reported");
  std::vector<properties::PropertyFile> files;
  for (const auto& f : a.property_files)
    files.push_back(properties::parse_properties(read_input(f), m, input_name(f)));
  if (a.standard) files.push_back(properties::standard_properties(m));

  reports::EvidenceInputs in;
  in.matrix_file = input_name(a.matrix_file);
  in.validation = model::validate(m);
  in.date = date;
  if (!a.coverage_file.empty()) {
    in.coverage_file = a.coverage_file;
    in.coverage_json = read_input(a.coverage_file);
  }
  checker::CheckOptions options;
  options.property_timeout_s = a.timeout_s;
  options.jobs = a.jobs;
  options.standard = a.standard;
  try {
    if (!files.empty()) in.check = checker::check_properties(m, files, options);
  } catch (const std::exception& e) {
    bool refuted = dynamic_cast<const checker::InternalError*>(&e) != nullptr;
    std::cerr << "internal error: " << (refuted ? "" : "the checker failed: ") << e.what()
              << "\n(a bug in cemv: please report it with the matrix and property files)\n";
    return 4;
  }
  in.check.matrix_name = m.name;
  in.check.matrix_signature = formats::signature(m);
  in.check.tool_version = CEMV_VERSION;
  in.check.property_files.clear();
  for (const auto& f : a.property_files) in.check.property_files.push_back(input_name(f));
  in.check.standard = a.standard;
  write_output(a.out_file, reports::evidence_html(m, in));
  std::cout << "cemv evidence: " << m.name << ": " << in.check.properties.size()
            << (in.check.properties.size() == 1 ? " property" : " properties") << "; wrote " << a.out_file << "\n";
  return 0;
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
  cmd->add_option("--coverage", a.coverage_file, "test generation results (coverage and mutation figures) to include")
      ->type_name("FILE");
  cmd->add_option("--timeout", a.timeout_s, "wall-clock limit per property, seconds (0 = none)")
      ->type_name("S")
      ->capture_default_str();
  cmd->add_option("--jobs", a.jobs, "worker threads over the properties")->capture_default_str();
  cmd->footer("Exit status: 0 report written (the verdicts are in the report); 2 invalid input;\n"
              "4 internal error. The date is SOURCE_DATE_EPOCH (UTC) when set, else now.\n");
  cmd->callback([&ctx]() { ctx.exit_code = run_evidence(a); });
}

}  // namespace cemv::cli
