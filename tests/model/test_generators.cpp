// The random matrix and scenario generators (tests/support/README.md) that the differential
// test and the benchmarks rely on: valid, reproducible, and between them using
// every option of cemv-matrix/1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "formats/matrix_json.hpp"
#include "model/vocabulary.hpp"
#include "model/validate.hpp"
#include "runtime/runtime.hpp"
#include "tests/support/random_inputs.hpp"
#include "tests/support/random_matrix.hpp"

using namespace cemv::model;
using namespace cemv::formats;
using namespace cemv::testsupport;

namespace {

constexpr int kSeeds = 500;

// Every field of a matrix as text: two matrices are equal iff their dumps are.
std::string dump(const Matrix& m) {
  std::ostringstream o;
  o << m.name << '|' << m.title << '|' << m.cycle_ms << '\n';
  for (const auto& [k, v] : m.sif_groups) o << "sif " << k << ' ' << v << '\n';
  if (m.secure_write) o << "sw " << m.secure_write->enable_tag << '\n';
  if (m.group_deactivation)
    o << "gd " << m.group_deactivation->enable_tag << ' ' << m.group_deactivation->set_tag << '\n';
  for (const auto& c : m.causes) {
    o << "C " << c.id << ' ' << c.name << '|' << c.description << '|' << c.sil << ' ' << to_string(c.input)
      << ' ' << to_string(c.function) << ' ' << to_string(c.bad_quality) << ' ' << to_string(c.time.mode) << ' '
      << c.time.ms << ' ' << c.auto_ack << ' ' << c.soft_bypass.allowed << ' ' << c.soft_bypass.max_s << ' '
      << c.soft_bypass.prealarm_s << ' ' << c.bypass_tag.value_or("-") << ' ' << c.inhibit_tag.value_or("-")
      << ' ' << c.first_out_group << ' ' << c.mutually_locked_maintenance << ' ' << c.note << '\n';
    for (const auto& t : c.tags) o << "  t " << t.name << ' ' << t.ett << ' ' << t.soft_bypass_allowed << '\n';
    if (c.analog)
      o << "  a " << to_string(c.analog->limit_type) << ' ' << c.analog->limit << ' ' << c.analog->hysteresis << ' '
        << (c.analog->prewarning ? *c.analog->prewarning : -1e30f) << ' ' << c.analog->delta << ' '
        << c.analog->unit << '\n';
    for (int s : c.sif) o << "  sif " << s << '\n';
  }
  for (const auto& e : m.effects) {
    o << "E " << e.id << ' ' << e.name << '|' << e.description << '|' << e.sil << ' ' << to_string(e.function)
      << ' ' << e.output_delay_ms << ' ' << e.soft_bypass_allowed << ' ' << e.bypass_tag.value_or("-") << ' '
      << e.reset_tag.value_or("-") << ' ' << e.mutually_locked_maintenance << ' ' << e.note << '\n';
    for (const auto& t : e.tags) o << "  t " << t.name << ' ' << t.ett << '\n';
    if (e.override_time) o << "  o " << e.override_time->max_s << ' ' << e.override_time->prealarm_s << '\n';
    if (e.process_data)
      o << "  p " << e.process_data->tag.value_or("-") << ' ' << e.process_data->pass_through << ' '
        << e.process_data->mask_tag.value_or("-") << '\n';
    for (int s : e.sif) o << "  sif " << s << '\n';
  }
  for (const auto& x : m.intersections)
    o << "X " << x.cause << ' ' << x.effect << ' ' << to_string(x.type) << ' ' << x.xoon.value_or(0) << ' '
      << x.note << '\n';
  return o.str();
}

std::string dump(const std::vector<CycleInput>& frames) {
  std::ostringstream o;
  o.precision(9);
  for (const auto& f : frames) {
    for (const auto& t : f.tags) o << t.value << (t.bad_quality ? "b " : " ");
    for (const auto& c : f.commands)
      o << '[' << to_string(c.op) << ' ' << c.cause << ' ' << c.effect << ' ' << c.tag << ' ' << c.group << ' '
        << c.on << ' ' << c.tag_name << ' ' << c.value << ']';
    o << '\n';
  }
  return o.str();
}

// The structural rules of the format and of 11.5 that a generated matrix must
// meet, checked here independently of model::validate (which checks them too).
void expect_well_formed(const Matrix& m, std::uint64_t seed) {
  SCOPED_TRACE("seed " + std::to_string(seed));
  ASSERT_GE(m.causes.size(), 1u);
  ASSERT_LE(m.causes.size(), static_cast<std::size_t>(kMaxCauses));
  ASSERT_LE(m.effects.size(), static_cast<std::size_t>(kMaxEffects));
  ASSERT_LE(m.intersections.size(), static_cast<std::size_t>(kMaxIntersections));
  auto multiple = [&](std::uint32_t ms) { return ms % m.cycle_ms == 0; };
  std::set<std::string> inputs, outputs, names;
  for (const auto& c : m.causes) {
    EXPECT_TRUE(names.insert(c.name).second) << c.name;
    auto n = tag_count_of(c.function);
    EXPECT_GE(static_cast<int>(c.tags.size()), n.min);
    EXPECT_LE(static_cast<int>(c.tags.size()), n.max);
    EXPECT_EQ(c.analog.has_value(), c.input == InputKind::Analog);
    EXPECT_TRUE(multiple(c.time.ms));
    EXPECT_EQ(c.time.ms == 0, c.time.mode == TimeMode::None);
    if (!c.auto_ack) {
      EXPECT_TRUE(c.time.mode == TimeMode::None || c.time.mode == TimeMode::OnDelay);
    }
    EXPECT_TRUE(multiple(c.soft_bypass.max_s * 1000));
    if (c.soft_bypass.prealarm_s) {
      EXPECT_LT(c.soft_bypass.prealarm_s, c.soft_bypass.max_s);
    }
    EXPECT_LE(c.first_out_group, kMaxFirstOutGroup);
    for (int s : c.sif) EXPECT_TRUE(m.sif_groups.count(s));
    if (c.analog) {
      EXPECT_GE(c.analog->hysteresis, 0.0f);
      if (c.analog->delta > 0) {
        EXPECT_GE(c.tags.size(), 2u);
        EXPECT_LT(c.analog->hysteresis, c.analog->delta);
      }
      if (c.analog->prewarning) {
        if (c.analog->limit_type == LimitType::High) EXPECT_LT(*c.analog->prewarning, c.analog->limit);
        else EXPECT_GT(*c.analog->prewarning, c.analog->limit);
      }
    }
    std::set<std::string> own;
    for (const auto& t : c.tags) {
      EXPECT_TRUE(own.insert(tag_key(t.name)).second) << "tag repeated in one cause: " << t.name;
      EXPECT_LE(t.name.size(), kMaxTagNameLength);
      if (auto r = parse_internal_ref(t.name)) {
        EXPECT_EQ(c.input, InputKind::Discrete);
        if (r->kind == InternalRef::Kind::Cause) {
          const Cause* src = m.find_cause(r->id);
          ASSERT_TRUE(src) << t.name;
          EXPECT_NE(src->function, CauseFunction::Comment);
          EXPECT_NE(src->id, c.id);
        } else {
          const Effect* src = m.find_effect(r->id);
          ASSERT_TRUE(src) << t.name;
          EXPECT_NE(src->function, EffectFunction::Comment);
          EXPECT_LE(r->tag, static_cast<int>(src->tags.size()));
        }
      } else if (c.function != CauseFunction::Comment) {
        inputs.insert(tag_key(t.name));
      }
    }
    if (c.bypass_tag) inputs.insert(tag_key(*c.bypass_tag));
    if (c.inhibit_tag) inputs.insert(tag_key(*c.inhibit_tag));
  }
  for (const auto& e : m.effects) {
    EXPECT_TRUE(names.insert(e.name).second) << e.name;
    EXPECT_GE(e.tags.size(), 1u);
    EXPECT_LE(e.tags.size(), static_cast<std::size_t>(kMaxEffectTags));
    for (const auto& t : e.tags) EXPECT_TRUE(outputs.insert(tag_key(t.name)).second) << "output twice: " << t.name;
    EXPECT_TRUE(multiple(e.output_delay_ms));
    bool overridable = false;
    int xoon_n = 0;
    std::set<int> xs;
    std::set<IntersectionType> xoon_types;
    for (const auto* x : m.intersections_of_effect(e.id)) {
      EXPECT_NE(e.function, EffectFunction::Comment);
      EXPECT_NE(x->type, IntersectionType::X);
      if (x->type == IntersectionType::V || x->type == IntersectionType::R) overridable = true;
      if (x->xoon) {
        ++xoon_n;
        xs.insert(*x->xoon);
        xoon_types.insert(x->type);
        EXPECT_TRUE(is_processed(x->type));
      }
    }
    EXPECT_EQ(overridable, e.override_time.has_value());
    if (e.override_time) {
      EXPECT_GE(e.override_time->max_s, 1u);
      if (e.override_time->prealarm_s) {
        EXPECT_LT(e.override_time->prealarm_s, e.override_time->max_s);
      }
    }
    if (xoon_n) {
      EXPECT_EQ(xs.size(), 1u);
      EXPECT_EQ(xoon_types.size(), 1u);
      EXPECT_GE(*xs.begin(), kMinXooN);
      EXPECT_LE(*xs.begin(), xoon_n);
      EXPECT_LE(xoon_n, kMaxXooN);
    }
    if (e.process_data) {
      EXPECT_TRUE(e.process_data->tag.has_value());
      EXPECT_TRUE(e.process_data->pass_through || e.process_data->mask_tag);
    }
  }
  for (const auto& c : m.causes)
    if (c.function == CauseFunction::Comment) {
      EXPECT_TRUE(m.intersections_of_cause(c.id).empty());
    }
  for (const auto& out : outputs) EXPECT_FALSE(inputs.count(out)) << "tag both input and output: " << out;
  EXPECT_TRUE(std::is_sorted(m.intersections.begin(), m.intersections.end(), [](const auto& a, const auto& b) {
    return std::pair{a.cause, a.effect} < std::pair{b.cause, b.effect};
  }));
}

}  // namespace

TEST(RandomMatrix, IsReproduciblePerSeed) {
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) ASSERT_EQ(dump(random_matrix(seed)), dump(random_matrix(seed)));
  EXPECT_NE(dump(random_matrix(1)), dump(random_matrix(2)));
}

TEST(RandomMatrix, IsWellFormedForEverySeed) {
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) expect_well_formed(random_matrix(seed), seed);
}

std::string errors_of(const Matrix& m) {
  std::string out;
  for (const auto& d : validate(m))
    if (d.severity == Severity::Error) out += d.rule + " " + d.element + ": " + d.message + "\n";
  return out;
}

TEST(RandomMatrix, HasNoValidationErrors) {
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    Matrix m = random_matrix(seed);
    ASSERT_EQ(errors_of(m), "") << "seed " << seed;
  }
}

// Saving and loading loses nothing: the canonical text reads back into the same
// matrix, whose canonical text is the same again.
void expect_round_trip(const Matrix& m, std::uint64_t seed) {
  std::string text = to_canonical_json(m);
  Matrix back;
  try {
    back = parse_matrix(text, "seed " + std::to_string(seed));
  } catch (const LoadError& e) {
    std::string issues;
    for (const auto& i : e.issues()) issues += i.str() + "\n";
    FAIL() << "seed " << seed << ": the canonical form does not load:\n" << issues;
  }
  EXPECT_EQ(dump(back), dump(m)) << "seed " << seed;
  EXPECT_EQ(to_canonical_json(back), text) << "seed " << seed;
}

TEST(RandomMatrix, RoundTripsThroughTheCanonicalForm) {
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) expect_round_trip(random_matrix(seed), seed);
}

TEST(RandomMatrix, SignatureIsReproduciblePerSeed) {
  std::set<std::string> signatures;
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    std::string s = signature(random_matrix(seed));
    EXPECT_EQ(s, signature(random_matrix(seed)));
    signatures.insert(s);
  }
  EXPECT_EQ(signatures.size(), static_cast<std::size_t>(kSeeds));  // seeds give different matrices
}

TEST(RandomMatrix, DefaultSizesAreSmall) {
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    Matrix m = random_matrix(seed);
    EXPECT_GE(m.causes.size(), 2u);
    EXPECT_LE(m.causes.size(), 6u);
    EXPECT_GE(m.effects.size(), 1u);
    EXPECT_LE(m.effects.size(), 4u);
  }
}

TEST(RandomMatrix, SeedsTogetherUseEveryOption) {
  std::map<std::string, int> total;
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed)
    for (const auto& [f, n] : feature_counts(random_matrix(seed))) total[f] += n;
  for (const auto& f : feature_names()) EXPECT_GT(total[f], 0) << "no matrix of " << kSeeds << " seeds uses " << f;
}

TEST(RandomMatrix, OptionsSetTheSize) {
  MatrixOptions o;
  o.min_causes = o.max_causes = 20;
  o.min_effects = o.max_effects = 10;
  o.intersections = 50;
  o.cycle_ms = 250;
  Matrix m = random_matrix(7, o);
  EXPECT_EQ(m.causes.size(), 20u);
  EXPECT_EQ(m.effects.size(), 10u);
  EXPECT_EQ(m.intersections.size(), 50u);
  EXPECT_EQ(m.cycle_ms, 250u);
  expect_well_formed(m, 7);
}

TEST(RandomMatrix, DegenerateOptionsDoNotCrash) {
  MatrixOptions o;
  o.min_effects = o.max_effects = 0;
  Matrix m = random_matrix(3, o);
  EXPECT_TRUE(m.effects.empty());
  EXPECT_TRUE(m.intersections.empty());
  EXPECT_EQ(random_inputs(m, 3, 50).size(), 50u);
  Matrix empty;
  EXPECT_EQ(random_inputs(empty, 3, 50).size(), 50u);
}

TEST(BigMatrix, HasTheLimitsOf34AndEveryOption) {
  Matrix m = big_matrix(1);
  EXPECT_EQ(m.causes.size(), 128u);
  EXPECT_EQ(m.effects.size(), 128u);
  EXPECT_EQ(m.intersections.size(), 1024u);
  expect_well_formed(m, 1);
  EXPECT_EQ(errors_of(m), "");
  expect_round_trip(m, 1);
  auto counts = feature_counts(m);
  for (const auto& f : feature_names())
    if (f != "matrix.id_gap") {  // 128 ids leave no gap
      EXPECT_GT(counts[f], 0) << f;
    }
  EXPECT_EQ(dump(m), dump(big_matrix(1)));
}

TEST(RandomInputs, AreReproducibleAndIndexedByTheInputTable) {
  for (std::uint64_t seed = 0; seed < 100; ++seed) {
    Matrix m = random_matrix(seed);
    auto a = random_inputs(m, seed, 300);
    ASSERT_EQ(a.size(), 300u);
    EXPECT_EQ(dump(a), dump(random_inputs(m, seed, 300)));
    InputTable table(m);
    for (const auto& f : a) ASSERT_EQ(f.tags.size(), table.size());
    // The first frame is the calm plant: every tag at its default, no command.
    EXPECT_EQ(dump({a[0]}), dump({default_inputs(m)}));
  }
}

TEST(RandomInputs, DefaultsAreNonTripped) {
  for (std::uint64_t seed = 0; seed < 100; ++seed) {
    Matrix m = random_matrix(seed);
    InputTable table(m);
    CycleInput d = default_inputs(m);
    for (const auto& c : m.causes) {
      if (c.function == CauseFunction::Comment) continue;
      const auto& t = c.tags.front();
      auto i = table.find(t.name);
      if (!i || table.tags()[*i].roles.front() != TagRole::CauseInput) continue;
      // Only the first cause reading a tag fixes its default.
      bool first_reader = true;
      for (const auto& o : m.causes) {
        if (o.id >= c.id) break;
        if (o.function == CauseFunction::Comment) continue;
        for (const auto& ot : o.tags) if (tag_key(ot.name) == tag_key(t.name)) first_reader = false;
      }
      if (!first_reader) continue;
      float v = d.tags[*i].value;
      if (c.analog) {
        if (c.analog->limit_type == LimitType::High) EXPECT_LT(v, c.analog->limit - c.analog->hysteresis);
        else EXPECT_GT(v, c.analog->limit + c.analog->hysteresis);
      } else {
        EXPECT_EQ(v, t.ett ? 0.0f : 1.0f);
      }
      EXPECT_FALSE(d.tags[*i].bad_quality);
    }
  }
}

TEST(RandomInputs, ExerciseThresholdsQualityEdgesAndEveryCommand) {
  std::set<CommandOp> ops;
  int at_limit = 0, just_below_limit = 0, at_relaxed = 0, bad = 0, reset_edges = 0, invalid_targets = 0;
  for (std::uint64_t seed = 0; seed < 100; ++seed) {
    Matrix m = random_matrix(seed);
    InputTable table(m);
    auto frames = random_inputs(m, seed, 300);
    for (std::size_t k = 0; k < frames.size(); ++k) {
      for (const auto& c : frames[k].commands) {
        ops.insert(c.op);
        if ((c.cause && !m.find_cause(c.cause)) || (c.effect && !m.find_effect(c.effect))) ++invalid_targets;
      }
      for (std::size_t i = 0; i < table.size(); ++i) {
        const auto& tv = frames[k].tags[i];
        bad += tv.bad_quality;
        const auto& roles = table.tags()[i].roles;
        if (k > 0 && std::find(roles.begin(), roles.end(), TagRole::EffectReset) != roles.end() &&
            frames[k - 1].tags[i].value == 0.0f && tv.value == 1.0f)
          ++reset_edges;
      }
      for (const auto& c : m.causes) {
        if (!c.analog || c.function == CauseFunction::Comment) continue;
        for (const auto& t : c.tags) {
          float v = frames[k].tags[*table.find(t.name)].value;
          at_limit += v == c.analog->limit;
          just_below_limit += v == std::nextafter(c.analog->limit, -1e30f);
          at_relaxed += c.analog->hysteresis > 0 && v == c.analog->limit - c.analog->hysteresis;
        }
      }
    }
  }
  EXPECT_EQ(ops.size(), static_cast<std::size_t>(CommandOp::ClearAlarms) + 1);
  EXPECT_GT(at_limit, 0);
  EXPECT_GT(just_below_limit, 0);
  EXPECT_GT(at_relaxed, 0);
  EXPECT_GT(bad, 0);
  EXPECT_GT(reset_edges, 0);
  EXPECT_GT(invalid_targets, 0);
}

// The scenarios are strong enough for the differential test: replayed on the
// reference runtime, 300 cycles of 100 random matrices drive every status field
// of docs/semantics.md to TRUE somewhere (timeouts and prealarms included), every
// resulting voting occurs, and commands are both accepted and refused.
TEST(RandomInputs, DriveEveryStatusFieldOnTheRuntime) {
  std::map<std::string, long> hits;
  long refused = 0, commands = 0;
  for (std::uint64_t seed = 0; seed < 100; ++seed) {
    Matrix m = random_matrix(seed);
    cemv::runtime::Runtime rt(m);
    auto obs = observables(m);
    std::vector<int> snap;
    for (const auto& frame : random_inputs(m, seed, 300)) {
      rt.step(frame);
      refused += rt.commands_refused();
      commands += static_cast<long>(frame.commands.size());
      rt.snapshot(snap);
      ASSERT_EQ(snap.size(), obs.size());
      for (std::size_t i = 0; i < obs.size(); ++i) {
        if (obs[i].type == FieldType::Voting) ++hits[std::string("voting=") + to_string(static_cast<Voting>(snap[i]))];
        else if (obs[i].field == "tag") ++hits[snap[i] ? "tag=1" : "tag=0"];
        else if (snap[i]) ++hits[obs[i].field];
      }
    }
  }
  for (const auto* fields : {&cause_fields(), &effect_fields()})
    for (const auto& f : *fields)
      if (f.type != FieldType::Voting) {
        EXPECT_GT(hits[f.name], 0) << f.name << " never became non-zero";
      }
  for (Voting v : {Voting::OneOoOne, Voting::OneOoTwo, Voting::TwoOoTwo, Voting::OneOoThree, Voting::TwoOoThree,
                   Voting::ThreeOoThree, Voting::Bypass})
    EXPECT_GT(hits[std::string("voting=") + to_string(v)], 0) << to_string(v);
  EXPECT_GT(hits["tag=0"], 0);
  EXPECT_GT(hits["tag=1"], 0);
  EXPECT_GT(refused, 0);
  EXPECT_LT(refused, commands);
}
