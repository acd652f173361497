// The timing keys of cemv-matrix/1 (docs/format.md, docs/response-time.md) are
// backward compatible: a file without them keeps its canonical form and its
// signature, and a key at its default changes nothing either.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "formats/matrix_json.hpp"

namespace {

using namespace cemv;

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The example as it was before it declared process safety times: every
// timing key removed, SIF groups in the string form.
std::string without_timing(const std::string& text) {
  auto j = nlohmann::ordered_json::parse(text);
  j.erase("watchdog_ms");
  for (auto& [key, group] : j["sif_groups"].items())
    if (group.is_object()) group = group["name"];
  for (auto& c : j["causes"]) {
    c.erase("sensor_ms");
    // The compressor's seeded defeat (docs/defeats.md, examples/compressor/
    // README.md "Defeats") came after the timing keys: undone here.
    if (j["name"] == "K401_COMPRESSOR" && c["name"] == "PSLL410") c["bad_quality"] = "trip";
  }
  for (auto& e : j["effects"]) e.erase("actuator_ms");
  return j.dump(2);
}

// The signatures the examples had on main before any timing key existed
// (`cemv signature examples/*/matrix.json` at commit 8f391fe).
TEST(ResponseFormat, ExamplesWithoutTimingKeysKeepTheirSignatures) {
  const std::pair<const char*, const char*> examples[] = {
      {"burner-management", "0ae9d4b837071aaf917c2384399be5e30f254812178f0f9fa593aefba7b7bf0a"},
      {"compressor", "9c67c72fcb09c76e9e54abe9fda58d050f7494bf81bbbb8a1de68fcd999e2b75"},
      {"pipeline-hipps", "854fb9b0e79e3bd05b7852c6bd69aa2288a81a013a2649f1a9c188cb917f4c42"},
      {"tank-overfill", "e6cbb14ac78b2f0c418ec173644699783169044e06be2b5e736df2a3aea83fb0"},
  };
  for (const auto& [name, old] : examples) {
    auto file = std::filesystem::path(CEMV_SOURCE_DIR) / "examples" / name / "matrix.json";
    auto stripped = formats::parse_matrix(without_timing(read(file)), name);
    EXPECT_EQ(formats::signature(stripped), old) << name;
    // The example itself declares process safety times: its signature moved.
    EXPECT_NE(formats::signature(formats::load_matrix(file)), old) << name;
  }
}

constexpr const char* kBase = R"({"format": "cemv-matrix/1", "name": "T", "sif_groups": {"1": "Level"},
  "causes": [{"id": 1, "name": "C1", "tags": [{"name": "S1"}], "sif": [1]}],
  "effects": [{"id": 1, "name": "E1", "tags": [{"name": "Y1"}], "sif": [1]}],
  "intersections": [{"cause": 1, "effect": 1, "type": "N"}]})";

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

TEST(ResponseFormat, DefaultsAndTheNameOnlyObjectFormSignLikeTheOldFile) {
  const auto base = formats::parse_matrix(kBase, "base");
  const std::string text = formats::to_canonical_json(base);
  EXPECT_EQ(text.find("process_safety_time_ms"), std::string::npos) << text;
  EXPECT_EQ(text.find("watchdog_ms"), std::string::npos) << text;
  EXPECT_EQ(text.find("sensor_ms"), std::string::npos) << text;
  EXPECT_EQ(text.find("actuator_ms"), std::string::npos) << text;
  for (const auto& variant : {
           replaced(kBase, R"("1": "Level")", R"("1": {"name": "Level"})"),
           replaced(kBase, R"("1": "Level")", R"("1": {"name": "Level", "process_safety_time_ms": null})"),
           replaced(kBase, R"("sif": [1]}],)", R"("sif": [1], "sensor_ms": 0}],)"),
           replaced(kBase, R"("name": "E1",)", R"("name": "E1", "actuator_ms": 0,)"),
           replaced(kBase, R"("name": "T",)", R"("name": "T", "watchdog_ms": null,)"),
       })
    EXPECT_EQ(formats::signature(formats::parse_matrix(variant, "variant")), formats::signature(base)) << variant;
}

TEST(ResponseFormat, DeclaredTimingKeysRoundTripAndChangeTheSignature) {
  std::string text = replaced(kBase, R"("1": "Level")", R"("1": {"name": "Level", "process_safety_time_ms": 8000})");
  text = replaced(text, R"("name": "T",)", R"("name": "T", "watchdog_ms": 200,)");
  text = replaced(text, R"("sif": [1]}],)", R"("sif": [1], "sensor_ms": 300}],)");
  text = replaced(text, R"("name": "E1",)", R"("name": "E1", "actuator_ms": 2500,)");
  const auto m = formats::parse_matrix(text, "timed");
  EXPECT_EQ(m.process_safety_time_ms.at(1), 8000u);
  EXPECT_EQ(*m.watchdog_ms, 200u);
  EXPECT_EQ(m.causes[0].sensor_ms, 300u);
  EXPECT_EQ(m.effects[0].actuator_ms, 2500u);
  const std::string canonical = formats::to_canonical_json(m);
  const auto again = formats::parse_matrix(canonical, "again");
  EXPECT_EQ(formats::to_canonical_json(again), canonical);
  EXPECT_NE(formats::signature(m), formats::signature(formats::parse_matrix(kBase, "base")));
}

TEST(ResponseFormat, BadTimingValuesAreLoadErrors) {
  for (const auto& bad : {
           replaced(kBase, R"("1": "Level")", R"("1": {"name": "Level", "process_safety_time_ms": 0})"),
           replaced(kBase, R"("1": "Level")", R"("1": {"process_safety_time_ms": 100})"),
           replaced(kBase, R"("1": "Level")", R"("1": {"name": "Level", "pst": 100})"),
           replaced(kBase, R"("name": "T",)", R"("name": "T", "watchdog_ms": 0,)"),
           replaced(kBase, R"("sif": [1]}],)", R"("sif": [1], "sensor_ms": -1}],)"),
       })
    EXPECT_THROW(formats::parse_matrix(bad, "bad"), formats::LoadError) << bad;
}

}  // namespace
