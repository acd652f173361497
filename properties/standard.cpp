// Each standard property restates one rule of docs/semantics.md over the
// status fields, so it is exactly true of a correct implementation of that
// rule; what it checks is the matrix's wiring (XooN, bypasses, references)
// and the encoder/runtime agreement, and its proof support shows which
// elements carry it.
#include "properties/standard.hpp"

#include <algorithm>

#include "model/graph.hpp"
#include "model/vocabulary.hpp"
#include "properties/parser.hpp"

namespace cemv::properties {

namespace {

using model::IntersectionType;

std::string c(int id) { return "cause[" + std::to_string(id) + "]"; }
std::string e(int id) { return "effect[" + std::to_string(id) + "]"; }

// A tag name as the language writes it: always quoted, so any name of 6.1.4 works.
std::string tag_literal(const std::string& name) {
  std::string out = "\"";
  for (char ch : name) {
    if (ch == '\\' || ch == '"') out += '\\';
    out += ch;
  }
  return out + "\"";
}

bool processed(const model::Cause* x) { return x && x->function != model::CauseFunction::Comment; }
bool processed(const model::Effect* x) { return x && x->function != model::EffectFunction::Comment; }

class Writer {
 public:
  explicit Writer(const model::Matrix& m) : m_(m), graph_(m), inputs_(m) {}

  std::string run() {
    for (const auto& i : m_.intersections) intersection(i);
    for (const auto& x : m_.effects)
      if (processed(&x)) output_delay(x);
    for (const auto& x : m_.effects)
      if (processed(&x)) reachable(x);
    for (const auto& x : m_.effects)
      if (processed(&x)) resettable(x);
    for (const auto& x : m_.causes)
      if (processed(&x)) failsafe(x);
    return out_;
  }

 private:
  void block(const std::string& name, const std::string& description, const std::vector<std::string>& assumptions,
             const std::string& statement) {
    out_ += "property " + name + " \"" + description + "\" {\n";
    for (const auto& a : assumptions) out_ += "  assume " + a + "\n";
    out_ += "  " + statement + "\n}\n";
  }

  // The cause's `active` as the effect reads it (I.4): the previous cycle's
  // value when the reference closes a cycle of the dependency graph.
  std::string active_as_read(int cause, int effect) const {
    bool previous = graph_.reads_previous({model::Node::Kind::Cause, cause}, {model::Node::Kind::Effect, effect});
    return previous ? "prev(" + c(cause) + ".active)" : c(cause) + ".active";
  }

  // E.2/E.6: an active cause on an N, S, V or R intersection requests the
  // effect, which is then active unless bypassed, or (V and R only) overridden.
  // With an XooN assignment (E.2) at least X of its causes must be active.
  void intersection(const model::Intersection& i) {
    if (!model::is_processed(i.type) || !processed(m_.find_cause(i.cause)) || !processed(m_.find_effect(i.effect)))
      return;
    std::string cond = active_as_read(i.cause, i.effect);
    std::string what = "cause " + std::to_string(i.cause) + " active";
    if (i.xoon) {
      std::vector<const model::Intersection*> group;
      for (const auto* j : m_.intersections_of_effect(i.effect))
        if (j->xoon && model::is_processed(j->type) && processed(m_.find_cause(j->cause))) group.push_back(j);
      int x = *i.xoon;
      for (const auto* j : group) x = std::min(x, *j->xoon);
      std::string list;
      for (const auto* j : group) list += (list.empty() ? "" : ", ") + active_as_read(j->cause, i.effect);
      cond += " and count(" + list + ") >= " + std::to_string(x);
      what += " with " + std::to_string(x) + "oo" + std::to_string(group.size()) + " of its XooN assignment";
    }
    // The type that counts is the assignment's (E.2): the type of its lowest cause.
    IntersectionType type = i.type;
    if (i.xoon)
      for (const auto* j : m_.intersections_of_effect(i.effect))
        if (j->xoon && model::is_processed(j->type)) {
          type = j->type;
          break;
        }
    cond += " and not " + e(i.effect) + ".bypassed";
    std::string unless = "not bypassed";
    if (type == IntersectionType::V || type == IntersectionType::R) {
      cond += " and not " + e(i.effect) + ".override_active";
      unless = "neither bypassed nor overridden";
    }
    block("std.intersection.c" + std::to_string(i.cause) + ".e" + std::to_string(i.effect),
          what + ", effect " + std::to_string(i.effect) + " " + unless + ": effect " + std::to_string(i.effect) +
              " active",
          {}, "always " + cond + " implies " + e(i.effect) + ".active");
  }

  // E.7: once the effect has been active for the whole output delay, the delay
  // no longer holds the outputs back.
  void output_delay(const model::Effect& x) {
    if (x.output_delay_ms == 0) return;
    std::uint64_t cycles = (std::uint64_t{x.output_delay_ms} + m_.cycle_ms - 1) / m_.cycle_ms;  // T.2
    block("std.output_delay.e" + std::to_string(x.id),
          "effect " + std::to_string(x.id) + " active for its output delay (" + std::to_string(x.output_delay_ms) +
              " ms): the outputs follow",
          {}, "always held(" + e(x.id) + ".active, " + std::to_string(cycles) + " cycles) implies not " + e(x.id) +
                  ".output_delay_running");
  }

  void reachable(const model::Effect& x) {
    block("std.reachable.e" + std::to_string(x.id), "effect " + std::to_string(x.id) + " can be tripped", {},
          "reachable " + e(x.id) + ".active");
  }

  // E.4/E.5: an effect that latches (S or R intersection) can leave the latched state.
  void resettable(const model::Effect& x) {
    bool latches = false;
    for (const auto* i : m_.intersections_of_effect(x.id))
      latches = latches || ((i->type == IntersectionType::S || i->type == IntersectionType::R) &&
                            processed(m_.find_cause(i->cause)));
    if (!latches) return;
    block("std.resettable.e" + std::to_string(x.id), "latched effect " + std::to_string(x.id) + " can be reset", {},
          "reachable prev(" + e(x.id) + ".latched) and not " + e(x.id) + ".latched");
  }

  // C.3/C.4: with every tag of a `trip` or `degrade` cause in bad quality the
  // trip is requested, unless every tag is soft-bypassed (voting `bypass`).
  // Simulation delivers good quality (C.2), so the property assumes none.
  void failsafe(const model::Cause& x) {
    if (x.bad_quality == model::BadQuality::Ignore || x.tags.empty()) return;
    std::vector<std::string> assumptions;
    std::string all_bad;
    for (const auto& t : x.tags) {
      if (model::parse_internal_ref(t.name) || !inputs_.find(t.name)) return;  // no quality to lose
      all_bad += (all_bad.empty() ? "" : " and ") + std::string("bad(") + tag_literal(t.name) + ")";
      assumptions.push_back("not issued(simulate_tag, tag = " + tag_literal(t.name) + ")");
    }
    block("std.failsafe.c" + std::to_string(x.id),
          "every tag of cause " + std::to_string(x.id) + " in bad quality (" + model::to_string(x.bad_quality) +
              "): trip requested",
          assumptions, "always " + all_bad + " and " + c(x.id) + ".voting != bypass implies " + c(x.id) +
                           ".trip_requested");
  }

  const model::Matrix& m_;
  model::DependencyGraph graph_;
  model::InputTable inputs_;
  std::string out_;
};

void clear_locations(Expr& x) {
  x.loc = {};
  for (auto& a : x.args) clear_locations(a);
}

}  // namespace

std::string standard_properties_text(const model::Matrix& m) { return Writer(m).run(); }

PropertyFile standard_properties(const model::Matrix& m) {
  PropertyFile f = parse_properties(standard_properties_text(m), m, "<standard>");
  for (auto& p : f.properties) {
    p.loc = {};
    clear_locations(p.body);
    clear_locations(p.trigger);
    clear_locations(p.response);
    for (auto& a : p.assumptions) {
      a.loc = {};
      clear_locations(a.expr);
    }
  }
  return f;
}

}  // namespace cemv::properties
