// A small fluent builder for matrices in validation and graph tests, so a test
// states only what matters to it.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/matrix.hpp"

namespace cemv::testcases {

using namespace cemv::model;

class MatrixBuilder {
 public:
  explicit MatrixBuilder(std::string name = "TEST") { m_.name = std::move(name); }

  MatrixBuilder& cycle_ms(std::uint32_t ms) {
    m_.cycle_ms = ms;
    return *this;
  }
  // A discrete cause with the given input tags; function from the tag count
  // (1: normal, 2-3: or) unless given.
  MatrixBuilder& cause(int id, std::string name, std::vector<std::string> tags) {
    Cause c;
    c.id = id;
    c.name = std::move(name);
    for (auto& t : tags) c.tags.push_back(CauseTag{std::move(t), false, true});
    c.function = c.tags.size() <= 1 ? CauseFunction::Normal : CauseFunction::Or;
    m_.causes.push_back(std::move(c));
    return *this;
  }
  MatrixBuilder& comment_cause(int id, std::string name) {
    cause(id, std::move(name), {});
    m_.causes.back().function = CauseFunction::Comment;
    return *this;
  }
  MatrixBuilder& effect(int id, std::string name, std::vector<std::string> tags) {
    Effect e;
    e.id = id;
    e.name = std::move(name);
    for (auto& t : tags) e.tags.push_back(EffectTag{std::move(t), false});
    m_.effects.push_back(std::move(e));
    return *this;
  }
  MatrixBuilder& comment_effect(int id, std::string name) {
    effect(id, std::move(name), {});
    m_.effects.back().function = EffectFunction::Comment;
    return *this;
  }
  MatrixBuilder& link(int cause, int effect, IntersectionType type = IntersectionType::N,
                      std::optional<int> xoon = std::nullopt) {
    m_.intersections.push_back(Intersection{cause, effect, type, xoon, ""});
    return *this;
  }
  // The last cause / effect added, for further settings.
  Cause& last_cause() { return m_.causes.back(); }
  Effect& last_effect() { return m_.effects.back(); }

  // Sorted as the loader keeps them (find_cause etc. rely on it).
  Matrix build() const {
    Matrix m = m_;
    m.sort_by_id();
    return m;
  }

 private:
  Matrix m_;
};

// A realistic matrix that validates without any error or warning and uses most
// options: analog 2oo3 with prewarning, delta and ON delay, manual acknowledgement,
// first out, SIF, XooN, R and V with override and reset tag, output delay,
// pass-through, an internal reference, secure write and group deactivation.
inline Matrix clean_matrix() {
  MatrixBuilder b("TANK_100");
  b.cause(1, "LT100_HH", {"LT_100A", "LT_100B", "LT_100C"});
  {
    Cause& c = b.last_cause();
    c.input = InputKind::Analog;
    c.function = CauseFunction::TwoOoThree;
    c.analog = AnalogParams{LimitType::High, 90.0f, 2.0f, 85.0f, 5.0f, "%"};
    c.bad_quality = BadQuality::Degrade;
    c.time = {TimeMode::OnDelay, 2000};
    c.soft_bypass = {true, 3600, 3000};
    c.bypass_tag = "HS_100_BYP";
    c.first_out_group = 1;
    c.sif = {1};
  }
  b.cause(2, "PSH_200", {"PS_200"});
  b.last_cause().auto_ack = false;
  b.last_cause().first_out_group = 1;
  b.cause(3, "XS_300", {"XS_300A", "XS_300B"});
  b.cause(4, "INLET_CLOSED", {"Effect[1][1]"});
  b.last_cause().soft_bypass.allowed = false;
  b.effect(1, "CLOSE_INLET", {"XV_101"});
  {
    Effect& e = b.last_effect();
    e.reset_tag = "HS_101_RST";
    e.override_time = Override{600, 540};
    e.process_data = ProcessData{"XV_101_BPCS", true, std::nullopt};
    e.sif = {1};
  }
  b.effect(2, "TRIP_PUMP", {"P_200_RUN"});
  b.last_effect().output_delay_ms = 500;
  b.effect(3, "ALARM_300", {"XA_300"});
  b.last_effect().tags[0].simulation_allowed = false;  // not every tag may be simulated (10.7.3.4)
  b.link(1, 1, IntersectionType::R)
      .link(3, 1, IntersectionType::V)
      .link(2, 2, IntersectionType::N, 2)
      .link(3, 2, IntersectionType::N, 2)
      .link(4, 3, IntersectionType::N);
  Matrix m = b.build();
  m.title = "Tank 100 overfill protection";
  m.cycle_ms = 100;
  m.sif_groups = {{1, "Tank 100 level"}};
  m.process_safety_time_ms = {{1, 30000}};
  m.secure_write = SecureWrite{"EN_SWC"};
  m.group_deactivation = GroupDeactivation{"EN_GDM", "SET_GDM"};
  return m;
}

}  // namespace cemv::testcases
