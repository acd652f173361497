// The catalogue of coverage objectives (docs/testgen.md, "Objectives"): each
// a `reachable` property with a stable id and a sentence, derived from the
// matrix alone, in a fixed order (causes by id, then per effect by id its
// intersections and its own behaviour, then matrix-level functions).
#include "properties/build.hpp"
#include "testgen/objective_builder.hpp"

namespace cemv::testgen {

const char* to_string(ObjectiveStatus s) {
  switch (s) {
    case ObjectiveStatus::Covered: return "covered";
    case ObjectiveStatus::Infeasible: return "infeasible";
    case ObjectiveStatus::Undecided: return "undecided";
  }
  return "undecided";
}

std::vector<Objective> derive_objectives(const model::Matrix& m) {
  std::vector<Objective> out;
  detail::ObjectiveBuilder b(m, out);
  for (const auto& c : m.causes)
    if (c.function != model::CauseFunction::Comment) detail::cause_objectives(b, c);
  for (const auto& e : m.effects)
    if (e.function != model::EffectFunction::Comment) {
      detail::intersection_objectives(b, e);
      detail::effect_objectives(b, e);
    }
  detail::matrix_objectives(b);
  return out;
}

// Each objective carries its own assumptions (no tag simulation, except the
// `reference` objectives: ObjectiveBuilder::add).
properties::PropertyFile objectives_file(const std::vector<Objective>& objectives) {
  properties::PropertyFile f;
  f.file_name = "objectives";
  f.properties.reserve(objectives.size());
  for (const auto& o : objectives) f.properties.push_back(o.property);
  return f;
}

std::string objectives_file_text(const model::Matrix& m, const std::vector<Objective>& objectives) {
  const model::InputTable inputs(m);
  std::string s = "# Coverage objectives (cemv testgen, docs/testgen.md)\n\n";
  for (const auto& o : objectives) s += "# " + o.text + "\n" + properties::build::block_text(o.property, inputs) + "\n";
  return s;
}

}  // namespace cemv::testgen
