// `cemv export-smt MATRIX [--roots cause:1,effect:2] --format smt2|vmt
//  [--depth k] [--property KEY | --reach KEY] [-o OUT]`: the encoder's
// transition system for other solvers (docs/encoding.md "Export").
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include "cli/commands.hpp"
#include "cli/matrix_input.hpp"
#include "cli/output.hpp"
#include "encoder/encode.hpp"
#include "encoder/export.hpp"
#include "formats/matrix_json.hpp"

namespace cemv::cli {

namespace {

struct SmtOptions {
  std::string file;
  std::string roots;
  std::string format = "smt2";
  int depth = 10;
  std::string property;
  std::string reach;
  std::string out = "-";
  bool depth_given = false;
};

// "cause:1,effect:2" -> nodes; nullopt-like empty vector with ok=false on error.
bool parse_roots(const std::string& text, std::vector<model::Node>& out, std::string& error) {
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    auto colon = item.find(':');
    if (colon == std::string::npos) {
      error = "bad root '" + item + "' (expected cause:ID or effect:ID)";
      return false;
    }
    std::string kind = item.substr(0, colon);
    std::string id = item.substr(colon + 1);
    if ((kind != "cause" && kind != "effect") || id.empty() ||
        id.find_first_not_of("0123456789") != std::string::npos || id.size() > 4) {
      error = "bad root '" + item + "' (expected cause:ID or effect:ID)";
      return false;
    }
    out.push_back({kind == "cause" ? model::Node::Kind::Cause : model::Node::Kind::Effect,
                   std::stoi(id)});
  }
  return true;
}

void run(const SmtOptions& o, Context& ctx) {
  // Options that mean nothing for the chosen format are refused, not ignored.
  if (o.format == "vmt" && o.depth_given)
    throw std::invalid_argument("export-smt: --depth applies to --format smt2 (an unrolling); VMT-LIB "
                                "describes the transition system itself, without a depth");
  check_writable(o.out);
  model::Matrix m = load_valid_matrix(o.file, "encoded");
  std::vector<model::Node> roots;
  std::string error;
  if (!parse_roots(o.roots, roots, error)) {
    std::cerr << "error: --roots: " << error << "\n";
    ctx.exit_code = 2;
    return;
  }
  for (const auto& r : roots) {
    bool ok = r.kind == model::Node::Kind::Cause
                  ? m.find_cause(r.id) && m.find_cause(r.id)->function != model::CauseFunction::Comment
                  : m.find_effect(r.id) && m.find_effect(r.id)->function != model::EffectFunction::Comment;
    if (!ok) {
      std::cerr << "error: --roots: no processed " << model::to_string(r) << " in " << o.file << "\n";
      ctx.exit_code = 2;
      return;
    }
  }
  if (!o.property.empty() && !o.reach.empty()) {
    std::cerr << "error: give --property or --reach, not both\n";
    ctx.exit_code = 2;
    return;
  }
  encoder::ExportGoal goal;
  if (!o.property.empty()) goal = {encoder::ExportGoal::Kind::Invariant, o.property};
  if (!o.reach.empty()) goal = {encoder::ExportGoal::Kind::Reach, o.reach};
  z3::context zc;
  auto enc = encoder::encode(zc, m, roots);
  std::string text;
  try {
    text = o.format == "vmt" ? encoder::to_vmt(*enc, goal) : encoder::to_smt2(*enc, o.depth, goal);
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << "\n";
    ctx.exit_code = 2;
    return;
  }
  write_output(o.out, text);
  ctx.exit_code = 0;
}

}  // namespace

void add_smt_commands(CLI::App& app, Context& ctx) {
  auto opt = std::make_shared<SmtOptions>();
  auto* cmd = app.add_subcommand(
      "export-smt", "Write the matrix's transition system as SMT-LIB 2 (an unrolling) or VMT-LIB");
  cmd->add_option("matrix", opt->file, "cemv-matrix/1 file ('-' = standard input)")->required();
  cmd->add_option("--roots", opt->roots,
                  "Cone of influence: causes/effects to encode, e.g. cause:1,effect:2 (default all)");
  cmd->add_option("--format", opt->format, "smt2 or vmt")
      ->check(CLI::IsMember({"smt2", "vmt"}));
  cmd->add_option("--depth", opt->depth, "smt2: number of cycles to unroll")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--property", opt->property,
                  "A Boolean observable that must hold in every cycle, e.g. 'effect[1].active' "
                  "(smt2: sat = counterexample)");
  cmd->add_option("--reach", opt->reach,
                  "A Boolean observable to reach (smt2: sat = witness)");
  cmd->add_option("-o,--output", opt->out, "Output file (default stdout; replaced atomically)");
  add_quiet_flag(cmd, ctx);
  cmd->callback([opt, cmd, &ctx] {
    opt->depth_given = cmd->count("--depth") > 0;
    run(*opt, ctx);
  });
}

}  // namespace cemv::cli
