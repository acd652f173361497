// The interpreter's scan (docs/plc.md P.8) and arithmetic (P.5).
#include <gtest/gtest.h>

#include <stdexcept>

#include "plc/interpreter.hpp"
#include "plc/parser.hpp"
#include "support.hpp"

namespace cemv::plc {
namespace {

Value b(bool v) { return Value{Type::Bool, v ? 1 : 0, 0}; }
Value i16(std::int64_t v) { return Value{Type::Int, v, 0}; }

TEST(PlcInterpreter, InitialValuesThenOneScan) {
  const Program p = parse_st(test::program("a : BOOL := TRUE; i : INT := 7; r : REAL := 1.5; t : TIME := T#2s;",
                                           "i := i + 1;"),
                             "i.st");
  Interpreter run(p);
  EXPECT_EQ(run.value("I"), i16(7));
  EXPECT_EQ(run.value("a"), b(true));
  EXPECT_EQ(run.value("r"), (Value{Type::Real, 0, 1.5f}));
  EXPECT_EQ(run.value("t"), (Value{Type::Time, 2000, 0}));
  run.step({}, 10);
  run.step({}, 10);
  EXPECT_EQ(run.value("i"), i16(9));
  EXPECT_EQ(run.scans(), 2u);
  EXPECT_EQ(run.now_ms(), 20);
  run.reset();
  EXPECT_EQ(run.value("i"), i16(7));
}

TEST(PlcInterpreter, WrapsAtTheWidthOfTheType) {
  const Program p = parse_st(test::program("i : INT := 32767; d : DINT := -2147483647; n : INT := -32768; m : INT;",
                                           "i := i + 1; d := d - 2; n := ABS(n); m := -32768 / -1;"),
                             "w.st");
  Interpreter run(p);
  run.step({}, 10);
  EXPECT_EQ(run.value("i").integer, -32768);
  EXPECT_EQ(run.value("d").integer, 2147483647);
  EXPECT_EQ(run.value("n").integer, -32768);
  EXPECT_EQ(run.value("m").integer, -32768);
}

TEST(PlcInterpreter, DivisionTruncatesTowardZero) {
  const Program p = parse_st(test::program("a, b, c, d : INT; r : REAL;",
                                           "a := -7 / 2; b := -7 MOD 2; c := 7 MOD -2; d := 7 / -2; r := 1.0 / 4.0;"),
                             "d.st");
  Interpreter run(p);
  run.step({}, 10);
  EXPECT_EQ(run.value("a").integer, -3);
  EXPECT_EQ(run.value("b").integer, -1);
  EXPECT_EQ(run.value("c").integer, 1);
  EXPECT_EQ(run.value("d").integer, -3);
  EXPECT_EQ(run.value("r").real, 0.25f);
}

TEST(PlcInterpreter, FunctionsAndTime) {
  const Program p = parse_st(
      test::program("a, b, c, d : INT; t : TIME; s : BOOL;",
                    "a := MIN(5, -2, 3); b := MAX(5, -2, 9); c := LIMIT(0, 12, 10); d := SEL(s, 1, 2);"
                    "t := MAX(T#1s, T#1m) - T#30s;"),
      "f.st");
  Interpreter run(p);
  run.step({}, 10);
  EXPECT_EQ(run.value("a").integer, -2);
  EXPECT_EQ(run.value("b").integer, 9);
  EXPECT_EQ(run.value("c").integer, 10);
  EXPECT_EQ(run.value("d").integer, 1);
  EXPECT_EQ(run.value("t").integer, 30000);
}

TEST(PlcInterpreter, ControlFlow) {
  const Program p = parse_st(test::program("i, sum, k : INT; mode : DINT := 4;",
                                           "sum := 0;\n"
                                           "FOR i := 10 TO 1 BY -3 DO sum := sum + i; END_FOR;\n"
                                           "CASE mode OF 1, 2: k := 1; 3..5: k := 2; ELSE k := 3; END_CASE;"),
                             "c.st");
  Interpreter run(p);
  run.step({}, 10);
  EXPECT_EQ(run.value("sum").integer, 10 + 7 + 4 + 1);
  EXPECT_EQ(run.value("i").integer, -2);  // the first value past the bound
  EXPECT_EQ(run.value("k").integer, 2);
}

TEST(PlcInterpreter, InputsKeepTheirValuesAndAreChecked) {
  const Program p = parse_st(
      "PROGRAM M VAR_INPUT x : BOOL; n : INT; END_VAR VAR_OUTPUT y : BOOL; END_VAR VAR z : BOOL; END_VAR\n"
      "y := x;\nEND_PROGRAM",
      "k.st");
  Interpreter run(p);
  run.step({{"X", b(true)}}, 100);
  EXPECT_TRUE(run.value("y").integer);
  EXPECT_EQ(run.last_assignment("Y"), (Position{2, 1}));
  EXPECT_EQ(run.last_assignment("z"), std::nullopt);
  run.step({}, 100);
  EXPECT_TRUE(run.value("y").integer);
  EXPECT_THROW(run.step({{"z", b(true)}}, 100), std::invalid_argument);
  EXPECT_THROW(run.step({{"nope", b(true)}}, 100), std::invalid_argument);
  EXPECT_THROW(run.step({{"n", b(true)}}, 100), std::invalid_argument);
  EXPECT_THROW(run.step({}, 0), std::invalid_argument);
  EXPECT_THROW(run.value("q"), std::invalid_argument);
}

TEST(PlcInterpreter, UserBlocksKeepStateAndBindInOut) {
  const Program p = parse_st(R"(
FUNCTION_BLOCK Vote2oo3
VAR_INPUT a, b, c : BOOL; END_VAR
VAR_OUTPUT trip : BOOL; END_VAR
VAR_IN_OUT count : INT; END_VAR
VAR seen : INT; END_VAR
trip := (a AND b) OR (a AND c) OR (b AND c);
IF trip THEN count := count + 1; END_IF;
seen := seen + 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR_INPUT x1, x2, x3 : BOOL; END_VAR
VAR_OUTPUT y : BOOL; n : INT; END_VAR
VAR v : Vote2oo3; END_VAR
v(a := x1, b := x2, c := x3, count := n, trip => y);
END_PROGRAM
)",
                             "vote.st");
  Interpreter run(p, "main");
  run.step({{"x1", b(true)}, {"x2", b(false)}, {"x3", b(false)}}, 100);
  EXPECT_FALSE(run.value("y").integer);
  run.step({{"x3", b(true)}}, 100);
  EXPECT_TRUE(run.value("y").integer);
  EXPECT_EQ(run.value("n").integer, 1);
  EXPECT_EQ(run.value("v.seen").integer, 2);
  EXPECT_EQ(run.last_assignment("n"), (Position{15, 1}));
  EXPECT_THROW(Interpreter(p, "Vote2oo3"), std::invalid_argument);
}

TEST(PlcInterpreter, NestedInstancesAndInOutOfTheProgram) {
  const Program p = parse_st(R"(
FUNCTION_BLOCK Inner
VAR_INPUT x : BOOL; END_VAR
VAR_OUTPUT q : BOOL; END_VAR
VAR edge : R_TRIG; hits : INT; END_VAR
edge(CLK := x);
IF edge.Q THEN hits := hits + 1; END_IF;
q := hits >= 2;
END_FUNCTION_BLOCK
FUNCTION_BLOCK Outer
VAR_INPUT x : BOOL; END_VAR
VAR_OUTPUT q : BOOL; END_VAR
VAR inner : Inner; END_VAR
inner(x := x, q => q);
END_FUNCTION_BLOCK
PROGRAM Other
VAR_OUTPUT z : BOOL; END_VAR
z := TRUE;
END_PROGRAM
PROGRAM Main
VAR_INPUT x : BOOL; END_VAR
VAR_IN_OUT total : DINT; END_VAR
VAR_OUTPUT q : BOOL; END_VAR
VAR o : Outer; END_VAR
o(x := x, q => q);
total := total + 1;
END_PROGRAM
)",
                             "nested.st");
  EXPECT_THROW(Interpreter{p}, std::invalid_argument);  // two PROGRAMs: one must be named
  Interpreter run(p, "MAIN");
  const Value t{Type::Bool, 1, 0}, f{Type::Bool, 0, 0};
  for (const Value& x : {t, f, t, f}) run.step({{"x", x}}, 20);
  EXPECT_EQ(run.value("o.inner.hits").integer, 2);
  EXPECT_EQ(run.value("o.inner.edge.Q").integer, 0);
  EXPECT_TRUE(run.value("q").integer);
  EXPECT_EQ(run.value("total").integer, 4);
  run.step({{"total", Value{Type::Dint, 100, 0}}}, 20);  // an in-out is also an input
  EXPECT_EQ(run.value("total").integer, 101);
  EXPECT_THROW(run.value("o.nope"), std::invalid_argument);
  EXPECT_THROW(run.value("o"), std::invalid_argument);
}

}  // namespace
}  // namespace cemv::plc
