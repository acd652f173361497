// Change pairs (docs/change-acceptance.md): two versions of an example matrix
// compared structurally and by behaviour, each with the classification an
// assessor must get: which changes are listed and whether they are critical
// (6.2.3), which effects' behaviour changed, and the retest scope (manual 12).
// Every kind of change the mutation operators make (docs/mutation.md), a pure
// rename, a pure comment edit, a moved row and an inserted row.
#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "checker/replay.hpp"
#include "diff/print.hpp"
#include "diff/semantic.hpp"
#include "diff/structural.hpp"
#include "formats/matrix_json.hpp"
#include "formats/scenario.hpp"
#include "model/validate.hpp"
#include "mutate/mutants.hpp"

namespace {

using namespace cemv;
using checker::EquivalenceVerdict;
using diff::ChangeKind;
using diff::ElementChange;

model::Matrix example(const std::string& name) {
  return formats::load_valid_matrix(std::string(CEMV_SOURCE_DIR) + "/examples/" + name + "/matrix.json", "compared");
}

struct Compared {
  diff::StructuralDiff structure;
  diff::SemanticDiff behaviour;
  // NEW ids of the effects whose behaviour changed (the retest list).
  std::vector<int> changed_effects() const {
    std::vector<int> out;
    for (const auto& e : behaviour.effects)
      if (e.behaviour_changed()) out.push_back(e.new_id ? e.new_id : e.old_id);
    return out;
  }
  std::vector<int> critically_changed_effects() const {
    std::vector<int> out;
    for (const auto& e : behaviour.effects)
      if (e.critically_changed) out.push_back(e.new_id ? e.new_id : e.old_id);
    return out;
  }
  std::size_t critical_changes() const {
    return static_cast<std::size_t>(std::count_if(structure.changes.begin(), structure.changes.end(),
                                                  [](const ElementChange& c) { return c.critical(); }));
  }
};

Compared compare(const model::Matrix& a, const model::Matrix& b) {
  for (const auto& d : model::validate(b)) EXPECT_NE(d.severity, model::Severity::Error) << d.message;
  Compared c;
  c.structure = diff::compare_structure(a, b);
  diff::SemanticOptions o;
  c.behaviour = diff::compare_behaviour(a, b, c.structure, o);
  return c;
}

// Every distinguishing run, as NEW's own inputs, gives NEW's value on NEW's
// runtime and differs from OLD's (the run was replayed on both runtimes by
// the comparison; this checks what the change checklist's test relies on).
void expect_runs_show_the_difference(const model::Matrix& b, const Compared& c) {
  for (const auto& e : c.behaviour.effects) {
    if (!e.result.distinction || !e.new_id) continue;
    const auto& d = *e.result.distinction;
    ASSERT_FALSE(e.new_inputs.empty()) << e.result.group;
    const checker::ConcreteTrace t = checker::run_on_runtime(b, e.new_inputs);
    const auto obs = model::observables(b);
    std::size_t k = 0;
    while (k < obs.size() && obs[k].key != e.new_key) ++k;
    ASSERT_LT(k, obs.size()) << e.new_key;
    EXPECT_EQ(t.observables.back()[k], d.value_b) << e.result.group;
    EXPECT_NE(d.value_a, d.value_b) << e.result.group;
  }
}

// Renumbers the causes of `m` by `map` (old -> new id; ids not in the map
// stay), intersections and `Cause[x]` references along.
model::Matrix renumber_causes(model::Matrix m, const std::map<int, int>& map) {
  auto to = [&](int id) { return map.count(id) ? map.at(id) : id; };
  for (auto& c : m.causes) {
    c.id = to(c.id);
    for (auto& t : c.tags)
      if (auto r = model::parse_internal_ref(t.name); r && r->kind == model::InternalRef::Kind::Cause)
        t.name = "Cause[" + std::to_string(to(r->id)) + "]";
  }
  std::sort(m.causes.begin(), m.causes.end(), [](const auto& x, const auto& y) { return x.id < y.id; });
  for (auto& x : m.intersections) x.cause = to(x.cause);
  std::sort(m.intersections.begin(), m.intersections.end(),
            [](const auto& x, const auto& y) { return std::tie(x.cause, x.effect) < std::tie(y.cause, y.effect); });
  return m;
}

// ---- edits that change no behaviour ----------------------------------------

// A pure rename (matrix, cause and effect names): non-critical, every effect
// unchanged in behaviour, nothing to retest.
TEST(ChangePairs, PureRename) {
  const model::Matrix m = example("tank-overfill");
  model::Matrix b = m;
  b.causes[1].name = "LSHH_100_FORK";
  b.effects[0].name = "CLOSE_XV_101";
  const Compared c = compare(m, b);
  ASSERT_EQ(c.structure.changes.size(), 2u);
  EXPECT_EQ(c.critical_changes(), 0u);
  for (const auto& ch : c.structure.changes) {
    EXPECT_EQ(ch.kind, ChangeKind::Changed);
    ASSERT_EQ(ch.fields.size(), 1u);
    EXPECT_EQ(ch.fields[0].field, "name");
  }
  EXPECT_TRUE(c.changed_effects().empty());
  for (const auto& e : c.behaviour.effects) EXPECT_EQ(e.result.method, "identical cone") << e.result.group;
  EXPECT_TRUE(c.behaviour.impact.effects.empty());
  const auto scope = diff::retest_scope(c.behaviour);
  EXPECT_TRUE(scope.partial) << scope.reason;
}

// A pure comment edit (descriptions, notes, title, units): non-critical, no
// behaviour changed; effect 1 is "changed, behaviour equivalent" because its
// own description changed, effect 3 because a cause of its cone did.
TEST(ChangePairs, PureCommentEdit) {
  const model::Matrix m = example("tank-overfill");
  model::Matrix b = m;
  b.title = "Storage tank T-100 (revision B)";
  b.effects[0].description = "Close inlet valve XV-101";
  b.causes[3].note = "transmitter replaced 2026";
  b.causes[3].analog->unit = "percent";
  b.intersections[0].note = "(1)";
  const Compared c = compare(m, b);
  EXPECT_EQ(c.structure.changes.size(), 4u);  // matrix, cause 4, effect 1, intersection c1/e1
  EXPECT_EQ(c.critical_changes(), 0u);
  EXPECT_TRUE(c.changed_effects().empty());
  std::set<int> touched;
  for (const auto& e : c.behaviour.effects)
    if (e.structurally_changed) touched.insert(e.new_id);
  EXPECT_EQ(touched, (std::set<int>{1, 3}));
  EXPECT_TRUE(c.critically_changed_effects().empty());
  EXPECT_TRUE(diff::retest_scope(c.behaviour).partial);
}

// A moved row: cause 4 moved up to number 2, causes 2 and 3 shift down.
// Three moves (critical: numbers are what references and faceplates use),
// no field change, and the behaviour of every effect proved unchanged on
// the product of OLD and NEW renumbered back.
TEST(ChangePairs, MovedRow) {
  const model::Matrix m = example("tank-overfill");
  const model::Matrix b = renumber_causes(m, {{4, 2}, {2, 3}, {3, 4}});
  const Compared c = compare(m, b);
  ASSERT_EQ(c.structure.changes.size(), 3u);
  for (const auto& ch : c.structure.changes) {
    EXPECT_EQ(ch.kind, ChangeKind::Moved) << ch.label();
    EXPECT_TRUE(ch.fields.empty()) << ch.label();
  }
  EXPECT_EQ(c.structure.cause_map, (std::map<int, int>{{1, 1}, {2, 3}, {3, 4}, {4, 2}}));
  EXPECT_TRUE(c.behaviour.relabelled);
  EXPECT_TRUE(c.changed_effects().empty());
  EXPECT_TRUE(diff::retest_scope(c.behaviour).partial);
}

// An inserted row: a comment row added as cause 2 shifts causes 2-4 to 3-5.
// The insertion is one added cause and three moves, not three changed rows.
TEST(ChangePairs, InsertedRowShiftsTheRest) {
  const model::Matrix m = example("tank-overfill");
  model::Matrix b = renumber_causes(m, {{2, 3}, {3, 4}, {4, 5}});
  model::Cause note;
  note.id = 2;
  note.name = "NOTE_ROW";
  note.description = "Causes 3-5 moved down for the new sensor (planned)";
  note.function = model::CauseFunction::Comment;
  b.causes.insert(b.causes.begin() + 1, note);
  const Compared c = compare(m, b);
  std::map<ChangeKind, int> kinds;
  for (const auto& ch : c.structure.changes) kinds[ch.kind]++;
  EXPECT_EQ(kinds, (std::map<ChangeKind, int>{{ChangeKind::Added, 1}, {ChangeKind::Moved, 3}}));
  EXPECT_TRUE(c.changed_effects().empty());
  EXPECT_TRUE(diff::retest_scope(c.behaviour).partial);
}

// ---- every kind of change the mutation operators make ----------------------

// One change pair per mutation operator (docs/mutation.md): the example and
// the mutant, chosen where the element is cheapest to decide (discrete
// inputs, short timers); `reverse` compares the mutant with the original
// (xoon-minus, which no example admits, is xoon-plus read backwards). The
// expectation is what the edit means by docs/semantics.md, worked out by hand
// from the example: the effects whose behaviour changes, and the cycle
// (1-based) of the shortest run that shows it.
struct OperatorPair {
  const char* op;
  const char* example;
  const char* mutant;
  bool reverse;
  std::vector<int> changed;  // NEW effect ids whose behaviour changed
  int cycle;                 // of the first effect's shortest difference; 0: not asserted (a
                             // difference beyond BMC's bound, found by accelerated BMC, is not
                             // guaranteed shortest)
  // Applied to the example before it is mutated, in both versions of the
  // pair: a long timer (soft bypass of 30 min, override of 5 min) shortened
  // to a few seconds, so that the difference the one-second edit makes lies
  // a few dozen cycles deep instead of 18,000 (the edit is the same).
  void (*shorten)(model::Matrix&) = nullptr;
};

model::Cause& cause(model::Matrix& m, int id) {
  return *std::find_if(m.causes.begin(), m.causes.end(), [id](const model::Cause& c) { return c.id == id; });
}
model::Effect& effect(model::Matrix& m, int id) {
  return *std::find_if(m.effects.begin(), m.effects.end(), [id](const model::Effect& e) { return e.id == id; });
}

// The timers the pairs below shorten, each in one example.
void soft_bypass_3s(model::Matrix& m) {  // tank-overfill cause 2 (LSHH_100): 1800 s / 1500 s
  cause(m, 2).soft_bypass.max_s = 3;
  cause(m, 2).soft_bypass.prealarm_s = 2;
}
void override_3s(model::Matrix& m) {  // burner-management effect 1 (MFT_MAIN_GAS): 300 s / 240 s
  effect(m, 1).override_time->max_s = 3;
  effect(m, 1).override_time->prealarm_s = 2;
}
void timed_300ms(model::Matrix& m) {  // pipeline-hipps cause 6 (XS300_ESD_UPSTREAM): timed 5000 ms
  cause(m, 6).time.ms = 300;
}

void PrintTo(const OperatorPair& p, std::ostream* os) { *os << p.op << " " << p.example << " " << p.mutant; }

class OperatorPairs : public testing::TestWithParam<OperatorPair> {};

TEST_P(OperatorPairs, ClassifiedAsExpected) {
  const OperatorPair& p = GetParam();
  model::Matrix m = example(p.example);
  if (p.shorten) {
    p.shorten(m);
    for (const auto& d : model::validate(m)) ASSERT_NE(d.severity, model::Severity::Error) << d.message;
  }
  const auto set = mutate::mutants(m);
  const auto it = std::find_if(set.mutants.begin(), set.mutants.end(), [&](const auto& x) { return x.id == p.mutant; });
  ASSERT_NE(it, set.mutants.end()) << p.mutant;
  ASSERT_EQ(it->op, p.reverse ? std::string("xoon-plus") : std::string(p.op));
  const model::Matrix& a = p.reverse ? it->matrix : m;
  const model::Matrix& b = p.reverse ? m : it->matrix;
  const Compared c = compare(a, b);

  // Structural: exactly the one edit, critical, on the mutated element (an
  // XooN edit moves the X of every intersection of the assignment: one
  // change per intersection, field `xoon`).
  const std::string op = p.op;
  const bool xoon = op.rfind("xoon", 0) == 0;
  if (xoon) {
    ASSERT_GE(c.structure.changes.size(), 2u) << it->description;
  } else {
    ASSERT_EQ(c.structure.changes.size(), 1u) << it->description;
  }
  const ChangeKind kind = op == "intersection-added"     ? ChangeKind::Added
                          : op == "intersection-removed" ? ChangeKind::Removed
                                                         : ChangeKind::Changed;
  for (const ElementChange& ch : c.structure.changes) {
    EXPECT_TRUE(ch.critical()) << ch.label();
    EXPECT_EQ(ch.kind, kind) << ch.label();
    if (op.rfind("intersection", 0) == 0 || xoon) {
      EXPECT_EQ(ch.element, ElementChange::Element::Intersection);
    }
    if (xoon) {
      ASSERT_EQ(ch.fields.size(), 1u) << ch.label();
      EXPECT_EQ(ch.fields[0].field, "xoon");
    }
    if (!xoon) {
      EXPECT_NE(it->element.find(ch.element == ElementChange::Element::Cause    ? "cause["
                                 : ch.element == ElementChange::Element::Effect ? "effect["
                                                                                : "intersection"),
                std::string::npos)
          << it->element << " vs " << ch.label();
    }
  }

  // Semantic: the expected effects changed, every other one proved
  // equivalent, none undecided; runs replayed.
  EXPECT_EQ(c.changed_effects(), p.changed) << it->description;
  EXPECT_FALSE(c.behaviour.any_unknown());
  for (const auto& e : c.behaviour.effects)
    if (e.behaviour_changed()) {
      EXPECT_TRUE(e.critically_changed) << e.result.group;
      ASSERT_TRUE(e.result.distinction.has_value()) << e.result.group;
      if (!p.changed.empty() && e.new_id == p.changed.front() && p.cycle > 0) {
        EXPECT_EQ(e.result.distinction->cycle + 1, p.cycle) << e.result.group;
      }
      EXPECT_FALSE(e.outputs.empty()) << e.result.group;
    }
  expect_runs_show_the_difference(b, c);

  // The retest list is the impact set; the comparisons agree.
  std::vector<int> impact = c.behaviour.impact.effects;
  std::sort(impact.begin(), impact.end());
  EXPECT_EQ(impact, p.changed);
  const auto scope = diff::retest_scope(c.behaviour);
  EXPECT_TRUE(scope.partial) << scope.reason;
}

INSTANTIATE_TEST_SUITE_P(
    Operators, OperatorPairs,
    testing::Values(
        // ESD cause 3 no longer trips P-102: effect 3 differs when it trips.
        OperatorPair{"intersection-removed", "tank-overfill", "intersection-removed.c3e3", false, {3}, 1},
        // The fork switch (cause 2) now also stops P-102.
        OperatorPair{"intersection-added", "tank-overfill", "intersection-added.N.c2e3", false, {3}, 1},
        // ESD into P-101 N -> S: effect 2 latches on the first trip.
        OperatorPair{"intersection-type", "tank-overfill", "intersection-type.S.c3e2", false, {2}, 1},
        // The ESD button's tag de-energise <-> energise to trip: at rest one
        // version trips, in cycle 1, every effect cause 3 drives.
        OperatorPair{"tag-ett", "tank-overfill", "tag-ett.c3t1", false, {1, 2, 3}, 1},
        // A bad-quality ESD signal trips OLD (default "trip"), not NEW.
        OperatorPair{"bad-quality", "tank-overfill", "bad-quality.ignore.c3", false, {1, 2, 3}, 1},
        // An on-delay on the ESD button: OLD trips in cycle 1, NEW later.
        OperatorPair{"time-mode", "tank-overfill", "time-mode.on_delay.c3", false, {1, 2, 3}, 1},
        // Acknowledgement of the ESD cause: a one-cycle trip stays active in one
        // version in cycle 2.
        OperatorPair{"auto-ack", "tank-overfill", "auto-ack.c3", false, {1, 2, 3}, 2},
        // P-102's output tag DTT <-> ETT: the output differs at rest.
        OperatorPair{"output-ett", "tank-overfill", "output-ett.e3t1", false, {3}, 1},
        // One cycle of output delay on P-102: a one-cycle trip clears a cycle later.
        OperatorPair{"output-delay-plus", "tank-overfill", "output-delay-plus.e3", false, {3}, 2},
        // XV-101 without its field reset tag: the reset of cycle 2 is refused.
        OperatorPair{"effect-reset-tag-removed", "tank-overfill", "effect-reset-tag-removed.e1", false, {1}, 2},
        // XV-101's process data no longer passes through: differs at rest.
        OperatorPair{"pass-through", "tank-overfill", "pass-through.e1", false, {1}, 1},
        // The ESD cause 4 (or of two tags) as "and": one tag tripped trips OLD
        // only; effect 1 differs, and effects 2, 3, 4 through the causes that
        // read Effect[1] and Effect[1][2] (causes 6 and 5).
        OperatorPair{"cause-function", "compressor", "cause-function.and.c4", false, {1, 2, 3, 4}, 1},
        // Output delay of ISOLATE_K401 5000 -> 4900 ms: differs only after the
        // delay runs out (a run beyond BMC's bound; cycle not asserted).
        OperatorPair{"output-delay-minus", "compressor", "output-delay-minus.e2", false, {2}, 0},
        // ISOLATE_K401 without its bypass tag: the bypass no longer holds it off.
        OperatorPair{"effect-bypass-tag-removed", "compressor", "effect-bypass-tag-removed.e2", false, {2}, 1},
        // OPEN_RECYCLE's mask tag removed: the mask no longer forces the output.
        OperatorPair{"mask-tag-removed", "compressor", "mask-tag-removed.e3", false, {3}, 1},
        // STOP_P305's XooN assignment needs one cause more (and, read
        // backwards, one fewer: xoon-minus, which no example admits).
        OperatorPair{"xoon-plus", "pipeline-hipps", "xoon-plus.e2", false, {2}, 1},
        OperatorPair{"xoon-minus", "pipeline-hipps", "xoon-plus.e2", true, {2}, 1},
        // ---- long timers, shortened in both versions (`shorten`) ----
        // The fork switch's soft bypass (cause 2 of tank-overfill, 3 s here,
        // prealarm 2 s) switched on with the switch tripped in cycle 1: the
        // bypass expires in cycle 1 + 30 (T.2), and XV-101 (S) and P-101 (N)
        // follow the cause; 4 s: 10 cycles later; 2 s: in cycle 21.
        OperatorPair{"soft-bypass-max-plus", "tank-overfill", "soft-bypass-max-plus.c2", false, {1, 2}, 31,
                     soft_bypass_3s},
        OperatorPair{"soft-bypass-max-minus", "tank-overfill", "soft-bypass-max-minus.c2", false, {1, 2}, 21,
                     soft_bypass_3s},
        // The soft-bypass prealarm is the cause's status (bypass_prealarm,
        // docs/semantics.md C.1), read by no effect: a critical edit of the
        // cause, every effect proved equivalent, nothing to retest (the
        // comparison is per effect and output tag).
        OperatorPair{"soft-bypass-prealarm-plus", "tank-overfill", "soft-bypass-prealarm-plus.c2", false, {}, 0,
                     soft_bypass_3s},
        OperatorPair{"soft-bypass-prealarm-minus", "tank-overfill", "soft-bypass-prealarm-minus.c2", false, {}, 0,
                     soft_bypass_3s},
        // The override of MFT_MAIN_GAS (burner-management effect 1, 3 s here,
        // prealarm 2 s): its timeout ends the override (E.3) a second later or
        // earlier, its prealarm shows a second later or earlier. The run is a
        // minimised random run more than BMC's few cycles deep (cycle not
        // asserted).
        OperatorPair{"override-max-plus", "burner-management", "override-max-plus.e1", false, {1}, 0, override_3s},
        OperatorPair{"override-max-minus", "burner-management", "override-max-minus.e1", false, {1}, 0, override_3s},
        OperatorPair{"override-prealarm-plus", "burner-management", "override-prealarm-plus.e1", false, {1}, 0,
                     override_3s},
        OperatorPair{"override-prealarm-minus", "burner-management", "override-prealarm-minus.e1", false, {1}, 0,
                     override_3s},
        // The light-off inhibit of the flame-failure cause removed: with the
        // inhibit tag set and two scanners tripped, NEW trips in cycle 1 what
        // the cause drives (effects 1, 2 and 4).
        OperatorPair{"cause-inhibit-tag-removed", "burner-management", "cause-inhibit-tag-removed.c1", false,
                     {1, 2, 4}, 1},
        // The pulse stretcher of the upstream ESD (pipeline-hipps cause 6, timed,
        // 300 ms here): 400 ms keeps STOP_P305 (N) on in cycle 4, 200 ms drops
        // it in cycle 3; CLOSE_HIPPS (S) differs in whether a reset then clears it.
        OperatorPair{"time-ms-plus", "pipeline-hipps", "time-ms-plus.c6", false, {1, 2}, 4, timed_300ms},
        OperatorPair{"time-ms-minus", "pipeline-hipps", "time-ms-minus.c6", false, {1, 2}, 3, timed_300ms},
        // PSLL410's bypass tag removed: with the tag set and the pressure low
        // from cycle 1, NEW trips K-401 after the 1000 ms on-delay (cycle 21
        // at 50 ms), and effects 2, 3, 4 through causes 5 and 6 that read it.
        OperatorPair{"cause-bypass-tag-removed", "compressor", "cause-bypass-tag-removed.c2", false, {1, 2, 3, 4}, 21}),
    [](const testing::TestParamInfo<OperatorPair>& i) {
      std::string s = i.param.op;
      for (char& ch : s)
        if (ch == '-') ch = '_';
      return s;
    });

}  // namespace

namespace {

// An N cell made S on an effect that passes process data through (E.9), with
// DTT outputs and an output delay: the effect differs at once (latched), but
// its outputs rest at the value they act with while the process value is 0,
// so they differ only once the trip is released with the process value at 1.
// The effect's run continued that way decides each tag, and the run replays.
TEST(ChangePairs, LatchOnAPassThroughEffectShowsInItsOutputsAfterRelease) {
  const std::string head = R"({"format": "cemv-matrix/1", "name": "LATCH", "cycle_ms": 100,
    "causes": [{"id": 1, "name": "C1", "tags": [{"name": "X1", "ett": true}], "time": {"mode": "timed", "ms": 300}}],
    "effects": [{"id": 1, "name": "SHUT", "output_delay_ms": 500,
                 "tags": [{"name": "V1", "ett": false}, {"name": "V2", "ett": false}],
                 "process_data": {"tag": "V_BPCS", "pass_through": true}}],
    "intersections": [{"cause": 1, "effect": 1, "type": )";
  const model::Matrix a = formats::parse_matrix(head + R"("N"}]})", "old");
  const model::Matrix b = formats::parse_matrix(head + R"("S"}]})", "new");
  const Compared c = compare(a, b);
  ASSERT_EQ(c.changed_effects(), std::vector<int>{1});
  const auto& e = c.behaviour.effects.front();
  ASSERT_EQ(e.outputs.size(), 2u);
  const auto obs_a = model::observables(a), obs_b = model::observables(b);
  for (const auto& o : e.outputs) {
    EXPECT_EQ(o.verdict, EquivalenceVerdict::Differs) << o.group << ": " << o.reason;
    EXPECT_NE(o.method.find("the effect's run continued"), std::string::npos) << o.method;
    ASSERT_TRUE(o.distinction) << o.group;
    const auto& d = *o.distinction;
    // Replayed here once more: both runtimes give the reported values in the reported cycle.
    const auto ta = checker::run_on_runtime(a, d.run_a.inputs), tb = checker::run_on_runtime(b, d.run_b.inputs);
    ASSERT_EQ(ta.observables.size(), static_cast<std::size_t>(d.cycle + 1));
    std::size_t ia = 0, ib = 0;
    while (obs_a[ia].key != d.key) ++ia;
    while (obs_b[ib].key != d.key) ++ib;
    EXPECT_EQ(ta.observables.back()[ia], d.value_a);
    EXPECT_EQ(tb.observables.back()[ib], d.value_b);
    EXPECT_NE(d.value_a, d.value_b);
  }
  expect_runs_show_the_difference(b, c);
}

}  // namespace
