// Plausibility checks (model::validate): every rule has a matrix that triggers
// it and a near miss that does not, both derived from one clean matrix.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <set>
#include <sstream>
#include <string>

#include "model/graph.hpp"
#include "model/validate.hpp"
#include "validate_cases/builder.hpp"

namespace cemv::model {
namespace {

using testcases::clean_matrix;

// "ZS_" + number, built by appending (GCC 12 at -O3 reports a false -Wrestrict
// for a string literal + std::string temporary).
std::string numbered(const char* prefix, int n) {
  std::string s(prefix);
  s += std::to_string(n);
  return s;
}

Cause& cause(Matrix& m, int id) {
  for (auto& c : m.causes)
    if (c.id == id) return c;
  throw std::runtime_error(numbered("no cause ", id));
}
Effect& effect(Matrix& m, int id) {
  for (auto& e : m.effects)
    if (e.id == id) return e;
  throw std::runtime_error(numbered("no effect ", id));
}
Intersection& inter(Matrix& m, int c, int e) {
  for (auto& x : m.intersections)
    if (x.cause == c && x.effect == e) return x;
  throw std::runtime_error("no intersection");
}
Cause discrete_cause(int id, std::string name, std::string tag) {
  Cause c;
  c.id = id;
  c.name = std::move(name);
  c.tags = {CauseTag{std::move(tag), false, true}};
  return c;
}
Effect plain_effect(int id, std::string name, std::string tag) {
  Effect e;
  e.id = id;
  e.name = std::move(name);
  e.tags = {EffectTag{std::move(tag), false}};
  return e;
}
void add_linked_cause(Matrix& m, Cause c, int effect_id) {
  int id = c.id;
  m.causes.push_back(std::move(c));
  m.intersections.push_back(Intersection{id, effect_id, IntersectionType::N, std::nullopt, ""});
  m.sort_by_id();
}

std::string dump(const std::vector<Diagnostic>& ds) {
  std::ostringstream out;
  for (const auto& d : ds)
    out << to_string(d.severity) << " " << d.rule << " | " << d.element << " | [" << d.section
        << "] " << d.message << "\n";
  return out.str();
}

struct RuleCase {
  std::string name;      // test name
  std::string rule;      // the rule the trigger must raise and the near miss must not
  std::function<void(Matrix&)> trigger;
  std::function<void(Matrix&)> near_miss;
  std::string element;   // expected element of the finding ("" = not checked)
};

// Printed in ctest's test list: the rule, not the raw bytes of the struct
// (which would show addresses and differ between runs).
void PrintTo(const RuleCase& c, std::ostream* os) { *os << c.rule; }

void nothing(Matrix&) {}

AnalogParams analog(LimitType t, float limit, float hyst, std::optional<float> pre, float delta) {
  return AnalogParams{t, limit, hyst, pre, delta, ""};
}

const std::vector<RuleCase>& rule_cases() {
  static const std::vector<RuleCase> cases = {
      {"AnalogMissing", "E-ANALOG-MISSING", [](Matrix& m) { cause(m, 1).analog.reset(); },
       [](Matrix& m) {
         cause(m, 2).input = InputKind::Analog;
         cause(m, 2).analog = analog(LimitType::High, 10, 0, std::nullopt, 0);
       },
       "cause[1] LT100_HH"},
      {"AnalogNotFinite", "E-ANALOG-NOT-FINITE",
       [](Matrix& m) { cause(m, 1).analog->limit = std::numeric_limits<float>::quiet_NaN(); },
       [](Matrix& m) { cause(m, 1).analog->limit = 3.4e38f; }, "cause[1] LT100_HH"},
      {"AnalogInfiniteHysteresis", "E-ANALOG-NOT-FINITE",
       [](Matrix& m) { cause(m, 1).analog->hysteresis = std::numeric_limits<float>::infinity(); },
       nothing, ""},
      {"CommentCauseIntersection", "E-COMMENT-INTERSECTION",
       [](Matrix& m) {
         Cause c = discrete_cause(5, "NOTE_ONLY", "ZS_500");
         c.function = CauseFunction::Comment;
         add_linked_cause(m, c, 3);
       },
       [](Matrix& m) {
         Cause c = discrete_cause(5, "NOTE_ONLY", "ZS_500");
         c.function = CauseFunction::Comment;
         add_linked_cause(m, c, 3);
         inter(m, 5, 3).type = IntersectionType::Note;
       },
       "intersection cause[5]/effect[3]"},
      {"CommentEffectIntersection", "E-COMMENT-INTERSECTION",
       [](Matrix& m) { effect(m, 3).function = EffectFunction::Comment; }, nothing,
       "intersection cause[4]/effect[3]"},
      {"ControlTagCollision", "E-CONTROL-TAG-COLLISION",
       [](Matrix& m) { m.secure_write->enable_tag = "hs_100_byp"; },
       [](Matrix& m) { m.secure_write->enable_tag = "HS_100_BYP2"; }, "matrix"},
      {"ControlTagCollisionOutput", "E-CONTROL-TAG-COLLISION",
       [](Matrix& m) { m.group_deactivation->set_tag = "XA_300"; }, nothing, "matrix"},
      {"CycleTimeZero", "E-CYCLE-TIME", [](Matrix& m) { m.cycle_ms = 0; },
       [](Matrix& m) { m.cycle_ms = 50; }, "matrix"},
      {"DeltaNegative", "E-DELTA-NEGATIVE", [](Matrix& m) { cause(m, 1).analog->delta = -1; },
       [](Matrix& m) { cause(m, 1).analog->delta = 0; }, "cause[1] LT100_HH"},
      {"DuplicateCauseId", "E-DUPLICATE-CAUSE-ID",
       [](Matrix& m) { add_linked_cause(m, discrete_cause(3, "OTHER", "ZS_900"), 3); },
       [](Matrix& m) { add_linked_cause(m, discrete_cause(5, "OTHER", "ZS_900"), 3); },
       "cause[3] OTHER"},
      {"DuplicateCauseName", "E-DUPLICATE-CAUSE-NAME",
       [](Matrix& m) { add_linked_cause(m, discrete_cause(5, "lt100_hh", "ZS_900"), 3); },
       [](Matrix& m) { add_linked_cause(m, discrete_cause(5, "LT100_HHH", "ZS_900"), 3); },
       "cause[5] lt100_hh"},
      {"DuplicateEffectId", "E-DUPLICATE-EFFECT-ID",
       [](Matrix& m) {
         m.effects.push_back(plain_effect(3, "OTHER", "XY_900"));
         m.sort_by_id();
       },
       [](Matrix& m) {
         m.effects.push_back(plain_effect(4, "OTHER", "XY_900"));
         m.intersections.push_back(Intersection{4, 4, IntersectionType::N, std::nullopt, ""});
         m.sort_by_id();
       },
       "effect[3] OTHER"},
      {"DuplicateEffectName", "E-DUPLICATE-EFFECT-NAME",
       [](Matrix& m) {
         m.effects.push_back(plain_effect(4, "Close_Inlet", "XY_900"));
         m.sort_by_id();
       },
       [](Matrix& m) {
         m.effects.push_back(plain_effect(4, "CLOSE_INLET_2", "XY_900"));
         m.sort_by_id();
       },
       "effect[4] Close_Inlet"},
      {"EffectNoTag", "E-EFFECT-TAG-COUNT", [](Matrix& m) { effect(m, 3).tags.clear(); },
       [](Matrix& m) {
         effect(m, 3).tags = {{"XA_301", false}, {"XA_302", false}, {"XA_303", false},
                              {"XA_304", false}};
       },
       "effect[3] ALARM_300"},
      {"EffectFiveTags", "E-EFFECT-TAG-COUNT",
       [](Matrix& m) {
         effect(m, 3).tags = {{"XA_301", false}, {"XA_302", false}, {"XA_303", false},
                              {"XA_304", false}, {"XA_305", false}};
       },
       [](Matrix& m) {
         effect(m, 3).function = EffectFunction::Comment;
         effect(m, 3).tags.clear();  // a comment-only effect needs no tag
         m.intersections.erase(m.intersections.end() - 1);
       },
       ""},
      {"FirstOutRange", "E-FIRST-OUT-RANGE", [](Matrix& m) { cause(m, 1).first_out_group = 16; },
       [](Matrix& m) { cause(m, 1).first_out_group = 15; }, "cause[1] LT100_HH"},
      {"FunctionNormalThreeTags", "E-FUNCTION-TAG-COUNT",
       [](Matrix& m) { cause(m, 1).function = CauseFunction::Normal; },
       [](Matrix& m) { cause(m, 1).function = CauseFunction::And; }, "cause[1] LT100_HH"},
      {"Function2oo3TwoTags", "E-FUNCTION-TAG-COUNT",
       [](Matrix& m) { cause(m, 3).function = CauseFunction::TwoOoThree; },
       [](Matrix& m) { cause(m, 3).function = CauseFunction::And; }, "cause[3] XS_300"},
      {"FunctionOrOneTag", "E-FUNCTION-TAG-COUNT",
       [](Matrix& m) { cause(m, 2).function = CauseFunction::Or; },
       [](Matrix& m) {
         cause(m, 2).function = CauseFunction::Comment;
         cause(m, 2).tags.clear();
       },
       "cause[2] PSH_200"},
      {"GdmSameTag", "E-GDM-SAME-TAG", [](Matrix& m) { m.group_deactivation->set_tag = "en_gdm"; },
       nothing, "matrix"},
      {"HysteresisNegative", "E-HYSTERESIS-NEGATIVE",
       [](Matrix& m) { cause(m, 1).analog->hysteresis = -0.5f; },
       [](Matrix& m) { cause(m, 1).analog->hysteresis = 0; }, "cause[1] LT100_HH"},
      {"IdRange", "E-ID-RANGE",
       [](Matrix& m) { add_linked_cause(m, discrete_cause(129, "FAR", "ZS_900"), 3); },
       [](Matrix& m) { add_linked_cause(m, discrete_cause(128, "FAR", "ZS_900"), 3); },
       "cause[129] FAR"},
      {"IdZero", "E-ID-RANGE",
       [](Matrix& m) {
         m.effects.push_back(plain_effect(0, "NULL", "XY_0"));
         m.intersections.push_back(Intersection{4, 0, IntersectionType::N, std::nullopt, ""});
         m.sort_by_id();
       },
       nothing, "effect[0] NULL"},
      {"IntersectionDanglingCause", "E-INTERSECTION-DANGLING",
       [](Matrix& m) {
         m.intersections.push_back(Intersection{9, 1, IntersectionType::N, std::nullopt, ""});
         m.sort_by_id();
       },
       [](Matrix& m) {
         m.intersections.push_back(Intersection{4, 1, IntersectionType::N, std::nullopt, ""});
         m.sort_by_id();
       },
       "intersection cause[9]/effect[1]"},
      {"IntersectionDanglingEffect", "E-INTERSECTION-DANGLING",
       [](Matrix& m) {
         m.intersections.push_back(Intersection{1, 7, IntersectionType::N, std::nullopt, ""});
       },
       nothing, "intersection cause[1]/effect[7]"},
      {"IntersectionRepeated", "E-INTERSECTION-REPEATED",
       [](Matrix& m) {
         m.intersections.push_back(Intersection{1, 1, IntersectionType::S, std::nullopt, ""});
         m.sort_by_id();
       },
       [](Matrix& m) {
         m.intersections.push_back(Intersection{1, 3, IntersectionType::N, std::nullopt, ""});
         m.sort_by_id();
       },
       "intersection cause[1]/effect[1]"},
      {"IntersectionX", "E-INTERSECTION-X",
       [](Matrix& m) { inter(m, 3, 1).type = IntersectionType::X; },
       [](Matrix& m) { inter(m, 3, 1).type = IntersectionType::Note; },
       "intersection cause[3]/effect[1]"},
      {"LimitCauses", "E-LIMIT",
       [](Matrix& m) {
         for (int id = 5; id <= 129; ++id)
           add_linked_cause(m, discrete_cause(id, numbered("C", id), numbered("ZS_", id)), 3);
       },
       [](Matrix& m) {
         for (int id = 5; id <= 128; ++id)
           add_linked_cause(m, discrete_cause(id, numbered("C", id), numbered("ZS_", id)), 3);
       },
       "matrix"},
      {"OutputTagReference", "E-OUTPUT-TAG-REFERENCE",
       [](Matrix& m) { effect(m, 3).tags[0].name = "Cause[1]"; },
       [](Matrix& m) { effect(m, 3).tags[0].name = "Cause_1"; }, "effect[3] ALARM_300"},
      {"OutputTagRepeated", "E-OUTPUT-TAG-REPEATED",
       [](Matrix& m) { effect(m, 3).tags.push_back({"xa_300", false}); },
       [](Matrix& m) { effect(m, 3).tags.push_back({"XA_301", false}); }, "effect[3] ALARM_300"},
      {"OutputTagShared", "E-OUTPUT-TAG-SHARED",
       [](Matrix& m) { effect(m, 3).tags[0].name = "xv_101"; },
       [](Matrix& m) { effect(m, 3).tags[0].name = "XV_102"; }, "effect[3] ALARM_300"},
      {"OverrideMissing", "E-OVERRIDE-TIME-MISSING",
       [](Matrix& m) { effect(m, 1).override_time.reset(); },
       [](Matrix& m) { effect(m, 1).override_time = Override{1, 0}; }, "effect[1] CLOSE_INLET"},
      {"OverrideZero", "E-OVERRIDE-TIME-MISSING",
       [](Matrix& m) { effect(m, 1).override_time = Override{0, 0}; }, nothing,
       "effect[1] CLOSE_INLET"},
      {"OverrideMissingV", "E-OVERRIDE-TIME-MISSING",
       [](Matrix& m) { inter(m, 4, 3).type = IntersectionType::V; },
       [](Matrix& m) {
         inter(m, 4, 3).type = IntersectionType::V;
         effect(m, 3).override_time = Override{300, 0};
       },
       "effect[3] ALARM_300"},
      {"PassThroughWithoutTag", "E-PROCESS-DATA-TAG-MISSING",
       [](Matrix& m) { effect(m, 1).process_data->tag.reset(); }, nothing,
       "effect[1] CLOSE_INLET"},
      {"MaskWithoutTag", "E-PROCESS-DATA-TAG-MISSING",
       [](Matrix& m) { effect(m, 2).process_data = ProcessData{std::nullopt, false, "MASK_2"}; },
       [](Matrix& m) { effect(m, 2).process_data = ProcessData{"P_200_BPCS", false, "MASK_2"}; },
       "effect[2] TRIP_PUMP"},
      {"RefAnalog", "E-REF-ANALOG", [](Matrix& m) { cause(m, 1).tags[2].name = "Cause[2]"; },
       [](Matrix& m) { cause(m, 3).tags[1].name = "Cause[2]"; }, "cause[1] LT100_HH"},
      {"RefMissingEffect", "E-REF-MISSING", [](Matrix& m) { cause(m, 4).tags[0].name = "Effect[9]"; },
       [](Matrix& m) { cause(m, 4).tags[0].name = "Effect[2]"; }, "cause[4] INLET_CLOSED"},
      {"RefMissingEffectTag", "E-REF-MISSING",
       [](Matrix& m) { cause(m, 4).tags[0].name = "Effect[1][2]"; }, nothing,
       "cause[4] INLET_CLOSED"},
      {"RefMissingCause", "E-REF-MISSING",
       [](Matrix& m) { effect(m, 2).bypass_tag = "Cause[42]"; },
       [](Matrix& m) { effect(m, 2).bypass_tag = "Cause[3]"; }, "effect[2] TRIP_PUMP"},
      {"RefMissingMatrixLevel", "E-REF-MISSING",
       [](Matrix& m) { m.secure_write->enable_tag = "Effect[8]"; },
       [](Matrix& m) { m.secure_write->enable_tag = "Effect[3]"; }, "matrix"},
      {"WatchdogShorterThanCycle", "E-WATCHDOG-CYCLE", [](Matrix& m) { m.watchdog_ms = 99; },
       [](Matrix& m) { m.watchdog_ms = 100; }, "matrix"},
      {"SifNoPst", "W-SIF-NO-PST", [](Matrix& m) { m.process_safety_time_ms.clear(); },
       [](Matrix& m) { m.sif_groups[2] = "no members"; },  // a group nobody belongs to needs no time
       "matrix"},
      {"SifPstNoMembers", "W-SIF-PST-NO-MEMBERS",
       [](Matrix& m) {
         m.sif_groups[2] = "empty";
         m.process_safety_time_ms[2] = 5000;
       },
       [](Matrix& m) {
         m.sif_groups[2] = "used";
         m.process_safety_time_ms[2] = 5000;
         effect(m, 2).sif = {2};
       },
       "matrix"},
      {"PstWithinControllerShareOfCycle", "W-PST-CONTROLLER",
       [](Matrix& m) { m.process_safety_time_ms[1] = 200; },
       [](Matrix& m) { m.process_safety_time_ms[1] = 201; }, "matrix"},
      {"PstWithinControllerShareOfWatchdog", "W-PST-CONTROLLER",
       [](Matrix& m) {
         m.watchdog_ms = 250;
         m.process_safety_time_ms[1] = 500;
       },
       [](Matrix& m) {
         m.watchdog_ms = 250;
         m.process_safety_time_ms[1] = 501;
       },
       "matrix"},
      {"SifGroupRange", "E-SIF-GROUP-RANGE", [](Matrix& m) { m.sif_groups[65] = "far"; },
       [](Matrix& m) { m.sif_groups[64] = "far"; }, "matrix"},
      {"SifRangeNumber", "E-SIF-RANGE", [](Matrix& m) { cause(m, 1).sif = {0}; },
       [](Matrix& m) { cause(m, 1).sif = {1}; }, "cause[1] LT100_HH"},
      {"SifRangeCount", "E-SIF-RANGE",
       [](Matrix& m) {
         for (int s = 1; s <= 5; ++s) m.sif_groups.emplace(s, "g");
         effect(m, 1).sif = {1, 2, 3, 4, 5};
       },
       [](Matrix& m) {
         for (int s = 1; s <= 5; ++s) m.sif_groups.emplace(s, "g");
         effect(m, 1).sif = {1, 2, 3, 4};
       },
       "effect[1] CLOSE_INLET"},
      {"TagInAndOut", "E-TAG-IN-AND-OUT", [](Matrix& m) { cause(m, 2).tags[0].name = "p_200_run"; },
       [](Matrix& m) { cause(m, 2).tags[0].name = "P_200_RUN_FB"; }, "effect[2] TRIP_PUMP"},
      {"TagInAndOutProcessValue", "E-TAG-IN-AND-OUT",
       [](Matrix& m) { effect(m, 1).process_data->tag = "XV_101"; }, nothing,
       "effect[1] CLOSE_INLET"},
      {"TagKindConflict", "E-TAG-KIND-CONFLICT",
       [](Matrix& m) { cause(m, 3).tags[1].name = "LT_100A"; },
       [](Matrix& m) {
         Cause c = discrete_cause(5, "LT100_H", "LT_100A");
         c.input = InputKind::Analog;
         c.analog = analog(LimitType::High, 80, 0, std::nullopt, 0);
         add_linked_cause(m, c, 3);
       },
       "cause[1] LT100_HH"},
      {"TagKindConflictControl", "E-TAG-KIND-CONFLICT",
       [](Matrix& m) { effect(m, 2).bypass_tag = "LT_100B"; }, nothing, "cause[1] LT100_HH"},
      {"TimedZero", "E-TIMED-CAUSE-ZERO", [](Matrix& m) { cause(m, 1).time = {TimeMode::Timed, 0}; },
       [](Matrix& m) { cause(m, 1).time = {TimeMode::Timed, 100}; }, "cause[1] LT100_HH"},
      {"XooNCount", "E-XOON-COUNT",
       [](Matrix& m) {
         inter(m, 2, 2).xoon = 3;
         inter(m, 3, 2).xoon = 3;
       },
       [](Matrix& m) {
         add_linked_cause(m, discrete_cause(5, "PSH_201", "PS_201"), 2);
         inter(m, 2, 2).xoon = 3;
         inter(m, 3, 2).xoon = 3;
         inter(m, 5, 2).xoon = 3;
       },
       "effect[2] TRIP_PUMP"},
      {"XooNSingle", "E-XOON-COUNT", [](Matrix& m) { inter(m, 4, 3).xoon = 2; }, nothing,
       "effect[3] ALARM_300"},
      {"XooNMixedType", "E-XOON-MIXED-TYPE", [](Matrix& m) { inter(m, 3, 2).type = IntersectionType::S; },
       [](Matrix& m) {
         inter(m, 3, 2).type = IntersectionType::S;
         inter(m, 2, 2).type = IntersectionType::S;
         effect(m, 2).reset_tag = "HS_200_RST";
       },
       "effect[2] TRIP_PUMP"},
      {"XooNMixedX", "E-XOON-MIXED-X",
       [](Matrix& m) {
         add_linked_cause(m, discrete_cause(5, "PSH_201", "PS_201"), 2);
         inter(m, 5, 2).xoon = 3;
       },
       [](Matrix& m) {
         add_linked_cause(m, discrete_cause(5, "PSH_201", "PS_201"), 2);
         inter(m, 5, 2).xoon = 2;
       },
       "effect[2] TRIP_PUMP"},
      {"XooNOnNote", "E-XOON-NOT-PROCESSED",
       [](Matrix& m) {
         inter(m, 2, 2).type = IntersectionType::Note;
         inter(m, 3, 2).type = IntersectionType::Note;
       },
       [](Matrix& m) {
         inter(m, 2, 2).type = IntersectionType::Note;
         inter(m, 3, 2).type = IntersectionType::Note;
         inter(m, 2, 2).xoon.reset();
         inter(m, 3, 2).xoon.reset();
       },
       "intersection cause[2]/effect[2]"},
      {"XooNRangeLow", "E-XOON-RANGE",
       [](Matrix& m) {
         inter(m, 2, 2).xoon = 1;
         inter(m, 3, 2).xoon = 1;
       },
       nothing, "intersection cause[2]/effect[2]"},
      {"XooNRangeHigh", "E-XOON-RANGE",
       [](Matrix& m) {
         for (int id = 5; id <= 20; ++id) {
           add_linked_cause(m, discrete_cause(id, numbered("C", id), numbered("ZS_", id)), 2);
           inter(m, id, 2).xoon = 16;
         }
         inter(m, 2, 2).xoon = 16;
         inter(m, 3, 2).xoon = 16;
       },
       [](Matrix& m) {
         for (int id = 5; id <= 20; ++id) {
           add_linked_cause(m, discrete_cause(id, numbered("C", id), numbered("ZS_", id)), 2);
           inter(m, id, 2).xoon = 15;
         }
         inter(m, 2, 2).xoon = 15;
         inter(m, 3, 2).xoon = 15;
       },
       ""},
      {"AckOffDelay", "W-ACK-NO-EFFECT", [](Matrix& m) { cause(m, 2).time = {TimeMode::OffDelay, 1000}; },
       [](Matrix& m) { cause(m, 2).time = {TimeMode::OnDelay, 1000}; }, "cause[2] PSH_200"},
      {"AckTimed", "W-ACK-NO-EFFECT", [](Matrix& m) { cause(m, 2).time = {TimeMode::Timed, 1000}; },
       [](Matrix& m) {
         cause(m, 2).time = {TimeMode::Timed, 1000};
         cause(m, 2).auto_ack = true;
       },
       "cause[2] PSH_200"},
      {"AnalogUnused", "W-ANALOG-UNUSED",
       [](Matrix& m) { cause(m, 2).analog = analog(LimitType::Low, 1, 0, std::nullopt, 0); }, nothing,
       "cause[2] PSH_200"},
      {"BadQualityIgnoredHighLimit", "W-BAD-QUALITY-IGNORED",
       [](Matrix& m) { cause(m, 1).bad_quality = BadQuality::Ignore; },
       [](Matrix& m) {
         cause(m, 1).bad_quality = BadQuality::Ignore;  // a low limit >= 0 trips on 0.0
         auto& a = *cause(m, 1).analog;
         a.limit_type = LimitType::Low;
         a.limit = 10;
         a.prewarning = 12;
       },
       "cause[1] LT100_HH"},
      {"BadQualityIgnoredEtt", "W-BAD-QUALITY-IGNORED",
       [](Matrix& m) {
         cause(m, 3).bad_quality = BadQuality::Ignore;
         cause(m, 3).tags[1].ett = true;
       },
       [](Matrix& m) {
         cause(m, 3).bad_quality = BadQuality::Ignore;  // DTT: FALSE is a trip
       },
       "cause[3] XS_300"},
      {"SelfBypass", "W-CAUSE-SELF-BYPASS", [](Matrix& m) { cause(m, 2).bypass_tag = "ps_200"; },
       [](Matrix& m) { cause(m, 2).bypass_tag = "PS_200_BYP"; }, "cause[2] PSH_200"},
      {"SelfInhibit", "W-CAUSE-SELF-BYPASS", [](Matrix& m) { cause(m, 3).inhibit_tag = "XS_300B"; },
       [](Matrix& m) { cause(m, 3).inhibit_tag = "XS_300_INH"; }, "cause[3] XS_300"},
      {"CauseUnused", "W-CAUSE-UNUSED",
       [](Matrix& m) {
         m.causes.push_back(discrete_cause(5, "SPARE", "ZS_500"));
         m.sort_by_id();
       },
       [](Matrix& m) {
         m.causes.push_back(discrete_cause(5, "SPARE", "ZS_500"));
         effect(m, 3).bypass_tag = "Cause[5]";  // read by an internal reference
         m.sort_by_id();
       },
       "cause[5] SPARE"},
      {"CauseReadByMatrixTag", "W-CAUSE-UNUSED",
       [](Matrix& m) {
         m.causes.push_back(discrete_cause(5, "KEY_SWITCH", "ZS_500"));
         m.sort_by_id();
       },
       [](Matrix& m) {
         m.causes.push_back(discrete_cause(5, "KEY_SWITCH", "ZS_500"));
         m.group_deactivation->enable_tag = "Cause[5]";
         m.sort_by_id();
       },
       "cause[5] KEY_SWITCH"},
      {"CauseOnlyNote", "W-CAUSE-UNUSED",
       [](Matrix& m) {
         add_linked_cause(m, discrete_cause(5, "SPARE", "ZS_500"), 3);
         inter(m, 5, 3).type = IntersectionType::Note;
       },
       [](Matrix& m) { add_linked_cause(m, discrete_cause(5, "SPARE", "ZS_500"), 3); },
       "cause[5] SPARE"},
      {"DeltaHysteresis", "W-DELTA-HYSTERESIS", [](Matrix& m) { cause(m, 1).analog->hysteresis = 5; },
       [](Matrix& m) { cause(m, 1).analog->hysteresis = 4.9f; }, "cause[1] LT100_HH"},
      {"DeltaSingleTag", "W-DELTA-SINGLE-TAG",
       [](Matrix& m) {
         Cause c = discrete_cause(5, "TT_500_H", "TT_500");
         c.input = InputKind::Analog;
         c.analog = analog(LimitType::High, 80, 0, std::nullopt, 1);
         add_linked_cause(m, c, 3);
       },
       [](Matrix& m) {
         Cause c = discrete_cause(5, "TT_500_H", "TT_500");
         c.input = InputKind::Analog;
         c.analog = analog(LimitType::High, 80, 0, std::nullopt, 0);
         add_linked_cause(m, c, 3);
       },
       "cause[5] TT_500_H"},
      {"EffectUndriven", "W-EFFECT-UNDRIVEN",
       [](Matrix& m) {
         m.effects.push_back(plain_effect(4, "SPARE", "XY_400"));
         m.sort_by_id();
       },
       [](Matrix& m) {
         m.effects.push_back(plain_effect(4, "SPARE", "XY_400"));
         m.intersections.push_back(Intersection{4, 4, IntersectionType::N, std::nullopt, ""});
         m.sort_by_id();
       },
       "effect[4] SPARE"},
      {"EffectOnlyNote", "W-EFFECT-UNDRIVEN",
       [](Matrix& m) {
         m.effects.push_back(plain_effect(4, "SPARE", "XY_400"));
         m.intersections.push_back(Intersection{4, 4, IntersectionType::Note, std::nullopt, ""});
         m.sort_by_id();
       },
       nothing, "effect[4] SPARE"},
      {"InputTagRepeated", "W-INPUT-TAG-REPEATED",
       [](Matrix& m) { cause(m, 3).tags[1].name = "xs_300a"; },
       [](Matrix& m) { cause(m, 3).tags[1].name = "XS_300C"; }, "cause[3] XS_300"},
      {"InputTagShared", "W-INPUT-TAG-SHARED", [](Matrix& m) { cause(m, 2).tags[0].name = "XS_300A"; },
       [](Matrix& m) { cause(m, 2).tags[0].name = "XS_300Z"; }, "cause[3] XS_300"},
      {"OverridePrealarm", "W-OVERRIDE-PREALARM",
       [](Matrix& m) { effect(m, 1).override_time = Override{600, 600}; },
       [](Matrix& m) { effect(m, 1).override_time = Override{600, 599}; }, "effect[1] CLOSE_INLET"},
      {"OverrideUnused", "W-OVERRIDE-UNUSED",
       [](Matrix& m) { effect(m, 3).override_time = Override{60, 0}; },
       [](Matrix& m) { effect(m, 3).override_time = Override{0, 0}; }, "effect[3] ALARM_300"},
      {"PrewarningHigh", "W-PREWARNING-BEYOND-LIMIT", [](Matrix& m) { cause(m, 1).analog->prewarning = 90; },
       [](Matrix& m) { cause(m, 1).analog->prewarning = 89.9f; }, "cause[1] LT100_HH"},
      {"PrewarningLow", "W-PREWARNING-BEYOND-LIMIT",
       [](Matrix& m) {
         auto& a = *cause(m, 1).analog;
         a.limit_type = LimitType::Low;
         a.limit = 10;
         a.prewarning = 9;
       },
       [](Matrix& m) {
         auto& a = *cause(m, 1).analog;
         a.limit_type = LimitType::Low;
         a.limit = 10;
         a.prewarning = 12;
       },
       "cause[1] LT100_HH"},
      {"ProcessDataUnused", "W-PROCESS-DATA-UNUSED",
       [](Matrix& m) { effect(m, 1).process_data->pass_through = false; },
       [](Matrix& m) {
         effect(m, 1).process_data->pass_through = false;
         effect(m, 1).process_data->mask_tag = "XV_101_MASK";
       },
       "effect[1] CLOSE_INLET"},
      {"RefComment", "W-REF-COMMENT",
       [](Matrix& m) {
         Cause c = discrete_cause(5, "NOTE_ONLY", "ZS_500");
         c.function = CauseFunction::Comment;
         m.causes.push_back(c);
         m.sort_by_id();
         cause(m, 4).tags[0].name = "Cause[5]";
       },
       [](Matrix& m) {
         m.causes.push_back(discrete_cause(5, "REAL_ONE", "ZS_500"));
         m.sort_by_id();
         cause(m, 4).tags[0].name = "Cause[5]";
       },
       "cause[4] INLET_CLOSED"},
      {"RefCycle", "W-REF-CYCLE", [](Matrix& m) { effect(m, 1).bypass_tag = "Cause[4]"; },
       [](Matrix& m) { effect(m, 3).bypass_tag = "Cause[4]"; }, "cause[4] INLET_CLOSED"},
      {"RefSelfCycle", "W-REF-CYCLE", [](Matrix& m) { cause(m, 2).inhibit_tag = "Cause[2]"; },
       [](Matrix& m) { cause(m, 2).inhibit_tag = "Cause[3]"; }, "cause[2] PSH_200"},
      {"ResetOperatorOnly", "W-RESET-OPERATOR-ONLY", [](Matrix& m) { effect(m, 1).reset_tag.reset(); },
       nothing, "effect[1] CLOSE_INLET"},
      {"ResetOperatorOnlyS", "W-RESET-OPERATOR-ONLY",
       [](Matrix& m) { inter(m, 4, 3).type = IntersectionType::S; },
       [](Matrix& m) {
         inter(m, 4, 3).type = IntersectionType::S;
         effect(m, 3).reset_tag = "HS_300_RST";
       },
       "effect[3] ALARM_300"},
      {"ResetTagUnused", "W-RESET-TAG-UNUSED",
       [](Matrix& m) { effect(m, 3).reset_tag = "HS_300_RST"; },
       [](Matrix& m) {
         effect(m, 3).reset_tag = "HS_300_RST";
         inter(m, 4, 3).type = IntersectionType::S;
       },
       "effect[3] ALARM_300"},
      {"SifUndefined", "W-SIF-UNDEFINED", [](Matrix& m) { cause(m, 1).sif = {2}; },
       [](Matrix& m) {
         cause(m, 1).sif = {2};
         m.sif_groups[2] = "Tank 100 pressure";
       },
       "cause[1] LT100_HH"},
      {"SoftBypassPrealarm", "W-SOFT-BYPASS-PREALARM",
       [](Matrix& m) { cause(m, 1).soft_bypass = {true, 3600, 3600}; },
       [](Matrix& m) { cause(m, 1).soft_bypass = {true, 3600, 3599}; }, "cause[1] LT100_HH"},
      {"SoftBypassPrealarmUntimed", "W-SOFT-BYPASS-PREALARM",
       [](Matrix& m) { cause(m, 1).soft_bypass = {true, 0, 10}; },
       [](Matrix& m) { cause(m, 1).soft_bypass = {true, 0, 0}; }, "cause[1] LT100_HH"},
      {"SimulationUnrestricted", "W-SIMULATION-UNRESTRICTED",
       [](Matrix& m) { effect(m, 3).tags[0].simulation_allowed = true; },
       [](Matrix& m) {
         effect(m, 3).tags[0].simulation_allowed = true;
         cause(m, 2).tags[0].simulation_allowed = false;
       },
       "matrix"},
      {"SoftBypassUntimed", "W-SOFT-BYPASS-UNTIMED",
       [](Matrix& m) {
         cause(m, 1).sil = 2;
         cause(m, 1).soft_bypass = {true, 0, 0};
       },
       [](Matrix& m) {
         cause(m, 1).soft_bypass = {true, 0, 0};  // SIL not stated: the import summary says it, not validate
         cause(m, 2).sil = 2;
         cause(m, 2).soft_bypass = {false, 0, 0};
       },
       "cause[1] LT100_HH"},
      {"SoftBypassUnused", "W-SOFT-BYPASS-UNUSED",
       [](Matrix& m) { cause(m, 4).soft_bypass = {false, 60, 0}; },
       [](Matrix& m) { cause(m, 4).soft_bypass = {true, 60, 0}; }, "cause[4] INLET_CLOSED"},
      {"TimeUnused", "W-TIME-UNUSED", [](Matrix& m) { cause(m, 2).time = {TimeMode::None, 100}; },
       [](Matrix& m) { cause(m, 2).time = {TimeMode::None, 0}; }, "cause[2] PSH_200"},
      {"TimeZero", "W-TIME-ZERO", [](Matrix& m) { cause(m, 1).time = {TimeMode::OnDelay, 0}; },
       [](Matrix& m) { cause(m, 1).time = {TimeMode::OnDelay, 100}; }, "cause[1] LT100_HH"},
      {"OffDelayZero", "W-TIME-ZERO", [](Matrix& m) { cause(m, 3).time = {TimeMode::OffDelay, 0}; },
       nothing, "cause[3] XS_300"},
      {"RoundingCauseTime", "W-TIMER-ROUNDING",
       [](Matrix& m) { cause(m, 1).time = {TimeMode::OnDelay, 2050}; },
       [](Matrix& m) { cause(m, 1).time = {TimeMode::OnDelay, 2100}; }, "cause[1] LT100_HH"},
      {"RoundingOutputDelay", "W-TIMER-ROUNDING", [](Matrix& m) { effect(m, 2).output_delay_ms = 550; },
       [](Matrix& m) { effect(m, 2).output_delay_ms = 600; }, "effect[2] TRIP_PUMP"},
      {"RoundingSeconds", "W-TIMER-ROUNDING",
       [](Matrix& m) {
         m.cycle_ms = 700;  // 600 s = 600000 ms is not a multiple of 700 ms
         cause(m, 1).time = {TimeMode::OnDelay, 2100};
         cause(m, 1).soft_bypass = {true, 0, 0};
         effect(m, 2).output_delay_ms = 700;
       },
       [](Matrix& m) {
         m.cycle_ms = 500;
         cause(m, 1).time = {TimeMode::OnDelay, 2000};
         effect(m, 2).output_delay_ms = 500;
       },
       "effect[1] CLOSE_INLET"},
  };
  return cases;
}

class RuleTest : public ::testing::TestWithParam<RuleCase> {};

TEST_P(RuleTest, TriggerRaisesTheRule) {
  const RuleCase& rc = GetParam();
  Matrix m = clean_matrix();
  rc.trigger(m);
  auto ds = validate(m);
  auto it = std::find_if(ds.begin(), ds.end(), [&](const Diagnostic& d) {
    return d.rule == rc.rule && (rc.element.empty() || d.element == rc.element);
  });
  ASSERT_NE(it, ds.end()) << "expected " << rc.rule << " at '" << rc.element << "', got:\n"
                          << dump(ds);
  EXPECT_FALSE(it->message.empty());
  if (rc.rule[0] == 'E') {
    EXPECT_TRUE(has_errors(ds));
  }
}

TEST_P(RuleTest, NearMissDoesNotRaiseTheRule) {
  const RuleCase& rc = GetParam();
  Matrix m = clean_matrix();
  rc.near_miss(m);
  auto ds = validate(m);
  for (const auto& d : ds) EXPECT_NE(d.rule, rc.rule) << dump(ds);
}

INSTANTIATE_TEST_SUITE_P(Rules, RuleTest, ::testing::ValuesIn(rule_cases()),
                         [](const auto& info) { return info.param.name; });

TEST(Validate, CleanMatrixHasNoFinding) {
  auto ds = validate(clean_matrix());
  EXPECT_TRUE(ds.empty()) << dump(ds);
  EXPECT_FALSE(has_errors(ds));
}

TEST(Validate, EveryRuleHasATriggerCase) {
  std::set<std::string> covered;
  for (const auto& c : rule_cases()) covered.insert(c.rule);
  for (const auto& r : validation_rules()) EXPECT_TRUE(covered.count(r.id)) << r.id;
  std::set<std::string> known;
  for (const auto& r : validation_rules()) known.insert(r.id);
  for (const auto& id : covered) EXPECT_TRUE(known.count(id)) << id;
}

TEST(Validate, RuleTableIsSortedAndConsistent) {
  const auto& rules = validation_rules();
  ASSERT_FALSE(rules.empty());
  for (std::size_t i = 1; i < rules.size(); ++i)
    EXPECT_LT(std::string(rules[i - 1].id), std::string(rules[i].id));
  for (const auto& r : rules) {
    std::string id = r.id;
    EXPECT_EQ(id.substr(0, 2), r.severity == Severity::Error ? "E-" : "W-") << id;
    EXPECT_FALSE(std::string(r.section).empty()) << id;
    EXPECT_FALSE(std::string(r.meaning).empty()) << id;
  }
}

// Every finding carries the severity and section its rule declares.
TEST(Validate, FindingsMatchTheRuleTable) {
  std::map<std::string, const RuleInfo*> by_id;
  for (const auto& r : validation_rules()) by_id[r.id] = &r;
  for (const auto& rc : rule_cases()) {
    Matrix m = clean_matrix();
    rc.trigger(m);
    for (const auto& d : validate(m)) {
      ASSERT_TRUE(by_id.count(d.rule)) << d.rule;
      EXPECT_EQ(d.severity, by_id[d.rule]->severity) << d.rule;
      EXPECT_EQ(d.section, by_id[d.rule]->section) << d.rule;
    }
  }
}

TEST(Validate, OrderIsRuleThenElementAndDeterministic) {
  Matrix m = clean_matrix();
  effect(m, 1).reset_tag.reset();                       // W-RESET-OPERATOR-ONLY
  inter(m, 3, 1).type = IntersectionType::X;            // E-INTERSECTION-X
  m.intersections.push_back(Intersection{1, 3, IntersectionType::X, std::nullopt, ""});
  m.causes.push_back(discrete_cause(12, "SPARE_12", "ZS_12"));  // W-CAUSE-UNUSED
  m.causes.push_back(discrete_cause(9, "SPARE_9", "ZS_9"));     // W-CAUSE-UNUSED
  m.sort_by_id();
  auto ds = validate(m);
  auto again = validate(m);
  ASSERT_EQ(dump(ds), dump(again));
  std::vector<std::string> got;
  for (const auto& d : ds) got.push_back(d.rule + " " + d.element);
  std::vector<std::string> want = {
      "E-INTERSECTION-X intersection cause[1]/effect[3]",
      "E-INTERSECTION-X intersection cause[3]/effect[1]",
      "W-CAUSE-UNUSED cause[9] SPARE_9",
      "W-CAUSE-UNUSED cause[12] SPARE_12",  // by id, not by text
      "W-RESET-OPERATOR-ONLY effect[1] CLOSE_INLET",
  };
  EXPECT_EQ(got, want) << dump(ds);
}

TEST(Validate, MessagesNameTheProblem) {
  Matrix m = clean_matrix();
  inter(m, 3, 1).type = IntersectionType::X;
  effect(m, 1).bypass_tag = "Cause[4]";
  cause(m, 1).time = {TimeMode::OnDelay, 2050};
  auto ds = validate(m);
  std::string text = dump(ds);
  EXPECT_NE(text.find("error E-INTERSECTION-X | intersection cause[3]/effect[1] | [6.5.2] "
                      "intersection type X is not yet specified"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("W-REF-CYCLE | cause[4] INLET_CLOSED | [8.3] cycle cause[4] -> effect[1] "
                      "-> cause[4]: cause[4] reads effect[1] from the previous scan cycle"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("time.ms = 2050 ms is not a multiple of cycle_ms 100: it acts as 2100 ms "
                      "(21 cycles)"),
            std::string::npos)
      << text;
}

TEST(Validate, XooNMessageStatesXAndN) {
  Matrix m = clean_matrix();
  inter(m, 2, 2).xoon = 3;
  inter(m, 3, 2).xoon = 3;
  std::string text = dump(validate(m));
  EXPECT_NE(text.find("3oo2: X exceeds N = 2"), std::string::npos) << text;
}

TEST(Validate, CycleCapIsReported) {
  // 20 causes each reading five effects that all of them trip: a knot with far
  // more than kMaxReportedCycles elementary cycles.
  testcases::MatrixBuilder b("KNOT");
  for (int e = 1; e <= 5; ++e) b.effect(e, numbered("E", e), {numbered("Y", e)});
  for (int c = 1; c <= 20; ++c) {
    b.cause(c, numbered("C", c), {"Effect[1]", "Effect[2]", "Effect[3]"});
    b.last_cause().bypass_tag = "Effect[4]";
    b.last_cause().inhibit_tag = "Effect[5]";
    for (int e = 1; e <= 5; ++e) b.link(c, e);
  }
  auto ds = validate(b.build());
  std::size_t cycles = 0;
  bool cap_note = false;
  for (const auto& d : ds)
    if (d.rule == "W-REF-CYCLE") {
      if (d.element == "matrix")
        cap_note = true;
      else
        ++cycles;
    }
  EXPECT_EQ(cycles, kMaxReportedCycles);
  EXPECT_TRUE(cap_note);
}

// validate() is total: whatever a program builds, it reports, never throws.
TEST(Validate, NeverThrowsOnBrokenMatrices) {
  Matrix empty;
  EXPECT_NO_THROW(validate(empty));
  Matrix m = clean_matrix();
  m.causes.push_back(m.causes.front());          // duplicate id and name
  std::reverse(m.causes.begin(), m.causes.end());  // unsorted
  m.effects.push_back(Effect{});                  // id 0, no name, no tag
  m.intersections.push_back(Intersection{77, 88, IntersectionType::R, 99, ""});
  m.intersections.push_back(Intersection{77, 88, IntersectionType::Note, -5, ""});
  m.cycle_ms = 0;
  m.group_deactivation = GroupDeactivation{"", ""};
  cause(m, 2).tags.clear();
  cause(m, 2).input = InputKind::Analog;
  std::vector<Diagnostic> ds;
  ASSERT_NO_THROW(ds = validate(m));
  EXPECT_TRUE(has_errors(ds));
}

// docs/validation.md lists every rule with its severity and section.
TEST(Validate, DocumentationListsEveryRule) {
  std::ifstream in(std::string(CEMV_SOURCE_DIR) + "/docs/validation.md");
  ASSERT_TRUE(in) << "docs/validation.md missing";
  std::stringstream buf;
  buf << in.rdbuf();
  std::string doc = buf.str();
  for (const auto& r : validation_rules()) {
    std::string row = std::string("| `") + r.id + "` | " + to_string(r.severity) + " | " +
                      r.section + " |";
    EXPECT_NE(doc.find(row), std::string::npos) << "missing row starting " << row;
  }
}

}  // namespace
}  // namespace cemv::model
