// Fuzz target: the scenario parser (formats/scenario.hpp, docs/scenario.md),
// the bytes `cemv simulate` and `cemv replay` read, resolved against the
// matrices the repository's scenarios name, then expanded into scan cycles.
// The scenario's `matrix` key picks the matrix by its file stem
// (`matrices/ch13_causes.json`); `matrix.json` or anything else is tried
// against every example. Expected answers: a scenario, or a LoadError.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "formats/scenario.hpp"
#include "fuzz/fuzz_support.hpp"

using namespace cemv;

namespace {

struct Matrices {
  std::map<std::string, model::Matrix> by_stem;  // tests/scenarios/matrices/*
  std::vector<model::Matrix> examples;
  Matrices() {
    for (const char* stem : {"ch13_causes", "ch13_effects", "ch13_process_data", "semantics_rules",
                             "semantics_M_3_secure_write"})
      by_stem.emplace(stem, fuzz::repository_matrix(std::string("tests/scenarios/matrices/") + stem + ".json"));
    for (const char* example : {"tank-overfill", "burner-management", "pipeline-hipps", "compressor"})
      examples.push_back(fuzz::repository_matrix(std::string("examples/") + example + "/matrix.json"));
  }
};

void parse_and_expand(std::string_view text, const model::Matrix& m) {
  try {
    const formats::Scenario sc = formats::parse_scenario(text, m, "fuzz.json");
    const formats::ExpandedScenario ex = formats::expand_scenario(sc, m);
    if (ex.checks.size() != sc.steps.size()) fuzz::finding("an expansion without one check per step");
  } catch (const formats::LoadError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Matrices matrices;
  const auto text = fuzz::as_text(data, size);
  std::string stem;
  try {
    if (auto key = formats::scenario_matrix_key(text, "fuzz.json")) {
      stem = *key;
      if (auto slash = stem.find_last_of('/'); slash != std::string::npos) stem.erase(0, slash + 1);
      if (auto dot = stem.rfind('.'); dot != std::string::npos) stem.erase(dot);
    }
  } catch (const formats::LoadError&) {
  }
  if (auto it = matrices.by_stem.find(stem); it != matrices.by_stem.end()) {
    parse_and_expand(text, it->second);
  } else {
    for (const auto& m : matrices.examples) parse_and_expand(text, m);
  }
  return 0;
}
