#include "properties/traps.hpp"

#include <map>
#include <set>
#include <tuple>

#include "properties/lexer.hpp"

namespace cemv::properties {

namespace {

using model::CommandOp;

// A command pattern that an assumption rules out: it occurs only under an odd
// number of negations (`not issued(...)`, the left of `implies`).
struct Excluded {
  CommandOp op;
  std::optional<int> effect;
  SourceLoc loc;
};

// Polarity: +1 positive, -1 negative, 0 both (iff, comparisons, rose/fell).
void collect(const Expr& e, int polarity, std::vector<Excluded>& out) {
  switch (e.kind) {
    case Expr::Kind::CommandIssued:
      if (polarity == -1 && (e.command.op == CommandOp::OverrideEffect || e.command.op == CommandOp::StopOverride))
        out.push_back({e.command.op, e.command.effect, e.loc});
      return;
    case Expr::Kind::Not: collect(e.args.at(0), -polarity, out); return;
    case Expr::Kind::Implies:
      collect(e.args.at(0), -polarity, out);
      collect(e.args.at(1), polarity, out);
      return;
    case Expr::Kind::And:
    case Expr::Kind::Or:
    case Expr::Kind::Prev:
    case Expr::Kind::Held:
    case Expr::Kind::Within:
    case Expr::Kind::Since:
      for (const auto& a : e.args) collect(a, polarity, out);
      return;
    default:
      for (const auto& a : e.args) collect(a, 0, out);
      return;
  }
}

const char* name(CommandOp op) { return model::to_string(op); }

std::string target(const std::optional<int>& effect) {
  return effect ? "effect = " + std::to_string(*effect) : "";
}

}  // namespace

std::vector<std::string> find_traps(PropertyFile& file, const model::Matrix& m) {
  std::vector<Excluded> shared;
  for (const auto& a : file.assumptions) collect(a.expr, 1, shared);
  std::map<std::tuple<int, int, std::string>, std::string> warnings;  // by place, in file order
  for (auto& p : file.properties) {
    std::vector<Excluded> all = shared;
    for (const auto& a : p.assumptions) collect(a.expr, 1, all);
    std::set<std::string> said;
    for (const auto& x : all) {
      const CommandOp other = x.op == CommandOp::OverrideEffect ? CommandOp::StopOverride : CommandOp::OverrideEffect;
      std::vector<int> effects;
      if (x.effect) effects.push_back(*x.effect);
      else
        for (const auto& e : m.effects) effects.push_back(e.id);
      std::string text;
      // An effect with a reset tag refuses both commands (O.3): its override
      // is toggled by the reset tag's rising edge, which no command excludes.
      for (int id : effects) {
        const model::Effect* e = m.find_effect(id);
        if (x.effect && e && e->reset_tag) {
          text = "the assumption excludes " + std::string(name(x.op)) + " on effect " + std::to_string(id) +
                 ", which has the reset tag " + *e->reset_tag + ": the effect refuses override commands " +
                 "(docs/semantics.md O.3) and a rising edge of " + *e->reset_tag +
                 " toggles its override (E.3); to exclude the override, assume `not rose(" + *e->reset_tag + ")`";
          break;
        }
      }
      if (text.empty()) {
        bool covered = false;
        for (const auto& y : all)
          if (y.op == other && (!y.effect || (x.effect && *y.effect == *x.effect))) covered = true;
        if (covered) continue;
        text = "the assumption excludes " + std::string(name(x.op)) + " but not " + name(other) +
               ", the same button (docs/semantics.md E.3, O.3: either command toggles the override): an override "
               "can still start or stop; exclude both, e.g. `not issued(override_effect" +
               (x.effect ? ", " + target(x.effect) : std::string()) + ") and not issued(stop_override" +
               (x.effect ? ", " + target(x.effect) : std::string()) + ")`";
      }
      warnings[{x.loc.line, x.loc.column, text}] = place(file.file_name, x.loc) + ": warning: " + text;
      if (said.insert(text).second) p.notes.push_back("warning: line " + std::to_string(x.loc.line) + ": " + text);
    }
  }
  std::vector<std::string> out;
  for (auto& [where, line] : warnings) out.push_back(std::move(line));
  return out;
}

}  // namespace cemv::properties
