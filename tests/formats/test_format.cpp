// cemv-matrix/1: loading, defaults, the canonical form, the signature and
// float_text. The malformed-file table is test_format_malformed.cpp.
#include <gtest/gtest.h>

#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <fstream>
#include <random>
#include <sstream>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "formats/matrix_json.hpp"
#include "model/names.hpp"
#include "model/text.hpp"
#include "tests/support/random_matrix.hpp"

using namespace cemv::model;
using namespace cemv::formats;
namespace fs = std::filesystem;

namespace {

// An example matrix, verbatim (intersection 2 names a cause
// that does not exist: that is validate()'s business, not the loader's).
const char* kFormatExample = R"({
  "format": "cemv-matrix/1",
  "name": "TANK_100",
  "title": "Tank 100 overfill protection",
  "cycle_ms": 100,
  "sif_groups": {"1": "Tank 100 level"},
  "secure_write": {"enable_tag": "EN_SWC"},
  "group_deactivation": {"enable_tag": "EN_GDM", "set_tag": "SET_GDM"},
  "causes": [
    {
      "id": 1, "name": "LT100_HH", "description": "Tank 100 level high-high", "sil": 2,
      "input": "analog",
      "function": "2oo3",
      "tags": [ {"name": "LT_100A", "ett": false, "soft_bypass_allowed": true},
                {"name": "LT_100B"}, {"name": "LT_100C"} ],
      "analog": {"limit_type": "high", "limit": 90.0, "hysteresis": 2.0,
                 "prewarning": 85.0, "delta": 5.0, "unit": "%"},
      "bad_quality": "degrade",
      "time": {"mode": "on_delay", "ms": 2000},
      "auto_ack": true,
      "soft_bypass": {"allowed": true, "max_s": 3600, "prealarm_s": 3000},
      "bypass_tag": "HS_100_BYP",
      "inhibit_tag": null,
      "first_out_group": 1,
      "mutually_locked_maintenance": false,
      "sif": [1]
    }
  ],
  "effects": [
    {
      "id": 1, "name": "CLOSE_INLET", "description": "Close inlet valve XV-101", "sil": 2,
      "function": "normal",
      "tags": [ {"name": "XV_101", "ett": false} ],
      "output_delay_ms": 0,
      "soft_bypass_allowed": false,
      "bypass_tag": null,
      "reset_tag": "HS_101_RST",
      "override": {"max_s": 600, "prealarm_s": 540},
      "process_data": {"tag": "XV_101_BPCS", "pass_through": true, "mask_tag": null},
      "sif": [1]
    }
  ],
  "intersections": [
    {"cause": 1, "effect": 1, "type": "N"},
    {"cause": 2, "effect": 1, "type": "S", "xoon": 2}
  ]
})";

// Every field left at its default: only what the format requires.
const char* kMinimal = R"({"format": "cemv-matrix/1", "name": "M",
  "causes": [{"id": 1, "name": "C1", "tags": [{"name": "T1"}]}],
  "effects": [{"id": 1, "name": "E1", "tags": [{"name": "Y1"}]}],
  "intersections": [{"cause": 1, "effect": 1, "type": "N"}]})";

// ---- Deep comparison of two matrices, field by field ----------------------------
#define SAME(field) EXPECT_EQ(a.field, b.field) << where << "." #field

void expect_same(const Cause& a, const Cause& b, const std::string& where) {
  SAME(id); SAME(name); SAME(description); SAME(sil); SAME(input); SAME(function);
  ASSERT_EQ(a.tags.size(), b.tags.size()) << where;
  for (std::size_t i = 0; i < a.tags.size(); ++i) {
    SAME(tags[i].name); SAME(tags[i].ett); SAME(tags[i].soft_bypass_allowed);
  }
  ASSERT_EQ(a.analog.has_value(), b.analog.has_value()) << where;
  if (a.analog) {
    SAME(analog->limit_type); SAME(analog->limit); SAME(analog->hysteresis);
    SAME(analog->prewarning); SAME(analog->delta); SAME(analog->unit);
  }
  SAME(bad_quality); SAME(time.mode); SAME(time.ms); SAME(auto_ack);
  SAME(soft_bypass.allowed); SAME(soft_bypass.max_s); SAME(soft_bypass.prealarm_s);
  SAME(bypass_tag); SAME(inhibit_tag); SAME(first_out_group); SAME(mutually_locked_maintenance);
  SAME(sif); SAME(note);
}

void expect_same(const Effect& a, const Effect& b, const std::string& where) {
  SAME(id); SAME(name); SAME(description); SAME(sil); SAME(function);
  ASSERT_EQ(a.tags.size(), b.tags.size()) << where;
  for (std::size_t i = 0; i < a.tags.size(); ++i) {
    SAME(tags[i].name); SAME(tags[i].ett);
  }
  SAME(output_delay_ms); SAME(soft_bypass_allowed); SAME(bypass_tag); SAME(reset_tag);
  ASSERT_EQ(a.override_time.has_value(), b.override_time.has_value()) << where;
  if (a.override_time) {
    SAME(override_time->max_s); SAME(override_time->prealarm_s);
  }
  ASSERT_EQ(a.process_data.has_value(), b.process_data.has_value()) << where;
  if (a.process_data) {
    SAME(process_data->tag); SAME(process_data->pass_through); SAME(process_data->mask_tag);
  }
  SAME(mutually_locked_maintenance); SAME(sif); SAME(note);
}

void expect_same(const Matrix& a, const Matrix& b) {
  const std::string where = "matrix";
  SAME(name); SAME(title); SAME(cycle_ms); SAME(sif_groups);
  ASSERT_EQ(a.secure_write.has_value(), b.secure_write.has_value());
  if (a.secure_write) {
    SAME(secure_write->enable_tag);
  }
  ASSERT_EQ(a.group_deactivation.has_value(), b.group_deactivation.has_value());
  if (a.group_deactivation) {
    SAME(group_deactivation->enable_tag); SAME(group_deactivation->set_tag);
  }
  ASSERT_EQ(a.causes.size(), b.causes.size());
  for (std::size_t i = 0; i < a.causes.size(); ++i)
    expect_same(a.causes[i], b.causes[i], "causes[" + std::to_string(i) + "]");
  ASSERT_EQ(a.effects.size(), b.effects.size());
  for (std::size_t i = 0; i < a.effects.size(); ++i)
    expect_same(a.effects[i], b.effects[i], "effects[" + std::to_string(i) + "]");
  ASSERT_EQ(a.intersections.size(), b.intersections.size());
  for (std::size_t i = 0; i < a.intersections.size(); ++i) {
    SAME(intersections[i].cause); SAME(intersections[i].effect); SAME(intersections[i].type);
    SAME(intersections[i].xoon); SAME(intersections[i].note);
  }
}
#undef SAME

// Canonical text -> matrix -> canonical text is the identity, and the matrix
// read back equals the one written.
void expect_canonical_round_trip(const Matrix& m) {
  std::string text = to_canonical_json(m);
  Matrix back = parse_matrix(text);
  expect_same(m, back);
  EXPECT_EQ(to_canonical_json(back), text);
  EXPECT_EQ(signature(back), signature(m));
}

std::vector<std::string> issues_of(std::string_view text) {
  try {
    parse_matrix(text);
  } catch (const LoadError& e) {
    std::vector<std::string> out;
    for (const auto& i : e.issues()) out.push_back(i.str());
    return out;
  }
  return {};
}

fs::path fresh_temp_dir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("cemv-format-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

// ---- Loading ---------------------------------------------------------------------

TEST(Load, ReadsEveryFieldOfTheFormatExample) {
  Matrix m = parse_matrix(kFormatExample);
  EXPECT_EQ(m.name, "TANK_100");
  EXPECT_EQ(m.title, "Tank 100 overfill protection");
  EXPECT_EQ(m.cycle_ms, 100u);
  EXPECT_EQ(m.sif_groups, (std::map<int, std::string>{{1, "Tank 100 level"}}));
  ASSERT_TRUE(m.secure_write);
  EXPECT_EQ(m.secure_write->enable_tag, "EN_SWC");
  ASSERT_TRUE(m.group_deactivation);
  EXPECT_EQ(m.group_deactivation->set_tag, "SET_GDM");

  ASSERT_EQ(m.causes.size(), 1u);
  const Cause& c = m.causes[0];
  EXPECT_EQ(c.input, InputKind::Analog);
  EXPECT_EQ(c.function, CauseFunction::TwoOoThree);
  ASSERT_EQ(c.tags.size(), 3u);
  EXPECT_EQ(c.tags[1].name, "LT_100B");
  ASSERT_TRUE(c.analog);
  EXPECT_EQ(c.analog->limit_type, LimitType::High);
  EXPECT_EQ(c.analog->limit, 90.0f);
  EXPECT_EQ(c.analog->hysteresis, 2.0f);
  EXPECT_EQ(c.analog->prewarning, std::optional<float>(85.0f));
  EXPECT_EQ(c.analog->delta, 5.0f);
  EXPECT_EQ(c.analog->unit, "%");
  EXPECT_EQ(c.bad_quality, BadQuality::Degrade);
  EXPECT_EQ(c.time.mode, TimeMode::OnDelay);
  EXPECT_EQ(c.time.ms, 2000u);
  EXPECT_EQ(c.soft_bypass.max_s, 3600u);
  EXPECT_EQ(c.soft_bypass.prealarm_s, 3000u);
  EXPECT_EQ(c.bypass_tag, std::optional<std::string>("HS_100_BYP"));
  EXPECT_FALSE(c.inhibit_tag);
  EXPECT_EQ(c.first_out_group, 1);
  EXPECT_EQ(c.sif, std::vector<int>{1});

  ASSERT_EQ(m.effects.size(), 1u);
  const Effect& e = m.effects[0];
  EXPECT_EQ(e.reset_tag, std::optional<std::string>("HS_101_RST"));
  ASSERT_TRUE(e.override_time);
  EXPECT_EQ(e.override_time->max_s, 600u);
  EXPECT_EQ(e.override_time->prealarm_s, 540u);
  ASSERT_TRUE(e.process_data);
  EXPECT_EQ(e.process_data->tag, std::optional<std::string>("XV_101_BPCS"));
  EXPECT_TRUE(e.process_data->pass_through);
  EXPECT_FALSE(e.process_data->mask_tag);

  ASSERT_EQ(m.intersections.size(), 2u);
  EXPECT_EQ(m.intersections[1].type, IntersectionType::S);
  EXPECT_EQ(m.intersections[1].xoon, std::optional<int>(2));
  EXPECT_FALSE(m.intersections[0].xoon);
}

TEST(Load, AppliesTheDefaultsOfTheFormat) {
  Matrix m = parse_matrix(kMinimal);
  EXPECT_EQ(m.title, "");
  EXPECT_EQ(m.cycle_ms, 100u);
  EXPECT_TRUE(m.sif_groups.empty());
  EXPECT_FALSE(m.secure_write);
  EXPECT_FALSE(m.group_deactivation);
  const Cause& c = m.causes.at(0);
  EXPECT_EQ(c.description, "");
  EXPECT_EQ(c.sil, 0);
  EXPECT_EQ(c.input, InputKind::Discrete);
  EXPECT_EQ(c.function, CauseFunction::Normal);
  EXPECT_FALSE(c.tags.at(0).ett);
  EXPECT_TRUE(c.tags.at(0).soft_bypass_allowed);
  EXPECT_FALSE(c.analog);
  EXPECT_EQ(c.bad_quality, BadQuality::Trip);
  EXPECT_EQ(c.time.mode, TimeMode::None);
  EXPECT_EQ(c.time.ms, 0u);
  EXPECT_TRUE(c.auto_ack);
  EXPECT_TRUE(c.soft_bypass.allowed);
  EXPECT_EQ(c.soft_bypass.max_s, 0u);
  EXPECT_FALSE(c.bypass_tag);
  EXPECT_FALSE(c.inhibit_tag);
  EXPECT_EQ(c.first_out_group, 0);
  EXPECT_FALSE(c.mutually_locked_maintenance);
  EXPECT_TRUE(c.sif.empty());
  EXPECT_EQ(c.note, "");
  const Effect& e = m.effects.at(0);
  EXPECT_EQ(e.function, EffectFunction::Normal);
  EXPECT_FALSE(e.tags.at(0).ett);
  EXPECT_EQ(e.output_delay_ms, 0u);
  EXPECT_FALSE(e.soft_bypass_allowed);
  EXPECT_FALSE(e.bypass_tag);
  EXPECT_FALSE(e.reset_tag);
  EXPECT_FALSE(e.override_time);
  EXPECT_FALSE(e.process_data);
  EXPECT_FALSE(e.mutually_locked_maintenance);
  const Intersection& x = m.intersections.at(0);
  EXPECT_FALSE(x.xoon);
  EXPECT_EQ(x.note, "");
}

TEST(Load, AnalogDefaultsAndOptionalBlocks) {
  Matrix m = parse_matrix(R"({"format": "cemv-matrix/1", "name": "M",
    "causes": [{"id": 1, "name": "C1", "input": "analog", "tags": [{"name": "T1"}],
                "analog": {"limit_type": "low", "limit": -2.5}}],
    "effects": [{"id": 1, "name": "E1", "tags": [{"name": "Y1"}], "override": {"max_s": 60},
                 "process_data": {}}]})");
  const AnalogParams& a = *m.causes.at(0).analog;
  EXPECT_EQ(a.limit_type, LimitType::Low);
  EXPECT_EQ(a.limit, -2.5f);
  EXPECT_EQ(a.hysteresis, 0.0f);
  EXPECT_FALSE(a.prewarning);
  EXPECT_EQ(a.delta, 0.0f);
  EXPECT_EQ(a.unit, "");
  EXPECT_EQ(m.effects.at(0).override_time->prealarm_s, 0u);
  ASSERT_TRUE(m.effects.at(0).process_data);
  EXPECT_FALSE(m.effects.at(0).process_data->tag);
  EXPECT_FALSE(m.effects.at(0).process_data->pass_through);
}

TEST(Load, OptionalFieldsAcceptNullAndAbsenceAlike) {
  Matrix with_null = parse_matrix(R"({"format": "cemv-matrix/1", "name": "M",
    "secure_write": null, "group_deactivation": null,
    "causes": [{"id": 1, "name": "C1", "tags": [{"name": "T1"}], "analog": null,
                "bypass_tag": null, "inhibit_tag": null}],
    "effects": [{"id": 1, "name": "E1", "tags": [{"name": "Y1"}], "bypass_tag": null,
                 "reset_tag": null, "override": null, "process_data": null}],
    "intersections": [{"cause": 1, "effect": 1, "type": "N", "xoon": null}]})");
  EXPECT_EQ(to_canonical_json(with_null), to_canonical_json(parse_matrix(kMinimal)));
}

TEST(Load, CommentElementsMayHaveNoTags) {
  Matrix m = parse_matrix(R"({"format": "cemv-matrix/1", "name": "M",
    "causes": [{"id": 1, "name": "NOTE_C", "function": "comment"}],
    "effects": [{"id": 1, "name": "NOTE_E", "function": "comment", "tags": []}]})");
  EXPECT_TRUE(m.causes.at(0).tags.empty());
  EXPECT_TRUE(m.effects.at(0).tags.empty());
}

TEST(Load, IntegralFloatsAreIntegers) {
  Matrix m = parse_matrix(R"({"format": "cemv-matrix/1", "name": "M", "cycle_ms": 250.0})");
  EXPECT_EQ(m.cycle_ms, 250u);
}

// Duplicates and dangling references are plausibility findings with rule ids
// (validate()), so the loader must let them through, sorted by id.
TEST(Load, LeavesCrossElementProblemsToValidate) {
  Matrix m = parse_matrix(R"({"format": "cemv-matrix/1", "name": "M",
    "causes": [{"id": 3, "name": "C3", "tags": [{"name": "T3"}]},
               {"id": 1, "name": "FIRST", "tags": [{"name": "T1"}]},
               {"id": 1, "name": "SECOND", "tags": [{"name": "T1"}]}],
    "effects": [{"id": 2, "name": "E2", "tags": [{"name": "T3"}]},
                {"id": 1, "name": "E2", "tags": [{"name": "Y1"}]}],
    "intersections": [{"cause": 9, "effect": 1, "type": "X"},
                      {"cause": 1, "effect": 2, "type": "N"},
                      {"cause": 1, "effect": 2, "type": "S"}]})");
  ASSERT_EQ(m.causes.size(), 3u);
  EXPECT_EQ(m.causes[0].name, "FIRST");   // stable: file order among equal ids
  EXPECT_EQ(m.causes[1].name, "SECOND");
  EXPECT_EQ(m.causes[2].id, 3);
  EXPECT_EQ(m.effects[0].id, 1);
  ASSERT_NE(m.find_cause(3), nullptr);
  EXPECT_EQ(m.find_effect(2)->name, "E2");
  EXPECT_EQ(m.intersections[0].type, IntersectionType::N);
  EXPECT_EQ(m.intersections[1].type, IntersectionType::S);
  EXPECT_EQ(m.intersections[2].cause, 9);
  EXPECT_NE(m.find_intersection(9, 1), nullptr);
}

TEST(Load, SifListsAreSortedSets) {
  Matrix m = parse_matrix(R"({"format": "cemv-matrix/1", "name": "M",
    "causes": [{"id": 1, "name": "C1", "tags": [{"name": "T1"}], "sif": [64, 2, 17]}]})");
  EXPECT_EQ(m.causes[0].sif, (std::vector<int>{2, 17, 64}));
}

TEST(Load, SingleRangeBoundariesOfRealValues) {
  auto limit_of = [](const std::string& number) {
    return parse_matrix(R"({"format": "cemv-matrix/1", "name": "M", "causes": [{"id": 1, "name": "C1",
      "input": "analog", "tags": [{"name": "T1"}], "analog": {"limit_type": "high", "limit": )" +
                        number + "}}]}")
        .causes[0]
        .analog->limit;
  };
  EXPECT_EQ(limit_of("3.4028235e+38"), FLT_MAX);
  EXPECT_EQ(limit_of("-3.4028235e38"), -FLT_MAX);
  EXPECT_EQ(limit_of("3.40282356e38"), FLT_MAX);  // rounds down to FLT_MAX
  EXPECT_EQ(limit_of("1e-50"), 0.0f);             // underflows to zero
  EXPECT_FALSE(std::signbit(limit_of("-0.0")));    // one zero, one canonical text
  EXPECT_EQ(limit_of("0.1"), 0.1f);
  EXPECT_EQ(limit_of("90"), 90.0f);
  EXPECT_THROW(limit_of("3.4028236e38"), LoadError);  // would round to infinity
  EXPECT_THROW(limit_of("-1e300"), LoadError);
}

TEST(Load, ReportsEveryProblemInFileOrder) {
  auto issues = issues_of(R"({"format": "cemv-matrix/1", "name": "bad name",
    "causes": [{"id": 0, "name": "C1", "tags": [{"name": "#TIC__543"}], "bypas_tag": "X"},
               {"id": 2, "name": "C2", "function": "2003", "tags": [{"name": "A"}]}],
    "effects": [{"name": "E1", "tags": [{"name": "Y1", "ett": "no"}]}]})");
  std::vector<std::string> expected = {
      "name: 'bad name' contains ' '; names allow only letters, digits and '_' (6.3.4)",
      "causes[0].id: 0 is out of range 1-128 (causes are numbered 1-128, 3.4)",
      "causes[0].tags[0].name: '#TIC__543' repeats '_'",
      "causes[0].bypas_tag: unknown key (did you mean 'bypass_tag'?)",
      "causes[1].function: '2003' is not one of 'normal', 'and', 'or', '2oo3', 'comment' (did you mean '2oo3'?)",
      "effects[0].tags[0].ett: expected true or false, got the string 'no'",
      "effects[0].id: required key is missing",
  };
  EXPECT_EQ(issues, expected);
}

TEST(Load, StopsListingAfterAHundredProblems) {
  std::string text = R"({"format": "cemv-matrix/1", "name": "M", "causes": [)";
  for (int i = 0; i < 500; ++i) text += std::string(i ? "," : "") + R"({"id": 0, "name": "-"})";
  text += "]}";
  auto issues = issues_of(text);
  ASSERT_EQ(issues.size(), 101u);
  EXPECT_EQ(issues.back(), "too many problems; the rest are not listed");
}

TEST(Load, FileErrorsNameTheFile) {
  try {
    load_matrix("/nonexistent/cemv/matrix.json");
    FAIL() << "no LoadError";
  } catch (const LoadError& e) {
    ASSERT_EQ(e.issues().size(), 1u);
    EXPECT_EQ(e.issues()[0].where, "/nonexistent/cemv/matrix.json");
    EXPECT_NE(e.issues()[0].what.find("cannot open"), std::string::npos);
  }
  fs::path dir = fresh_temp_dir("dir");
  try {
    load_matrix(dir);
    FAIL() << "no LoadError";
  } catch (const LoadError& e) {
    EXPECT_EQ(e.issues().at(0).what, "is a directory, not a file");
  }
  fs::remove_all(dir);
}

// ---- Hostile inputs, generated here rather than committed ---------------------------

TEST(Hostile, A50MegabyteFileIsRejectedBeforeParsing) {
  fs::path dir = fresh_temp_dir("big");
  fs::path file = dir / "big.json";
  {
    std::ofstream out(file, std::ios::binary);
    std::string chunk(1 << 20, ' ');
    chunk.front() = '[';
    for (int i = 0; i < 50; ++i) {
      out.write(chunk.data(), static_cast<std::streamsize>(chunk.size()));
      chunk.front() = ' ';
    }
    out << "]";
  }
  ASSERT_GE(fs::file_size(file), 50u << 20);
  try {
    load_matrix(file);
    FAIL() << "no LoadError";
  } catch (const LoadError& e) {
    EXPECT_EQ(e.issues().at(0).where, file.string());
    EXPECT_NE(e.issues().at(0).what.find("larger than the limit of 16777216 bytes"), std::string::npos);
  }
  fs::remove_all(dir);
  EXPECT_THROW(parse_matrix(std::string(kMaxFileBytes + 1, ' ')), LoadError);
}

TEST(Hostile, DeepNestingIsRejectedWithItsPosition) {
  auto first = [](const std::string& text) { return issues_of(text).at(0); };
  EXPECT_EQ(first(std::string(100000, '[')), "line 1, column 65: JSON nesting deeper than 64 levels (a matrix needs 5)");
  std::string objects;
  for (int i = 0; i < 100000; ++i) objects += "{\"a\":";
  EXPECT_EQ(first(objects), "line 1, column 321: JSON nesting deeper than 64 levels (a matrix needs 5)");
  // Brackets inside strings are text, not nesting.
  std::string in_string = R"({"format": "cemv-matrix/1", "name": "M", "title": "\")" + std::string(1000, '[') + "\"}";
  EXPECT_EQ(parse_matrix(in_string).title, "\"" + std::string(1000, '['));
}

TEST(Hostile, WideObjectsAreRejectedBeforeParsing) {
  std::string text = R"({"format": "cemv-matrix/1", "name": "M", "title": "t")";
  for (int i = 0; i < 200000; ++i) text += ", \"k" + std::to_string(i) + "\": 0";
  text += "}";
  auto issues = issues_of(text);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_NE(issues[0].find("object with more than 256 members"), std::string::npos) << issues[0];
}

TEST(Hostile, LoadsFromADeviceWithoutSizeStopAtTheCap) {
  if (!fs::exists("/dev/zero")) GTEST_FAIL() << "/dev/zero missing";
  try {
    load_matrix("/dev/zero");
    FAIL() << "no LoadError";
  } catch (const LoadError& e) {
    EXPECT_NE(e.issues().at(0).what.find("larger than the limit"), std::string::npos);
  }
}

// ---- Canonical form ------------------------------------------------------------------

TEST(Canonical, IsSortedIndentedAndEndsWithANewline) {
  std::string text = to_canonical_json(parse_matrix(kMinimal));
  EXPECT_EQ(text.substr(0, 16), "{\n  \"causes\": [\n");
  EXPECT_EQ(text.back(), '\n');
  EXPECT_NE(text.find("\n  \"format\": \"cemv-matrix/1\",\n"), std::string::npos);
  // Absent optionals are written as null, every default spelt out.
  EXPECT_NE(text.find("\"analog\": null"), std::string::npos);
  EXPECT_NE(text.find("\"bypass_tag\": null"), std::string::npos);
  EXPECT_NE(text.find("\"override\": null"), std::string::npos);
  EXPECT_NE(text.find("\"secure_write\": null"), std::string::npos);
  EXPECT_NE(text.find("\"xoon\": null"), std::string::npos);
  EXPECT_NE(text.find("\"soft_bypass_allowed\": true"), std::string::npos);
  EXPECT_NE(text.find("\"bad_quality\": \"trip\""), std::string::npos);
  EXPECT_NE(text.find("\"sif_groups\": {}"), std::string::npos);
  EXPECT_NE(text.find("\"cycle_ms\": 100"), std::string::npos);
}

// Every object of the canonical text, at every depth, has its keys in strictly
// increasing byte order.
TEST(Canonical, EveryObjectHasSortedKeys) {
  std::string text = to_canonical_json(cemv::testsupport::big_matrix(1));
  auto doc = nlohmann::ordered_json::parse(text);
  int objects = 0;
  std::function<void(const nlohmann::ordered_json&)> walk = [&](const nlohmann::ordered_json& j) {
    if (j.is_object()) {
      ++objects;
      std::string previous;
      bool first = true;
      for (auto it = j.begin(); it != j.end(); ++it) {
        EXPECT_TRUE(first || previous < it.key()) << previous << " before " << it.key();
        previous = it.key();
        first = false;
        walk(it.value());
      }
    } else if (j.is_array()) {
      for (const auto& e : j) walk(e);
    }
  };
  walk(doc);
  EXPECT_GT(objects, 1000);
}

TEST(Canonical, EscapesTextAndRepairsBrokenUtf8FromCode) {
  Matrix m = parse_matrix(kMinimal);
  m.title = "a\"b\\c\nd\x01 \xC3\xA9 \xFF end";  // built in code: not loadable as is
  std::string text = to_canonical_json(m);
  EXPECT_NE(text.find("\"title\": \"a\\\"b\\\\c\\nd\\u0001 \xC3\xA9 \xEF\xBF\xBD end\""), std::string::npos) << text;
  // The canonical text is valid JSON even then (the loader itself rejects the
  // control characters, which is why this goes through nlohmann).
  EXPECT_EQ(nlohmann::json::parse(text)["title"], "a\"b\\c\nd\x01 \xC3\xA9 \xEF\xBF\xBD end");
}

TEST(Canonical, RoundTripsTheFormatExampleAndTheMinimalFile) {
  expect_canonical_round_trip(parse_matrix(kFormatExample));
  expect_canonical_round_trip(parse_matrix(kMinimal));
}

TEST(Canonical, RoundTripsRandomMatricesOfEveryOption) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    Matrix m = cemv::testsupport::random_matrix(seed);
    // The generator builds matrices in code: the canonical form must also hold
    // for them, whatever order they are in.
    std::string text = to_canonical_json(m);
    Matrix back = parse_matrix(text);
    EXPECT_EQ(to_canonical_json(back), text);
    expect_canonical_round_trip(back);
  }
  expect_canonical_round_trip(parse_matrix(to_canonical_json(cemv::testsupport::big_matrix(1))));
}

TEST(Canonical, RoundTripsTheBundledExamples) {
  int seen = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(CEMV_SOURCE_DIR) / "examples")) {
    fs::path file = entry.path() / "matrix.json";
    if (!fs::exists(file)) continue;
    SCOPED_TRACE(file.string());
    expect_canonical_round_trip(load_matrix(file));
    ++seen;
  }
  EXPECT_GE(seen, 4);
}

TEST(Canonical, DoesNotDependOnKeyOrderElementOrderOrSpacing) {
  const char* shuffled = R"({"intersections":[{"type":"N","effect":1,"cause":1}],
    "effects":[{"tags":[{"name":"Y1"}],"name":"E1","id":1}],
    "causes":[{"tags":[{"name":"T1"}],"name":"C1","id":1}],"name":"M","format":"cemv-matrix/1"})";
  EXPECT_EQ(to_canonical_json(parse_matrix(shuffled)), to_canonical_json(parse_matrix(kMinimal)));

  Matrix a = parse_matrix(R"({"format": "cemv-matrix/1", "name": "M",
    "causes": [{"id": 2, "name": "C2", "tags": [{"name": "T2"}]}, {"id": 1, "name": "C1", "tags": [{"name": "T1"}]}]})");
  Matrix b = parse_matrix(R"({"format": "cemv-matrix/1", "name": "M",
    "causes": [{"id": 1, "name": "C1", "tags": [{"name": "T1"}]}, {"id": 2, "name": "C2", "tags": [{"name": "T2"}]}]})");
  EXPECT_EQ(to_canonical_json(a), to_canonical_json(b));
  // A matrix built in code in any order is written sorted.
  std::swap(b.causes[0], b.causes[1]);
  EXPECT_EQ(to_canonical_json(a), to_canonical_json(b));
}

TEST(Canonical, WritesRealsInTheirShortestSingleForm) {
  Matrix m = parse_matrix(kFormatExample);
  m.causes[0].analog->limit = 0.1f;
  m.causes[0].analog->hysteresis = -0.0f;
  m.causes[0].analog->delta = 1e20f;
  std::string text = to_canonical_json(m);
  EXPECT_NE(text.find("\"limit\": 0.1,"), std::string::npos);
  EXPECT_NE(text.find("\"hysteresis\": 0,"), std::string::npos);
  EXPECT_NE(text.find("\"delta\": 1e+20,"), std::string::npos);
  EXPECT_NE(text.find("\"prewarning\": 85,"), std::string::npos);
  m.causes[0].analog->limit = std::nanf("");
  EXPECT_THROW(to_canonical_json(m), std::invalid_argument);
}

TEST(Canonical, SaveWritesExactlyTheCanonicalText) {
  fs::path dir = fresh_temp_dir("save");
  Matrix m = parse_matrix(kFormatExample);
  save_matrix(m, dir / "out.json");
  std::ifstream in(dir / "out.json", std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(ss.str(), to_canonical_json(m));
  EXPECT_THROW(save_matrix(m, dir / "no" / "such" / "dir.json"), std::runtime_error);
  fs::remove_all(dir);
}

// ---- Signature -------------------------------------------------------------------------

TEST(Signature, IsTheSha256OfTheCanonicalText) {
  // Pinned: `cemv fmt` of kMinimal piped through sha256sum gave this value. A
  // change means every recorded signature changes: that must be deliberate.
  EXPECT_EQ(signature(parse_matrix(kMinimal)), "76bfd26b01a3fe1983fdbc9b8c595ce49c00e7d25d1c8ab2c62c68464e83fdc2");
}

TEST(Signature, ChangesWithAnyFieldAndOnlyThen) {
  Matrix m = parse_matrix(kFormatExample);
  const std::string base = signature(m);
  EXPECT_EQ(base.size(), 64u);
  EXPECT_EQ(base.find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_EQ(signature(parse_matrix(to_canonical_json(m))), base);
  Matrix changed = m;
  changed.causes[0].analog->limit = std::nextafter(90.0f, 100.0f);
  EXPECT_NE(signature(changed), base);
  changed = m;
  changed.effects[0].note = "x";
  EXPECT_NE(signature(changed), base);
  changed = m;
  changed.intersections[1].xoon.reset();
  EXPECT_NE(signature(changed), base);
}

// ---- float_text --------------------------------------------------------------------

TEST(FloatText, KnownValues) {
  EXPECT_EQ(float_text(0.1f), "0.1");
  EXPECT_EQ(float_text(90.0f), "90");
  EXPECT_EQ(float_text(-2.5f), "-2.5");
  EXPECT_EQ(float_text(1e20f), "1e+20");
  EXPECT_EQ(float_text(FLT_MAX), "3.4028235e+38");
  EXPECT_EQ(float_text(std::numeric_limits<float>::denorm_min()), "1e-45");
  EXPECT_EQ(float_text(123456.7f), "123456.7");
  EXPECT_EQ(float_text(16777216.0f), "16777216");
}

// The loader reads numbers as doubles and rounds to float; the text float_text
// writes must survive exactly that path, for every kind of float.
TEST(FloatText, RoundTripsThroughTheLoadersDoublePath) {
  std::mt19937 rng(12345);
  int checked = 0;
  for (int i = 0; i < 1'000'000; ++i) {
    std::uint32_t bits = static_cast<std::uint32_t>(rng());
    float f;
    std::memcpy(&f, &bits, sizeof f);
    if (!std::isfinite(f)) continue;
    std::string text = float_text(f);
    float via_double = static_cast<float>(std::strtod(text.c_str(), nullptr));
    ASSERT_EQ(std::memcmp(&via_double, &f, sizeof f), 0) << text;
    float via_float = 0;
    std::from_chars(text.data(), text.data() + text.size(), via_float);
    ASSERT_EQ(std::memcmp(&via_float, &f, sizeof f), 0) << text;
    ++checked;
  }
  EXPECT_GT(checked, 990'000);
}

// ---- Names ---------------------------------------------------------------------------

TEST(TagNames, AcceptsTheValidFormsOf614) {
  for (const char* name : {"LT_100A", "TIC2344", "tic2344", "E1.6", "A'B", "A@B", "A#B", "#TIC4711",
                           "#TIC 4711", "#_4_321", "TIC4711#", "4711#", "#TIC4711#", "Cause[3]", "Effect[12]",
                           "Effect[2][1]", "!$&()*+,-:;<=>?[]^_`", "ABCDEFGHIJKLMNOPQRSTUVWX", "a b", "/\\"}) {
    EXPECT_EQ(tag_name_problem(name), std::nullopt) << name;
  }
}

TEST(TagNames, RejectsEachRuleOf614WithAClearReason) {
  const std::pair<const char*, const char*> cases[] = {
      {"", "tag name is empty"},
      {"ABCDEFGHIJKLMNOPQRSTUVWXY", "'ABCDEFGHIJKLMNOPQRSTUVWXY' is longer than 24 characters"},
      {"A\"B", "'A\"B' contains '\"', which tag names must not use"},
      {"A%B", "'A%B' contains '%', which tag names must not use"},
      {"A~B", "'A~B' contains '~', which tag names must not use"},
      {"A{B", "'A{B' contains the byte 0x7B, outside the permitted characters 0x20-0x7A"},
      {"A|B", "'A|B' contains the byte 0x7C, outside the permitted characters 0x20-0x7A"},
      {" AB", "' AB' starts with a blank"},
      {"AB ", "'AB ' ends with a blank"},
      {"AB'", "'AB'' ends with an inverted comma (')"},
      {"@AB", "'@AB' starts with '@', which marks an external address"},
      {"#", "'#' has no name besides '#'"},
      {"##", "'##' has no name besides '#'"},
      {"#4711", "'#4711' must start with a letter or '_' after the '#' prefix"},
      {"# 4 321", "'# 4 321' must start with a letter or '_' after the '#' prefix"},
      {"_TIC#", "'_TIC#' must start with a letter or a digit before the '#' suffix"},
      {"#TIC__543", "'#TIC__543' repeats '_'"},
      {"#TIC_4711_", "'#TIC_4711_' ends with '_'"},
      {"TIC_4711_#", "'TIC_4711_#' ends with '_'"},
      {"#TIC.4711", "'#TIC.4711' contains '.'; chart connection names ('#') allow only letters, digits, '_' and blanks"},
      {"#A#B", "'#A#B' contains '#'; chart connection names ('#') allow only letters, digits, '_' and blanks"},
      {"TIC #", "'TIC #' has a blank before the '#' suffix"},
      {"cause[1]x{", "'cause[1]x{' contains the byte 0x7B, outside the permitted characters 0x20-0x7A"},
  };
  for (auto [name, why] : cases) EXPECT_EQ(tag_name_problem(name), std::optional<std::string>(why)) << name;
}

TEST(ElementNames, LettersDigitsUnderscoreUpTo32) {
  EXPECT_EQ(element_name_problem("LT100_HH"), std::nullopt);
  EXPECT_EQ(element_name_problem(std::string(32, 'A')), std::nullopt);
  EXPECT_EQ(element_name_problem(""), std::optional<std::string>("name is empty"));
  EXPECT_TRUE(element_name_problem(std::string(33, 'A')));
  EXPECT_TRUE(element_name_problem("LT 100"));
  EXPECT_TRUE(element_name_problem("LT-100"));
  EXPECT_TRUE(element_name_problem("Ä"));
}
