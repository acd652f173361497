// `cemv validate FILE...` (the validation report of 11.5, as a CI gate) and
// `cemv graph` (the dependency graph and evaluation order), docs/validation.md.
// validate reads every file, reports each, and exits with the worst file's
// status: 0 clean, 1 errors, 2 unreadable.
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/errors.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "formats/matrix_json.hpp"
#include "model/graph.hpp"
#include "model/validate.hpp"
#include "reports/dot.hpp"
#include "reports/validation_report.hpp"

#ifndef CEMV_VERSION
#define CEMV_VERSION "unknown"
#endif

namespace cemv::cli {

namespace {

struct ValidateOptions {
  std::vector<std::string> files;
  std::string format = "text";
  std::string out = "-";
  bool warnings_as_errors = false;
};

struct GraphOptions {
  std::string file;
  std::string out = "-";
  bool order = false;
};

// One file read, parsed and validated; a load error is kept, not thrown.
reports::ValidatedFile validate_file(const std::string& path) {
  reports::ValidatedFile f;
  f.file = input_name(path);
  try {
    const std::string text = read_input(path);
    model::Matrix m = formats::parse_matrix(text, f.file);
    f.diagnostics = model::validate(m);
    f.matrix_name = m.name;
    f.signature = formats::signature(m);
    const formats::JsonPositions positions(text);
    for (const auto& d : f.diagnostics) {
      std::pair<std::size_t, std::size_t> at{0, 0};
      if (auto offset = formats::element_offset(positions, d.element))
        at = formats::line_and_column(text, *offset);
      f.positions.push_back(at);
    }
    f.loaded = true;
  } catch (const formats::LoadError& e) {
    std::ostringstream lines;
    print_load_error(e.in_file(f.file), lines);
    std::string line;
    for (std::istringstream in(lines.str()); std::getline(in, line);) f.load_errors.push_back(line);
  }
  return f;
}

// One node per line in evaluation order, naming the references it reads from
// the previous scan cycle.
std::string order_report(const model::Matrix& m, const model::DependencyGraph& g) {
  std::ostringstream out;
  std::size_t position = 0;
  for (const auto& n : g.evaluation_order()) {
    out << ++position << " " << model::to_string(n);
    if (n.kind == model::Node::Kind::Cause) {
      if (const auto* c = m.find_cause(n.id)) out << " " << c->name;
    } else if (const auto* e = m.find_effect(n.id)) {
      out << " " << e->name;
    }
    std::string stale;
    for (const auto& edge : g.edges())
      if (edge.to == n && edge.reads_previous)
        stale += (stale.empty() ? "" : ", ") + model::to_string(edge.from);
    if (!stale.empty()) out << "  (reads " << stale << " from the previous cycle)";
    out << "\n";
  }
  return out.str();
}

int run_validate(const ValidateOptions& o, bool quiet) {
  check_writable(o.out);
  std::size_t stdin_uses = 0;
  for (const auto& f : o.files) stdin_uses += f == "-";
  if (stdin_uses > 1) throw std::invalid_argument("validate: '-' (standard input) can be read only once");
  std::vector<reports::ValidatedFile> files;
  for (const auto& path : o.files) {
    files.push_back(validate_file(path));
    for (const auto& line : files.back().load_errors) std::cerr << line << "\n";
  }
  reports::ValidationOptions options;
  options.warnings_as_errors = o.warnings_as_errors;
  options.quiet = quiet;
  options.tool_version = CEMV_VERSION;
  const auto format = *reports::validation_format_from_string(o.format);
  write_output(o.out, reports::validation_report(files, format, options));
  const auto summary = reports::summarize(files, options);
  // The machine-readable formats keep standard output to themselves: the
  // summary goes to standard error.
  bool machine = format == reports::ValidationFormat::Json || format == reports::ValidationFormat::Junit ||
                 format == reports::ValidationFormat::Sarif;
  if (machine && !quiet && (files.size() > 1 || o.out != "-"))
    std::cerr << reports::summary_line(summary) << "\n";
  return summary.exit_code;
}

}  // namespace

void add_validate_commands(CLI::App& app, Context& ctx) {
  auto vopt = std::make_shared<ValidateOptions>();
  CLI::App* validate_cmd = app.add_subcommand(
      "validate",
      "Plausibility checks (validation report, 11.5) of one or more matrices: errors and warnings with "
      "rule id, element and manual section; exit 0 without errors, 1 with errors, 2 for an unreadable "
      "file (the worst file decides)");
  validate_cmd->add_option("FILE", vopt->files, "Matrix files (cemv-matrix/1 JSON; '-' = standard input)")
      ->required();
  validate_cmd
      ->add_option("--format", vopt->format,
                   "text (default), json, gcc (FILE:LINE:COL: error|warning: [RULE] element: message), "
                   "junit or sarif (SARIF 2.1.0)")
      ->check(CLI::IsMember({"text", "json", "gcc", "junit", "sarif"}));
  validate_cmd->add_option("-o,--output", vopt->out, "Write the report here instead of standard output");
  validate_cmd->add_flag("--warnings-as-errors", vopt->warnings_as_errors,
                         "A warning counts as an error (exit 1, failures in JUnit, level error in SARIF)");
  add_quiet_flag(validate_cmd, ctx);
  validate_cmd->callback([vopt, &ctx] { ctx.exit_code = run_validate(*vopt, ctx.quiet); });

  auto gopt = std::make_shared<GraphOptions>();
  CLI::App* graph_cmd = app.add_subcommand(
      "graph",
      "Write the dependency graph (causes, effects, intersections, internal references) as "
      "Graphviz DOT, or the evaluation order of a scan cycle with --order; a matrix with "
      "validation errors is refused (exit 2)");
  graph_cmd->add_option("FILE", gopt->file, "Matrix file (cemv-matrix/1 JSON; '-' = standard input)")->required();
  graph_cmd->add_option("-o,--output", gopt->out, "Write here instead of standard output");
  graph_cmd->add_flag("--order", gopt->order,
                      "Print the evaluation order (one node per line) instead of DOT");
  add_quiet_flag(graph_cmd, ctx);
  graph_cmd->callback([gopt, &ctx] {
    check_writable(gopt->out);
    model::Matrix m = load_valid_matrix(gopt->file, "drawn as a graph");
    model::DependencyGraph g(m);
    write_output(gopt->out, gopt->order ? order_report(m, g) : cemv::reports::to_dot(m, g));
    ctx.exit_code = 0;
  });
}

}  // namespace cemv::cli
