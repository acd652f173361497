// Test harness for the runtime tables and timer tests: builds small matrices in
// code (no loader involved, so these tests check the runtime alone) and drives
// the runtime cycle by cycle with scenario defaults (model/vocabulary.hpp).
#pragma once

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "model/vocabulary.hpp"
#include "model/matrix.hpp"
#include "formats/scenario.hpp"
#include "runtime/runtime.hpp"

namespace cemv::testing {

using namespace cemv::model;
using namespace cemv::formats;

// Analog parameters used throughout: high limit 90 / low limit 10, hysteresis 5
// (so the relaxed thresholds of 6.3.1 are 85 and 15, the defaults 84 and 16).
inline constexpr float kHighLimit = 90.0f;
inline constexpr float kLowLimit = 10.0f;
inline constexpr float kHyst = 5.0f;

// Concatenation without `"literal" + std::string&&`, which GCC 12 misreports
// under -Werror=restrict.
inline std::string cat(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (auto p : parts) out.append(p);
  return out;
}
inline std::string num(int v) { return std::to_string(v); }

enum class Kind { DiscreteDtt, DiscreteEtt, AnalogHigh, AnalogLow };
inline const char* kind_name(Kind k) {
  switch (k) {
    case Kind::DiscreteDtt: return "discrete DTT";
    case Kind::DiscreteEtt: return "discrete ETT";
    case Kind::AnalogHigh: return "analog high";
    case Kind::AnalogLow: return "analog low";
  }
  return "?";
}
inline constexpr Kind kAllKinds[] = {Kind::DiscreteDtt, Kind::DiscreteEtt, Kind::AnalogHigh,
                                     Kind::AnalogLow};

// A tripped / healthy value of one tag of this kind (6.3.4, 6.3.5).
inline float tripped_value(Kind k) {
  switch (k) {
    case Kind::DiscreteDtt: return 0.0f;
    case Kind::DiscreteEtt: return 1.0f;
    case Kind::AnalogHigh: return 95.0f;
    case Kind::AnalogLow: return 5.0f;
  }
  return 0.0f;
}
inline float healthy_value(Kind k) {
  switch (k) {
    case Kind::DiscreteDtt: return 1.0f;
    case Kind::DiscreteEtt: return 0.0f;
    case Kind::AnalogHigh: return 84.0f;
    case Kind::AnalogLow: return 16.0f;
  }
  return 0.0f;
}

// Cause `id` with tags "<prefix>1".."<prefix>n".
inline Cause make_cause(int id, CauseFunction f, int ntags, Kind kind,
                        BadQuality bq = BadQuality::Trip, const std::string& prefix = "") {
  Cause c;
  c.id = id;
  c.name = cat({"C", num(id)});
  c.description = cat({"cause ", num(id)});
  c.function = f;
  std::string p = prefix.empty() ? cat({"T", num(id), "_"}) : prefix;
  for (int i = 1; i <= ntags; ++i) {
    CauseTag t;
    t.name = cat({p, num(i)});
    t.ett = kind == Kind::DiscreteEtt;
    c.tags.push_back(t);
  }
  if (kind == Kind::AnalogHigh || kind == Kind::AnalogLow) {
    c.input = InputKind::Analog;
    AnalogParams a;
    a.limit_type = kind == Kind::AnalogHigh ? LimitType::High : LimitType::Low;
    a.limit = kind == Kind::AnalogHigh ? kHighLimit : kLowLimit;
    a.hysteresis = kHyst;
    a.unit = "%";
    c.analog = a;
  }
  c.bad_quality = bq;
  return c;
}

inline Effect make_effect(int id, int ntags = 1, bool ett = false) {
  Effect e;
  e.id = id;
  e.name = cat({"E", num(id)});
  e.description = cat({"effect ", num(id)});
  for (int i = 1; i <= ntags; ++i) e.tags.push_back({cat({"Y", num(id), "_", num(i)}), ett});
  return e;
}

inline Intersection link(int cause, int effect, IntersectionType t = IntersectionType::N) {
  Intersection x;
  x.cause = cause;
  x.effect = effect;
  x.type = t;
  return x;
}

inline Matrix make_matrix(std::vector<Cause> causes, std::vector<Effect> effects,
                          std::vector<Intersection> xs, std::uint32_t cycle_ms = 100) {
  Matrix m;
  m.name = "TEST";
  m.title = "test matrix";
  m.cycle_ms = cycle_ms;
  m.causes = std::move(causes);
  m.effects = std::move(effects);
  m.intersections = std::move(xs);
  return m;
}

inline Command command(CommandOp op, int cause = 0, int effect = 0, int tag = 0, bool on = true) {
  Command c;
  c.op = op;
  c.cause = cause;
  c.effect = effect;
  c.tag = tag;
  c.on = on;
  return c;
}

// Drives one runtime: inputs persist between cycles, commands apply to the next
// cycle only (the scenario convention of docs/scenario.md).
class Sim {
 public:
  explicit Sim(Matrix m) : m_(std::move(m)), rt_(m_), in_(default_cycle_input(m_)) {
    for (const auto& o : observables(m_)) obs_.emplace(o.key, o);
  }
  const Matrix& matrix() const { return m_; }
  runtime::Runtime& runtime() { return rt_; }
  const CycleInput& input() const { return in_; }

  void set(const std::string& tag, float value, bool bad = false) {
    auto idx = rt_.inputs().find(tag);
    ASSERT_TRUE(idx) << "no input tag " << tag;
    in_.tags[*idx] = {value, bad};
  }
  void set_bool(const std::string& tag, bool v) { set(tag, v ? 1.0f : 0.0f); }
  void cmd(const Command& c) { in_.commands.push_back(c); }
  // Runs n cycles; the queued commands go with the first.
  void step(int n = 1) {
    for (int i = 0; i < n; ++i) {
      rt_.step(in_);
      in_.commands.clear();
      ++cycle_;
    }
  }
  std::uint64_t cycle() const { return cycle_; }  // number of cycles run
  int get(const std::string& key) const {
    auto it = obs_.find(key);
    EXPECT_NE(it, obs_.end()) << "no observable " << key;
    if (it == obs_.end()) return -1;
    return rt_.value(it->second);
  }
  bool b(const std::string& key) const { return get(key) != 0; }
  std::string voting(int cause) const {
    return to_string(static_cast<Voting>(get(cat({"cause[", num(cause), "].voting"}))));
  }
  int out(const std::string& tag) const {
    auto v = rt_.output(tag);
    EXPECT_TRUE(v.has_value()) << "no output tag " << tag;
    return v ? (*v ? 1 : 0) : -1;
  }

 private:
  Matrix m_;
  runtime::Runtime rt_;
  CycleInput in_;
  std::map<std::string, Observable> obs_;
  std::uint64_t cycle_ = 0;
};

}  // namespace cemv::testing
