// The standard blocks against scan sequences computed by hand from
// docs/plc.md P.6 (the IEC 61131-3 state machines on the scan time base).
#include <gtest/gtest.h>

#include "plc/interpreter.hpp"
#include "plc/parser.hpp"

namespace cemv::plc {
namespace {

Value b(bool v) { return Value{Type::Bool, v ? 1 : 0, 0}; }

struct Sequence {
  std::vector<bool> q;
  std::vector<std::int64_t> et;
};

// `block` called once per scan of 100 ms with IN = ins[k], PT = pt.
Sequence timer(const std::string& block, const std::string& pt, const std::vector<bool>& ins) {
  const Program p = parse_st("PROGRAM M VAR_INPUT x : BOOL; END_VAR VAR t : " + block +
                                 "; END_VAR\n t(IN := x, PT := " + pt + "); END_PROGRAM",
                             "t.st");
  Interpreter run(p);
  Sequence out;
  for (bool in : ins) {
    run.step({{"x", b(in)}}, 100);
    out.q.push_back(run.value("t.Q").integer != 0);
    out.et.push_back(run.value("t.ET").integer);
  }
  return out;
}

TEST(PlcBlocks, OnDelay) {
  // started in scan 2 (at 200 ms), 300 ms = 3 scans: Q in scan 5
  const Sequence r = timer("TON", "T#300ms", {false, true, true, true, true, true, false, true, false});
  EXPECT_EQ(r.q, (std::vector<bool>{false, false, false, false, true, true, false, false, false}));
  EXPECT_EQ(r.et, (std::vector<std::int64_t>{0, 0, 100, 200, 300, 300, 0, 0, 0}));
}

TEST(PlcBlocks, OnDelayNotMultipleOfTheScan) {
  // 250 ms at 100 ms scans: elapsed 300 >= 250 in the third scan after the start
  const Sequence r = timer("TON", "T#250ms", {true, true, true, true});
  EXPECT_EQ(r.q, (std::vector<bool>{false, false, false, true}));
  EXPECT_EQ(r.et, (std::vector<std::int64_t>{0, 100, 200, 250}));
}

TEST(PlcBlocks, OnDelayOfZeroIsOneScanLate) {
  const Sequence r = timer("TON", "T#0s", {true, true, false});
  EXPECT_EQ(r.q, (std::vector<bool>{false, true, false}));
}

TEST(PlcBlocks, OffDelay) {
  const Sequence r = timer("TOF", "T#200ms", {true, false, false, false, false, true, false, true});
  EXPECT_EQ(r.q, (std::vector<bool>{true, true, true, false, false, true, true, true}));
  EXPECT_EQ(r.et, (std::vector<std::int64_t>{0, 0, 100, 200, 200, 0, 0, 0}));
}

TEST(PlcBlocks, Pulse) {
  // a rising edge during the pulse does not retrigger it; re-armed once IN is FALSE
  const Sequence r = timer("TP", "T#200ms", {true, false, true, true, false, true});
  EXPECT_EQ(r.q, (std::vector<bool>{true, true, false, false, false, true}));
  EXPECT_EQ(r.et, (std::vector<std::int64_t>{0, 100, 200, 200, 0, 0}));
}

std::vector<bool> two_inputs(const std::string& block, const std::string& a, const std::string& c,
                             const std::string& out, const std::vector<std::pair<bool, bool>>& ins) {
  const Program p = parse_st("PROGRAM M VAR_INPUT x, y : BOOL; END_VAR VAR f : " + block + "; END_VAR\n f(" + a +
                                 " := x" + (c.empty() ? "" : ", " + c + " := y") + "); END_PROGRAM",
                             "f.st");
  Interpreter run(p);
  std::vector<bool> q;
  for (auto [x, y] : ins) {
    run.step({{"x", b(x)}, {"y", b(y)}}, 50);
    q.push_back(run.value("f." + out).integer != 0);
  }
  return q;
}

TEST(PlcBlocks, RisingEdgeFiresInTheFirstScan) {
  EXPECT_EQ(two_inputs("R_TRIG", "CLK", "", "Q", {{true, false}, {true, false}, {false, false}, {true, false}}),
            (std::vector<bool>{true, false, false, true}));
}

TEST(PlcBlocks, FallingEdgeFiresInTheFirstScanWithClkFalse) {
  EXPECT_EQ(two_inputs("F_TRIG", "CLK", "", "Q", {{false, false}, {true, false}, {false, false}, {false, false}}),
            (std::vector<bool>{true, false, true, false}));
}

TEST(PlcBlocks, SetDominant) {
  EXPECT_EQ(two_inputs("SR", "S1", "R", "Q1",
                       {{true, true}, {false, true}, {true, false}, {false, false}, {false, true}}),
            (std::vector<bool>{true, false, true, true, false}));
}

TEST(PlcBlocks, ResetDominant) {
  EXPECT_EQ(two_inputs("RS", "S", "R1", "Q1",
                       {{true, true}, {true, false}, {false, false}, {true, true}, {false, false}}),
            (std::vector<bool>{false, true, true, false, false}));
}

TEST(PlcBlocks, ATimerNotCalledDoesNotAdvanceButTimeDoes) {
  // called only when `y`: the start is the time of the calling scan
  const Program p = parse_st(
      "PROGRAM M VAR_INPUT x, y : BOOL; END_VAR VAR t : TON; END_VAR\n"
      "IF y THEN t(IN := x, PT := T#300ms); END_IF; END_PROGRAM",
      "t.st");
  Interpreter run(p);
  run.step({{"x", b(true)}, {"y", b(true)}}, 100);   // start at 100
  run.step({{"y", b(false)}}, 100);                  // not called
  run.step({{"y", b(false)}}, 100);                  // not called
  EXPECT_FALSE(run.value("t.Q").integer);
  run.step({{"y", b(true)}}, 100);  // at 400: 300 elapsed
  EXPECT_TRUE(run.value("t.Q").integer);
  EXPECT_EQ(run.value("t.ET").integer, 300);
}

}  // namespace
}  // namespace cemv::plc
