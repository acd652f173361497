// `cemv validate` (the validation report of 11.5) and `cemv graph` (the
// dependency graph and evaluation order), docs/validation.md. An unreadable or
// malformed file throws formats::LoadError, which main() prints with exit 2.
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "formats/matrix_json.hpp"
#include "model/graph.hpp"
#include "reports/dot.hpp"
#include "model/validate.hpp"

namespace cemv::cli {

namespace {

struct ValidateOptions {
  std::string file;
  std::string format = "text";
};

struct GraphOptions {
  std::string file;
  std::string out;
  bool order = false;
};

std::string text_report(const model::Matrix& m, const std::vector<model::Diagnostic>& ds) {
  std::ostringstream out;
  std::size_t errors = 0, warnings = 0;
  for (const auto& d : ds) {
    (d.severity == model::Severity::Error ? errors : warnings)++;
    out << std::left << std::setw(7) << model::to_string(d.severity) << " " << d.rule << "  "
        << d.element << "  [" << d.section << "]  " << d.message << "\n";
  }
  out << errors << " errors, " << warnings << " warnings\n";
  out << "signature: " << formats::signature(m) << "\n";
  return out.str();
}

std::string json_report(const model::Matrix& m, const std::vector<model::Diagnostic>& ds) {
  nlohmann::ordered_json diagnostics = nlohmann::ordered_json::array();
  std::size_t errors = 0, warnings = 0;
  for (const auto& d : ds) {
    (d.severity == model::Severity::Error ? errors : warnings)++;
    diagnostics.push_back({{"severity", model::to_string(d.severity)},
                           {"rule", d.rule},
                           {"element", d.element},
                           {"section", d.section},
                           {"message", d.message}});
  }
  nlohmann::ordered_json j;
  j["format"] = "cemv-validation/1";
  j["matrix"] = m.name;
  j["signature"] = formats::signature(m);
  j["errors"] = errors;
  j["warnings"] = warnings;
  j["diagnostics"] = std::move(diagnostics);
  return j.dump(2) + "\n";
}

// One line per node in evaluation order, naming the references it reads from
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

}  // namespace

void add_validate_commands(CLI::App& app, Context& ctx) {
  auto vopt = std::make_shared<ValidateOptions>();
  CLI::App* validate_cmd = app.add_subcommand(
      "validate",
      "Plausibility checks (validation report, 11.5): errors and warnings with rule id, element "
      "and manual section; exit 0 without errors, 1 with errors, 2 for an unreadable file");
  validate_cmd->add_option("FILE", vopt->file, "Matrix file (cemv-matrix/1 JSON)")->required();
  validate_cmd->add_option("--format", vopt->format, "Output format: text (default) or json")
      ->check(CLI::IsMember({"text", "json"}));
  validate_cmd->callback([vopt, &ctx] {
    model::Matrix m = formats::load_matrix(vopt->file);
    auto ds = model::validate(m);
    std::cout << (vopt->format == "json" ? json_report(m, ds) : text_report(m, ds)) << std::flush;
    ctx.exit_code = model::has_errors(ds) ? 1 : 0;
  });

  auto gopt = std::make_shared<GraphOptions>();
  CLI::App* graph_cmd = app.add_subcommand(
      "graph",
      "Write the dependency graph (causes, effects, intersections, internal references) as "
      "Graphviz DOT, or the evaluation order of a scan cycle with --order");
  graph_cmd->add_option("FILE", gopt->file, "Matrix file (cemv-matrix/1 JSON)")->required();
  graph_cmd->add_option("-o,--output", gopt->out, "Write here instead of standard output");
  graph_cmd->add_flag("--order", gopt->order,
                      "Print the evaluation order (one node per line) instead of DOT");
  graph_cmd->callback([gopt, &ctx] {
    model::Matrix m = formats::load_matrix(gopt->file);
    model::DependencyGraph g(m);
    std::string text = gopt->order ? order_report(m, g) : cemv::reports::to_dot(m, g);
    if (gopt->out.empty()) {
      std::cout << text << std::flush;
    } else {
      std::ofstream out(gopt->out, std::ios::binary);
      out << text;
      out.close();
      if (!out) {
        std::cerr << "error: " << gopt->out << ": cannot write the file\n";
        ctx.exit_code = 2;
        return;
      }
    }
    ctx.exit_code = 0;
  });
}

}  // namespace cemv::cli
