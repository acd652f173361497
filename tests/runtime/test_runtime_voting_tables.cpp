// Every row of the degraded-voting tables: manual 6.1.6 ("Degraded Voting using
// the function type 2oo3 as an example") and appendix B ("Resulting cause logic
// for Degraded Voting", B.1-B.5, tables 1-3 each), plus the single-tag "normal"
// function derived from the rule of docs/semantics.md C.4 (not printed in the manual).
//
// Each printed cell stands for several concrete tag states, all of which must
// give the printed result:
//   Not tripped  healthy value, good quality (ignore tables: also bad quality,
//                since "Ignore Bad Quality" uses the delivered value)
//   Tripped      tripped value, good quality (ignore tables: also bad quality)
//   Tripped/Bad Quality (trip tables)  tripped+good, healthy+bad, tripped+bad
//   Bad Quality  (degrade tables)      healthy+bad, tripped+bad: out of the voting
//   Bypass       soft bypass of the tag with a healthy and with a tripped value
// and every state is tried with discrete DTT, discrete ETT, analog high and
// analog low tags. The manual's "(1oo1)" (all tags out, at least one for bad
// quality: the cause trips) is the voting string "1oo1".
#include <gtest/gtest.h>

#include <functional>
#include <sstream>

#include "test_sim.hpp"

namespace cemv::testing {
namespace {

struct Row {
  const char* table;        // e.g. "B4_T2"
  int case_no;
  CauseFunction function;
  BadQuality mode;
  std::vector<std::string> cells;  // "N", "T", "TQ", "Q", "B"
  const char* voting;              // expected resulting logic
  bool active;                     // expected cause status
  const char* erratum = nullptr;   // why the expectation differs from the print
};

// Printed in ctest's test list: a readable case, not the struct's raw bytes
// (which hold addresses and differ between runs).
void PrintTo(const Row& r, std::ostream* os) { *os << r.table << " case " << r.case_no; }

constexpr auto OR = CauseFunction::Or;
constexpr auto AND = CauseFunction::And;
constexpr auto V23 = CauseFunction::TwoOoThree;
constexpr auto NORMAL = CauseFunction::Normal;
constexpr auto TRIP = BadQuality::Trip;
constexpr auto DEG = BadQuality::Degrade;
constexpr auto IGN = BadQuality::Ignore;
constexpr bool A = true;   // Active
constexpr bool I = false;  // Inactive

const char* kB5Erratum =
    "B.5 table 2 prints Active for a non-tripped tag voting in 3oo3/2oo2; tables 1 and 3 print "
    "Inactive for the same tag states and AND requires every voting tag: erratum decided in "
    "docs/semantics.md C.4, the cause is inactive";

std::vector<Row> rows() {
  std::vector<Row> r = {
      // ---- B.1 OR, 2 tags (1oo2) ----
      {"B1_T1", 1, OR, TRIP, {"N", "N"}, "1oo2", I},
      {"B1_T1", 2, OR, TRIP, {"N", "TQ"}, "1oo2", A},
      {"B1_T1", 3, OR, TRIP, {"N", "B"}, "1oo1", I},
      {"B1_T1", 4, OR, TRIP, {"TQ", "TQ"}, "1oo2", A},
      {"B1_T1", 5, OR, TRIP, {"TQ", "B"}, "1oo1", A},
      {"B1_T1", 6, OR, TRIP, {"B", "B"}, "bypass", I},
      {"B1_T2", 1, OR, DEG, {"N", "N"}, "1oo2", I},
      {"B1_T2", 2, OR, DEG, {"N", "T"}, "1oo2", A},
      {"B1_T2", 3, OR, DEG, {"N", "Q"}, "1oo1", I},
      {"B1_T2", 4, OR, DEG, {"N", "B"}, "1oo1", I},
      {"B1_T2", 5, OR, DEG, {"T", "T"}, "1oo2", A},
      {"B1_T2", 6, OR, DEG, {"T", "Q"}, "1oo1", A},
      {"B1_T2", 7, OR, DEG, {"T", "B"}, "1oo1", A},
      {"B1_T2", 8, OR, DEG, {"Q", "Q"}, "1oo1", A},
      {"B1_T2", 9, OR, DEG, {"Q", "B"}, "1oo1", A},
      {"B1_T2", 10, OR, DEG, {"B", "B"}, "bypass", I},
      // The OCR places a stray "B.2 ..." heading before this table; its 1oo2
      // logic and its position show it is B.1 table 3.
      {"B1_T3", 1, OR, IGN, {"N", "N"}, "1oo2", I},
      {"B1_T3", 2, OR, IGN, {"N", "T"}, "1oo2", A},
      {"B1_T3", 3, OR, IGN, {"N", "B"}, "1oo1", I},
      {"B1_T3", 4, OR, IGN, {"T", "T"}, "1oo2", A},
      {"B1_T3", 5, OR, IGN, {"T", "B"}, "1oo1", A},
      {"B1_T3", 6, OR, IGN, {"B", "B"}, "bypass", I},
      // ---- B.2 AND, 2 tags (2oo2) ----
      {"B2_T1", 1, AND, TRIP, {"N", "N"}, "2oo2", I},
      {"B2_T1", 2, AND, TRIP, {"N", "TQ"}, "2oo2", I},
      {"B2_T1", 3, AND, TRIP, {"N", "B"}, "1oo1", I},
      {"B2_T1", 4, AND, TRIP, {"TQ", "TQ"}, "2oo2", A},
      {"B2_T1", 5, AND, TRIP, {"TQ", "B"}, "1oo1", A},
      {"B2_T1", 6, AND, TRIP, {"B", "B"}, "bypass", I},
      {"B2_T2", 1, AND, DEG, {"N", "N"}, "2oo2", I},
      {"B2_T2", 2, AND, DEG, {"N", "T"}, "2oo2", I},
      {"B2_T2", 3, AND, DEG, {"N", "Q"}, "1oo1", I},
      {"B2_T2", 4, AND, DEG, {"N", "B"}, "1oo1", I},
      {"B2_T2", 5, AND, DEG, {"T", "T"}, "2oo2", A},
      {"B2_T2", 6, AND, DEG, {"T", "Q"}, "1oo1", A},
      {"B2_T2", 7, AND, DEG, {"T", "B"}, "1oo1", A},
      {"B2_T2", 8, AND, DEG, {"Q", "Q"}, "1oo1", A},
      {"B2_T2", 9, AND, DEG, {"Q", "B"}, "1oo1", A},
      {"B2_T2", 10, AND, DEG, {"B", "B"}, "bypass", I},
      {"B2_T3", 1, AND, IGN, {"N", "N"}, "2oo2", I},
      {"B2_T3", 2, AND, IGN, {"N", "T"}, "2oo2", I},
      {"B2_T3", 3, AND, IGN, {"N", "B"}, "1oo1", I},
      {"B2_T3", 4, AND, IGN, {"T", "T"}, "2oo2", A},
      {"B2_T3", 5, AND, IGN, {"T", "B"}, "1oo1", A},
      {"B2_T3", 6, AND, IGN, {"B", "B"}, "bypass", I},
      // ---- B.3 OR, 3 tags (1oo3) ----
      {"B3_T1", 1, OR, TRIP, {"N", "N", "N"}, "1oo3", I},
      {"B3_T1", 2, OR, TRIP, {"N", "N", "TQ"}, "1oo3", A},
      {"B3_T1", 3, OR, TRIP, {"N", "N", "B"}, "1oo2", I},
      {"B3_T1", 4, OR, TRIP, {"N", "TQ", "TQ"}, "1oo3", A},
      {"B3_T1", 5, OR, TRIP, {"N", "TQ", "B"}, "1oo2", A},
      {"B3_T1", 6, OR, TRIP, {"N", "B", "B"}, "1oo1", I},
      {"B3_T1", 7, OR, TRIP, {"TQ", "TQ", "TQ"}, "1oo3", A},
      {"B3_T1", 8, OR, TRIP, {"TQ", "TQ", "B"}, "1oo2", A},
      {"B3_T1", 9, OR, TRIP, {"TQ", "B", "B"}, "1oo1", A},
      {"B3_T1", 10, OR, TRIP, {"B", "B", "B"}, "bypass", I},
      {"B3_T2", 1, OR, DEG, {"N", "N", "N"}, "1oo3", I},
      {"B3_T2", 2, OR, DEG, {"N", "N", "T"}, "1oo3", A},
      {"B3_T2", 3, OR, DEG, {"N", "N", "Q"}, "1oo2", I},
      {"B3_T2", 4, OR, DEG, {"N", "N", "B"}, "1oo2", I},
      {"B3_T2", 5, OR, DEG, {"N", "T", "T"}, "1oo3", A},
      {"B3_T2", 6, OR, DEG, {"N", "T", "Q"}, "1oo2", A},
      {"B3_T2", 7, OR, DEG, {"N", "T", "B"}, "1oo2", A},
      {"B3_T2", 8, OR, DEG, {"N", "Q", "Q"}, "1oo1", I},
      {"B3_T2", 9, OR, DEG, {"N", "Q", "B"}, "1oo1", I},
      {"B3_T2", 10, OR, DEG, {"N", "B", "B"}, "1oo1", I},
      {"B3_T2", 11, OR, DEG, {"T", "T", "T"}, "1oo3", A},
      {"B3_T2", 12, OR, DEG, {"T", "T", "Q"}, "1oo2", A},
      {"B3_T2", 13, OR, DEG, {"T", "T", "B"}, "1oo2", A},
      {"B3_T2", 14, OR, DEG, {"T", "Q", "Q"}, "1oo1", A},
      {"B3_T2", 15, OR, DEG, {"T", "Q", "B"}, "1oo1", A},
      {"B3_T2", 16, OR, DEG, {"T", "B", "B"}, "1oo1", A},
      {"B3_T2", 17, OR, DEG, {"Q", "Q", "Q"}, "1oo1", A},
      {"B3_T2", 18, OR, DEG, {"Q", "Q", "B"}, "1oo1", A},
      {"B3_T2", 19, OR, DEG, {"Q", "B", "B"}, "1oo1", A},
      {"B3_T2", 20, OR, DEG, {"B", "B", "B"}, "bypass", I},
      {"B3_T3", 1, OR, IGN, {"N", "N", "N"}, "1oo3", I},
      {"B3_T3", 2, OR, IGN, {"N", "N", "T"}, "1oo3", A},
      {"B3_T3", 3, OR, IGN, {"N", "N", "B"}, "1oo2", I},
      {"B3_T3", 4, OR, IGN, {"N", "T", "T"}, "1oo3", A},
      {"B3_T3", 5, OR, IGN, {"N", "T", "B"}, "1oo2", A},
      {"B3_T3", 6, OR, IGN, {"N", "B", "B"}, "1oo1", I},
      {"B3_T3", 7, OR, IGN, {"T", "T", "T"}, "1oo3", A},
      {"B3_T3", 8, OR, IGN, {"T", "T", "B"}, "1oo2", A},
      {"B3_T3", 9, OR, IGN, {"T", "B", "B"}, "1oo1", A},
      {"B3_T3", 10, OR, IGN, {"B", "B", "B"}, "bypass", I},
      // ---- B.4 2oo3 ----
      {"B4_T1", 1, V23, TRIP, {"N", "N", "N"}, "2oo3", I},
      {"B4_T1", 2, V23, TRIP, {"N", "N", "TQ"}, "2oo3", I},
      {"B4_T1", 3, V23, TRIP, {"N", "N", "B"}, "1oo2", I},
      {"B4_T1", 4, V23, TRIP, {"N", "TQ", "TQ"}, "2oo3", A},
      {"B4_T1", 5, V23, TRIP, {"N", "TQ", "B"}, "1oo2", A},
      {"B4_T1", 6, V23, TRIP, {"N", "B", "B"}, "1oo1", I},
      {"B4_T1", 7, V23, TRIP, {"TQ", "TQ", "TQ"}, "2oo3", A},
      {"B4_T1", 8, V23, TRIP, {"TQ", "TQ", "B"}, "1oo2", A},
      {"B4_T1", 9, V23, TRIP, {"TQ", "B", "B"}, "1oo1", A},
      {"B4_T1", 10, V23, TRIP, {"B", "B", "B"}, "bypass", I},
      {"B4_T3", 1, V23, IGN, {"N", "N", "N"}, "2oo3", I},
      {"B4_T3", 2, V23, IGN, {"N", "N", "T"}, "2oo3", I},
      {"B4_T3", 3, V23, IGN, {"N", "N", "B"}, "1oo2", I},
      {"B4_T3", 4, V23, IGN, {"N", "T", "T"}, "2oo3", A},
      {"B4_T3", 5, V23, IGN, {"N", "T", "B"}, "1oo2", A},
      {"B4_T3", 6, V23, IGN, {"N", "B", "B"}, "1oo1", I},
      {"B4_T3", 7, V23, IGN, {"T", "T", "T"}, "2oo3", A},
      {"B4_T3", 8, V23, IGN, {"T", "T", "B"}, "1oo2", A},
      {"B4_T3", 9, V23, IGN, {"T", "B", "B"}, "1oo1", A},
      {"B4_T3", 10, V23, IGN, {"B", "B", "B"}, "bypass", I},
      // ---- B.5 AND, 3 tags (3oo3) ----
      {"B5_T1", 1, AND, TRIP, {"N", "N", "N"}, "3oo3", I},
      {"B5_T1", 2, AND, TRIP, {"N", "N", "TQ"}, "3oo3", I},
      {"B5_T1", 3, AND, TRIP, {"N", "N", "B"}, "2oo2", I},
      {"B5_T1", 4, AND, TRIP, {"N", "TQ", "TQ"}, "3oo3", I},
      {"B5_T1", 5, AND, TRIP, {"N", "TQ", "B"}, "2oo2", I},
      {"B5_T1", 6, AND, TRIP, {"N", "B", "B"}, "1oo1", I},
      {"B5_T1", 7, AND, TRIP, {"TQ", "TQ", "TQ"}, "3oo3", A},
      {"B5_T1", 8, AND, TRIP, {"TQ", "TQ", "B"}, "2oo2", A},
      {"B5_T1", 9, AND, TRIP, {"TQ", "B", "B"}, "1oo1", A},
      {"B5_T1", 10, AND, TRIP, {"B", "B", "B"}, "bypass", I},
      {"B5_T2", 1, AND, DEG, {"N", "N", "N"}, "3oo3", I},
      {"B5_T2", 2, AND, DEG, {"N", "N", "T"}, "3oo3", I},
      {"B5_T2", 3, AND, DEG, {"N", "N", "Q"}, "2oo2", I},
      {"B5_T2", 4, AND, DEG, {"N", "N", "B"}, "2oo2", I},
      {"B5_T2", 5, AND, DEG, {"N", "T", "T"}, "3oo3", I, kB5Erratum},  // printed: Active
      {"B5_T2", 6, AND, DEG, {"N", "T", "Q"}, "2oo2", I, kB5Erratum},  // printed: Active
      {"B5_T2", 7, AND, DEG, {"N", "T", "B"}, "2oo2", I, kB5Erratum},  // printed: Active
      {"B5_T2", 8, AND, DEG, {"N", "Q", "Q"}, "1oo1", I},
      {"B5_T2", 9, AND, DEG, {"N", "Q", "B"}, "1oo1", I},
      {"B5_T2", 10, AND, DEG, {"N", "B", "B"}, "1oo1", I},
      {"B5_T2", 11, AND, DEG, {"T", "T", "T"}, "3oo3", A},
      {"B5_T2", 12, AND, DEG, {"T", "T", "Q"}, "2oo2", A},
      {"B5_T2", 13, AND, DEG, {"T", "T", "B"}, "2oo2", A},
      {"B5_T2", 14, AND, DEG, {"T", "Q", "Q"}, "1oo1", A},
      {"B5_T2", 15, AND, DEG, {"T", "Q", "B"}, "1oo1", A},
      {"B5_T2", 16, AND, DEG, {"T", "B", "B"}, "1oo1", A},
      {"B5_T2", 17, AND, DEG, {"Q", "Q", "Q"}, "1oo1", A},
      {"B5_T2", 18, AND, DEG, {"Q", "Q", "B"}, "1oo1", A},
      {"B5_T2", 19, AND, DEG, {"Q", "B", "B"}, "1oo1", A},
      {"B5_T2", 20, AND, DEG, {"B", "B", "B"}, "bypass", I},
      {"B5_T3", 1, AND, IGN, {"N", "N", "N"}, "3oo3", I},
      {"B5_T3", 2, AND, IGN, {"N", "N", "T"}, "3oo3", I},
      {"B5_T3", 3, AND, IGN, {"N", "N", "B"}, "2oo2", I},
      {"B5_T3", 4, AND, IGN, {"N", "T", "T"}, "3oo3", I},
      {"B5_T3", 5, AND, IGN, {"N", "T", "B"}, "2oo2", I},
      {"B5_T3", 6, AND, IGN, {"N", "B", "B"}, "1oo1", I},
      {"B5_T3", 7, AND, IGN, {"T", "T", "T"}, "3oo3", A},
      {"B5_T3", 8, AND, IGN, {"T", "T", "B"}, "2oo2", A},
      {"B5_T3", 9, AND, IGN, {"T", "B", "B"}, "1oo1", A},
      {"B5_T3", 10, AND, IGN, {"B", "B", "B"}, "bypass", I},
      // ---- single tag "normal": the C.4 rule applied to one tag ----
      {"Normal_Trip", 1, NORMAL, TRIP, {"N"}, "1oo1", I},
      {"Normal_Trip", 2, NORMAL, TRIP, {"TQ"}, "1oo1", A},
      {"Normal_Trip", 3, NORMAL, TRIP, {"B"}, "bypass", I},
      {"Normal_Degrade", 1, NORMAL, DEG, {"N"}, "1oo1", I},
      {"Normal_Degrade", 2, NORMAL, DEG, {"T"}, "1oo1", A},
      {"Normal_Degrade", 3, NORMAL, DEG, {"Q"}, "1oo1", A},
      {"Normal_Degrade", 4, NORMAL, DEG, {"B"}, "bypass", I},
      {"Normal_Ignore", 1, NORMAL, IGN, {"N"}, "1oo1", I},
      {"Normal_Ignore", 2, NORMAL, IGN, {"T"}, "1oo1", A},
      {"Normal_Ignore", 3, NORMAL, IGN, {"B"}, "bypass", I},
  };
  // B.4 table 2 and the 6.1.6 table print the same 20 rows (2oo3, degraded
  // voting at bad quality); both are kept so each printed table has its test.
  const std::vector<std::pair<std::vector<std::string>, std::pair<const char*, bool>>> deg23 = {
      {{"N", "N", "N"}, {"2oo3", I}}, {{"N", "N", "T"}, {"2oo3", I}},
      {{"N", "N", "Q"}, {"1oo2", I}}, {{"N", "N", "B"}, {"1oo2", I}},
      {{"N", "T", "T"}, {"2oo3", A}}, {{"N", "T", "Q"}, {"1oo2", A}},
      {{"N", "T", "B"}, {"1oo2", A}}, {{"N", "Q", "Q"}, {"1oo1", I}},
      {{"N", "Q", "B"}, {"1oo1", I}}, {{"N", "B", "B"}, {"1oo1", I}},
      {{"T", "T", "T"}, {"2oo3", A}}, {{"T", "T", "Q"}, {"1oo2", A}},
      {{"T", "T", "B"}, {"1oo2", A}}, {{"T", "Q", "Q"}, {"1oo1", A}},
      {{"T", "Q", "B"}, {"1oo1", A}}, {{"T", "B", "B"}, {"1oo1", A}},
      {{"Q", "Q", "Q"}, {"1oo1", A}}, {{"Q", "Q", "B"}, {"1oo1", A}},
      {{"Q", "B", "B"}, {"1oo1", A}}, {{"B", "B", "B"}, {"bypass", I}},
  };
  for (const char* table : {"B4_T2", "S6_1_6"})
    for (std::size_t i = 0; i < deg23.size(); ++i)
      r.push_back({table, static_cast<int>(i + 1), V23, DEG, deg23[i].first,
                   deg23[i].second.first, deg23[i].second.second});
  return r;
}

std::string configured_voting(CauseFunction f, int n) {
  switch (f) {
    case CauseFunction::Normal: return "1oo1";
    case CauseFunction::Or: return cat({"1oo", num(n)});
    case CauseFunction::And: return std::to_string(n) + "oo" + std::to_string(n);
    case CauseFunction::TwoOoThree: return "2oo3";
    default: return "?";
  }
}

// A concrete tag state.
struct TagState {
  bool tripped;
  bool bad;
  bool bypass;
};

std::vector<TagState> realizations(const std::string& cell, BadQuality mode) {
  if (cell == "N") {
    if (mode == BadQuality::Ignore) return {{false, false, false}, {false, true, false}};
    return {{false, false, false}};
  }
  if (cell == "T") {
    if (mode == BadQuality::Ignore) return {{true, false, false}, {true, true, false}};
    return {{true, false, false}};
  }
  if (cell == "TQ") return {{true, false, false}, {false, true, false}, {true, true, false}};
  if (cell == "Q") return {{false, true, false}, {true, true, false}};
  if (cell == "B") return {{false, false, true}, {true, false, true}};
  ADD_FAILURE() << "bad cell " << cell;
  return {};
}

std::string describe(const std::vector<TagState>& s) {
  std::ostringstream o;
  for (std::size_t i = 0; i < s.size(); ++i)
    o << (i ? ", " : "") << "tag" << i + 1 << "=" << (s[i].tripped ? "tripped" : "healthy")
      << (s[i].bad ? "+bad" : "") << (s[i].bypass ? "+soft-bypassed" : "");
  return o.str();
}

class DegradedVotingTable : public ::testing::TestWithParam<Row> {};

TEST_P(DegradedVotingTable, CauseStatusAndResultingLogicAsPrinted) {
  const Row& row = GetParam();
  if (row.erratum) RecordProperty("erratum", row.erratum);
  const int n = static_cast<int>(row.cells.size());
  const std::string configured = configured_voting(row.function, n);
  for (Kind kind : kAllKinds) {
    // Every combination of the realizations of the printed cells.
    std::vector<std::vector<TagState>> combos = {{}};
    for (const auto& cell : row.cells) {
      std::vector<std::vector<TagState>> next;
      for (const auto& prefix : combos)
        for (const auto& st : realizations(cell, row.mode)) {
          auto c = prefix;
          c.push_back(st);
          next.push_back(c);
        }
      combos = next;
    }
    for (const auto& combo : combos) {
      SCOPED_TRACE(std::string(kind_name(kind)) + ": " + describe(combo));
      Sim sim(make_matrix({make_cause(1, row.function, n, kind, row.mode)}, {make_effect(1)},
                          {link(1, 1)}));
      for (int i = 0; i < n; ++i) {
        const TagState& s = combo[static_cast<std::size_t>(i)];
        sim.set(cat({"T1_", num(i + 1)}), s.tripped ? tripped_value(kind) : healthy_value(kind),
                s.bad);
        if (s.bypass) sim.cmd(command(CommandOp::SoftBypassTag, 1, 0, i + 1, true));
      }
      // The state is held for two cycles: the table describes a steady state.
      sim.step(2);
      EXPECT_EQ(sim.b("cause[1].active"), row.active);
      EXPECT_EQ(sim.b("cause[1].trip_requested"), row.active);
      EXPECT_EQ(sim.voting(1), row.voting);
      // 6.1.6 "Activation of Degraded Voting": a soft-bypassed tag, or a bad
      // tag under "degraded voting at bad quality", changes the cause logic.
      EXPECT_EQ(sim.b("cause[1].degraded"), std::string(row.voting) != configured ||
                                                std::any_of(combo.begin(), combo.end(),
                                                            [&](const TagState& s) {
                                                              return s.bypass ||
                                                                     (s.bad && row.mode == DEG);
                                                            }));
      EXPECT_EQ(sim.b("effect[1].active"), row.active);
      EXPECT_EQ(sim.out("Y1_1"), row.active ? 0 : 1);  // DTT output: 0 when active (6.4.4)
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AppendixB, DegradedVotingTable, ::testing::ValuesIn(rows()),
                         [](const ::testing::TestParamInfo<Row>& info) {
                           return std::string(info.param.table) + "_case" +
                                  std::to_string(info.param.case_no);
                         });

}  // namespace
}  // namespace cemv::testing
