// The ST reader: what it accepts and how it resolves it (docs/plc.md P.1-P.7).
#include <gtest/gtest.h>

#include "plc/parser.hpp"
#include "plc/print.hpp"
#include "support.hpp"

namespace cemv::plc {
namespace {

const char* kTank = R"((* Tank overfill protection, written by hand *)
PROGRAM Tank
VAR_INPUT
  LSHH_101 : BOOL;          // level switch high-high
  LT_101 : REAL := 0.0;
  Reset : BOOL;
END_VAR
VAR_OUTPUT
  XV_101 : BOOL := TRUE;    (* inlet valve open *)
  Alarm : BOOL;
END_VAR
VAR
  Delay : TON;
  Latch : SR;
  Edge : R_TRIG;
  Count : INT := -3;
END_VAR
VAR CONSTANT
  Limit : REAL := 85.5;
  N : INT := 3;
END_VAR
  Delay(IN := LSHH_101 OR LT_101 > Limit, PT := T#1m30s);
  Edge(CLK := Reset);
  Latch(S1 := Delay.Q, R := Edge.Q AND NOT Delay.Q);
  xv_101 := NOT latch.Q1;
  IF Latch.Q1 THEN
    Alarm := TRUE;
  ELSIF LT_101 >= 80.0 THEN
    Alarm := TRUE;
  ELSE
    Alarm := FALSE;
  END_IF;
  CASE Count OF
    -3, 0..2: Count := Count + 1;
    3: ;
  ELSE
    Count := 0;
  END_CASE;
  FOR Count := 1 TO N BY 1 DO
    Alarm := Alarm OR Delay.ET > T#10s;
  END_FOR;
END_PROGRAM
)";

TEST(PlcParser, ReadsTheSubset) {
  const Program p = parse_st(kTank, "tank.st");
  ASSERT_EQ(p.pous.size(), 1u);
  const Pou& pou = p.pous[0];
  EXPECT_EQ(pou.name, "Tank");
  EXPECT_EQ(pou.kind, PouKind::Program);
  ASSERT_EQ(pou.variables.size(), 11u);
  EXPECT_EQ(pou.variables[0].section, Section::Input);
  EXPECT_EQ(pou.variables[3].name, "XV_101");
  EXPECT_EQ(pou.variables[3].initial->integer, 1);
  EXPECT_EQ(pou.variables[5].type.kind, VarType::Kind::Standard);
  EXPECT_EQ(pou.variables[5].type.block, StandardBlock::Ton);
  EXPECT_EQ(pou.variables[9].section, Section::Constant);
  EXPECT_EQ(pou.variables[9].initial->type, Type::Real);
  EXPECT_EQ(pou.variables[8].initial->integer, -3);
  EXPECT_EQ(pou.variables[8].initial->type, Type::Int);
  ASSERT_EQ(pou.body.size(), 7u);
  // the call, its arguments, the TIME literal
  const Statement& call = pou.body[0];
  EXPECT_EQ(call.kind, Statement::Kind::Call);
  EXPECT_EQ(call.position, (Position{22, 3}));
  ASSERT_EQ(call.args.size(), 2u);
  EXPECT_EQ(call.args[0].pin, Pin::In);
  EXPECT_EQ(call.args[1].value.literal, (Literal{Type::Time, 90000, 0}));
  // names resolved to their declared spelling, members to pins
  const Statement& assign = pou.body[3];
  EXPECT_EQ(assign.target, "XV_101");
  EXPECT_EQ(assign.value.args[0].name, "Latch");
  EXPECT_EQ(assign.value.args[0].member, "Q1");
  EXPECT_EQ(assign.value.args[0].pin, Pin::Q1);
  // CASE labels, FOR bounds with a constant
  EXPECT_EQ(pou.body[5].arms[0].labels, (std::vector<CaseRange>{{-3, -3}, {0, 2}}));
  EXPECT_EQ(pou.body[6].from, 1);
  EXPECT_EQ(pou.body[6].to, 3);
  EXPECT_EQ(pou.body[6].limit.name, "N");
}

TEST(PlcParser, PrintsWhatItReadsBack) {
  const Program p = parse_st(kTank, "tank.st");
  const std::string text = print_program(p);
  const Program again = parse_st(text, "printed.st");
  EXPECT_EQ(without_positions(again), without_positions(p)) << text;
  EXPECT_EQ(print_program(again), text);
}

TEST(PlcParser, KeywordsAndNamesAnyCase) {
  const Program p = parse_st(
      "program m var_input a : bool; end_var var_output B : Bool; end_var\n"
      "if A and not a then b := true; end_if; END_PROGRAM",
      "m.st");
  EXPECT_EQ(p.pous[0].body[0].branches[0].body[0].target, "B");
  EXPECT_EQ(p.pous[0].body[0].branches[0].condition.args[0].name, "a");
}

TEST(PlcParser, TimeLiterals) {
  struct Case {
    const char* text;
    std::int64_t ms;
  };
  for (const Case& c : {Case{"T#5s", 5000}, Case{"T#1m30s", 90000}, Case{"TIME#100ms", 100}, Case{"t#1.5s", 1500},
                        Case{"T#1h_2m", 3720000}, Case{"T#2d", 172800000}, Case{"T#-250ms", -250}, Case{"T#0s", 0}}) {
    const Program p = parse_st(test::program("t : TIME;", std::string("t := ") + c.text + ";"), "t.st");
    EXPECT_EQ(p.pous[0].body[0].value.literal.integer, c.ms) << c.text;
    EXPECT_EQ(literal_text(Literal{Type::Time, c.ms, 0}).substr(0, 2), "T#");
  }
}

TEST(PlcParser, IntegerLiteralsTakeTheirContextsType) {
  const Program p = parse_st(test::program("i : INT; d : DINT; r : REAL;",
                                           "i := 16#7FFF; d := 2#1010 * 3; r := 2 * r + 1; i := -32768;"),
                             "l.st");
  const auto& body = p.pous[0].body;
  EXPECT_EQ(body[0].value.type, Type::Int);
  EXPECT_EQ(body[0].value.literal.integer, 32767);
  EXPECT_EQ(body[1].value.args[0].literal, (Literal{Type::Dint, 10, 0}));
  EXPECT_EQ(body[2].value.args[0].args[0].literal, (Literal{Type::Real, 0, 2.0f}));
  EXPECT_EQ(body[3].value.literal.integer, -32768);
}

TEST(PlcParser, UserBlocksWithInOut) {
  const Program p = parse_st(R"(
FUNCTION_BLOCK Vote2oo3
VAR_INPUT a, b, c : BOOL; END_VAR
VAR_OUTPUT trip : BOOL; END_VAR
VAR_IN_OUT count : INT; END_VAR
trip := (a AND b) OR (a AND c) OR (b AND c);
IF trip THEN count := count + 1; END_IF;
END_FUNCTION_BLOCK
PROGRAM Main
VAR_INPUT x1, x2, x3 : BOOL; END_VAR
VAR_OUTPUT y : BOOL; n : INT; END_VAR
VAR v : Vote2oo3; END_VAR
v(a := x1, b := x2, c := x3, count := n, trip => y);
END_PROGRAM
)",
                             "vote.st");
  ASSERT_EQ(p.pous.size(), 2u);
  EXPECT_EQ(p.pous[1].variables[5].type.kind, VarType::Kind::User);
  EXPECT_EQ(p.pous[1].variables[5].type.user, "Vote2oo3");
  EXPECT_TRUE(p.pous[1].body[0].args[4].output);
}

TEST(PlcParser, PrecedenceAsIecTable) {
  const Program p = parse_st(test::program("a, b, c : BOOL; i : INT;", "a := a OR b AND c = (i + 2 * 3 > 4);"), "p.st");
  const Expr& e = p.pous[0].body[0].value;
  ASSERT_EQ(e.binary, BinaryOp::Or);
  ASSERT_EQ(e.args[1].binary, BinaryOp::And);
  ASSERT_EQ(e.args[1].args[1].binary, BinaryOp::Eq);
  EXPECT_EQ(print_expression(e), "a OR b AND c = i + 2 * 3 > 4");
}

TEST(PlcParser, CommentsOfAllThreeKinds) {
  const Program p = parse_st(test::program("a : BOOL; (* x *)", "/* block\ncomment */ a := TRUE; // end"), "c.st");
  EXPECT_EQ(p.pous[0].body[0].position, (Position{4, 12}));
}

}  // namespace
}  // namespace cemv::plc
