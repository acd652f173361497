#include "cli/testgen_change.hpp"

#include <chrono>

#include "cli/matrix_input.hpp"
#include "diff/print.hpp"
#include "formats/matrix_json.hpp"
#include "model/graph.hpp"

namespace cemv::cli {

ChangeScope apply_change(const std::string& old_file, const std::string& new_file, const model::Matrix& new_m,
                         double timeout_s, testgen::TestgenOptions& options) {
  const model::Matrix old_m = load_valid_matrix(old_file, "compared");
  diff::DiffReport r;
  r.old_m = &old_m;
  r.new_m = &new_m;
  r.old_file = input_name(old_file);
  r.new_file = input_name(new_file);
  r.old_signature = formats::signature(old_m);
  r.new_signature = formats::signature(new_m);
  r.structure = diff::compare_structure(old_m, new_m);
  diff::SemanticOptions so;
  so.timeout_s = timeout_s;
  so.cancel = options.cancel;  // --total-timeout bounds the comparison too
  r.behaviour = diff::compare_behaviour(old_m, new_m, r.structure, so);
  const diff::RetestScope scope = diff::retest_scope(r.behaviour);

  ChangeScope out;
  out.partial = scope.partial;
  // Partial: the impacted effects of NEW, every node of their cones, and the
  // causes of the impact set (which include the causes an OLD cone had).
  if (scope.partial) {
    std::set<model::Node> elements;
    const model::DependencyGraph g(new_m);
    for (const auto& e : r.behaviour.effects) {
      if (!e.behaviour_changed() || !e.new_id) continue;
      const model::Node n{model::Node::Kind::Effect, e.new_id};
      elements.insert(n);
      for (const auto& f : g.feeders_of(n)) elements.insert(f);
    }
    for (int c : r.behaviour.impact.causes) elements.insert({model::Node::Kind::Cause, c});
    options.elements = std::move(elements);
  }
  for (const auto& e : r.behaviour.effects) {
    if (!e.result.distinction || !e.new_id || e.new_inputs.empty()) continue;
    const auto& d = *e.result.distinction;
    const model::Effect& ef = *new_m.find_effect(e.new_id);
    testgen::GivenTest t;
    t.name = "effect[" + std::to_string(e.new_id) + "]";
    t.description = "Change: " + t.name + " " + ef.name + " behaves differently from the accepted version: " +
                    e.new_key + " in cycle " + std::to_string(d.cycle + 1) + " was " + std::to_string(d.value_a) +
                    ", is now " + std::to_string(d.value_b);
    t.sif = ef.sif.empty() ? 0 : ef.sif.front();
    t.inputs = e.new_inputs;
    t.key = e.new_key;
    options.given.push_back(std::move(t));
  }
  out.preface_markdown = diff::change_preface_markdown(r);
  out.preface_html = diff::change_preface_html(r);
  out.preface_csv = diff::change_preface_lines(r);
  const auto lines = diff::change_preface_lines(r);
  out.summary = lines[lines.size() - 2] + "\n" + lines.back() + "\n";
  return out;
}

}  // namespace cemv::cli
