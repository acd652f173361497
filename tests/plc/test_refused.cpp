// Everything outside the subset is refused at its place, naming the
// construct (docs/plc.md P.1-P.9): nothing skipped, nothing guessed.
#include <gtest/gtest.h>

#include "support.hpp"

namespace cemv::plc {
namespace {

using test::program;

TEST(PlcRefused, Statements) {
  EXPECT_REFUSED(program("a : BOOL;", "WHILE a DO a := FALSE; END_WHILE;"), 3, 1, "statement WHILE");
  EXPECT_REFUSED(program("a : BOOL;", "a := TRUE;\n  REPEAT a := FALSE; UNTIL a END_REPEAT;"), 4, 3, "statement REPEAT");
  EXPECT_REFUSED(program("a : BOOL;", "IF a THEN RETURN; END_IF;"), 3, 11, "statement RETURN");
  EXPECT_REFUSED(program("i : INT;", "FOR i := 1 TO 3 DO EXIT; END_FOR;"), 3, 20, "statement EXIT");
  EXPECT_REFUSED(program("i : INT;", "CASE i OF 1: CONTINUE; END_CASE;"), 3, 14, "statement CONTINUE");
}

TEST(PlcRefused, Types) {
  EXPECT_REFUSED(program("s : STRING;", ""), 2, 9, "type 'STRING'");
  EXPECT_REFUSED(program("a : ARRAY[1..3] OF INT;", ""), 2, 9, "type 'ARRAY'");
  EXPECT_REFUSED(program("p : POINTER TO INT;", ""), 2, 9, "type 'POINTER'");
  EXPECT_REFUSED(program("w : WORD;", ""), 2, 9, "type 'WORD'");
  EXPECT_REFUSED(program("r : LREAL;", ""), 2, 9, "type 'LREAL'");
  EXPECT_REFUSED("TYPE Mode : (A, B); END_TYPE\nPROGRAM P END_PROGRAM", 1, 1, "'TYPE' is not in the subset");
  EXPECT_REFUSED(program("a : BOOL;", "a := 'x' = 'y';"), 3, 6, "string literal");
  EXPECT_REFUSED(program("i : INT;", "i := INT#5;"), 3, 6, "typed literal 'INT#...'");
  EXPECT_REFUSED(program("t : TIME;", "t := T#5us;"), 3, 9, "time unit 'us'");
}

TEST(PlcRefused, Blocks) {
  EXPECT_REFUSED(program("c : CTU;", ""), 2, 9, "standard block 'CTU'");
  EXPECT_REFUSED(program("v : Voter;", ""), 2, 5, "unknown type or function block 'Voter'");
  EXPECT_REFUSED(program("a : BOOL;", "Timer1(IN := a);"), 3, 1, "undeclared variable 'Timer1'");
  EXPECT_REFUSED(program("a : BOOL;", "a(IN := TRUE);"), 3, 1, "'a' is not a block instance");
  EXPECT_REFUSED(program("t : TON; a : BOOL;", "t(a, T#1s);"), 3, 3, "positional arguments");
  EXPECT_REFUSED(program("t : TON; a : BOOL;", "t(IN := a, PT := T#1s, Q := a);"), 3, 24, "'Q' is an output");
  EXPECT_REFUSED(program("t : TON;", "t(IM := TRUE);"), 3, 3, "'IM' is not a parameter of TON (did you mean 'IN'?)");
  EXPECT_REFUSED(program("t : TON; a : BOOL;", "t.IN := a;"), 3, 1, "assignment to 't.IN'");
  EXPECT_REFUSED(program("t : TON; a : BOOL;", "a := t.IN;"), 3, 6, "'IN' is not an output of TON");
  EXPECT_REFUSED("FUNCTION_BLOCK F VAR x : F; END_VAR END_FUNCTION_BLOCK\nPROGRAM P VAR f : F; END_VAR END_PROGRAM", 1,
                 22, "contains an instance of itself");
  EXPECT_REFUSED("FUNCTION F : BOOL F := TRUE; END_FUNCTION", 1, 1, "'FUNCTION' is not in the subset");
}

TEST(PlcRefused, Pragmas) {
  EXPECT_REFUSED(program("a : BOOL;", "{attribute 'hide'}\na := TRUE;"), 3, 1, "pragma");
  EXPECT_REFUSED("{warning 'x'}\nPROGRAM P END_PROGRAM", 1, 1, "pragma");
}

TEST(PlcRefused, Functions) {
  EXPECT_REFUSED(program("r : REAL;", "r := SQRT(r);"), 3, 6, "function 'SQRT' is not in the subset");
  EXPECT_REFUSED(program("r : REAL; i : INT;", "r := INT_TO_REAL(i);"), 3, 6, "function 'INT_TO_REAL'");
  EXPECT_REFUSED(program("i : INT; b : BOOL;", "i := BOOL_TO_INT(b);"), 3, 6, "function 'BOOL_TO_INT'");
  EXPECT_REFUSED(program("i : INT;", "i := Scale(i);"), 3, 6, "unknown function 'Scale'");
  EXPECT_REFUSED(program("i : INT;", "i := LIMIT(MN := 0, IN := i, MX := 9);"), 3, 12, "named arguments of a function");
  EXPECT_REFUSED(program("i : INT;", "i := i ** 2;"), 3, 8, "operator '**'");
  EXPECT_REFUSED(program("i : INT;", "MAX(i, 1);"), 3, 1, "not a statement");
}

TEST(PlcRefused, NonConstantForBounds) {
  EXPECT_REFUSED(program("i, n : INT;", "FOR i := 1 TO n DO END_FOR;"), 3, 15, "'n' is a variable");
  EXPECT_REFUSED(program("i, n : INT;", "FOR i := 1 TO n + 1 DO END_FOR;"), 3, 15, "FOR bounds must be constants");
  EXPECT_REFUSED(program("i : INT;", "FOR i := 1 TO 10 BY 0 DO END_FOR;"), 3, 21, "BY 0");
  EXPECT_REFUSED(program("i : INT;", "FOR i := 1 TO 32767 DO END_FOR;"), 3, 1, "iterations");
  EXPECT_REFUSED(program("i : INT;", "FOR i := 32760 TO 32767 DO END_FOR;"), 3, 1, "leaves the range of INT");
  EXPECT_REFUSED(program("i, j : INT;", "FOR i := 1 TO 3 DO i := 2; END_FOR;"), 3, 20, "FOR variable 'i' inside its loop");
}

TEST(PlcRefused, Declarations) {
  EXPECT_REFUSED("PROGRAM P VAR_TEMP a : BOOL; END_VAR END_PROGRAM", 1, 11, "variable section 'VAR_TEMP'");
  EXPECT_REFUSED("PROGRAM P VAR_GLOBAL a : BOOL; END_VAR END_PROGRAM", 1, 11, "variable section 'VAR_GLOBAL'");
  EXPECT_REFUSED("PROGRAM P VAR RETAIN a : BOOL; END_VAR END_PROGRAM", 1, 15, "qualifier 'RETAIN'");
  EXPECT_REFUSED(program("a AT %IX0.0 : BOOL;", ""), 2, 7, "located variable");
  EXPECT_REFUSED(program("a : BOOL; A : INT;", ""), 2, 15, "declared twice");
  EXPECT_REFUSED("PROGRAM P VAR CONSTANT k : INT; END_VAR END_PROGRAM", 1, 24, "needs an initial value");
  EXPECT_REFUSED(program("i : INT := 40000;", ""), 2, 16, "out of the range of INT");
  EXPECT_REFUSED("FUNCTION_BLOCK F END_FUNCTION_BLOCK", 1, 1, "no PROGRAM");
}

TEST(PlcRefused, NamesAndTypes) {
  EXPECT_REFUSED(program("level : REAL;", "levle := 1.0;"), 3, 1, "undeclared variable 'levle' (did you mean 'level'?)");
  EXPECT_REFUSED("PROGRAM P VAR_INPUT a : BOOL; END_VAR a := TRUE; END_PROGRAM", 1, 39, "assignment to the input 'a'");
  EXPECT_REFUSED("PROGRAM P VAR CONSTANT k : INT := 1; END_VAR k := 2; END_PROGRAM", 1, 46, "assignment to the constant");
  EXPECT_REFUSED(program("a : BOOL; i : INT;", "a := i;"), 3, 6, "a INT assigned to 'a' of type BOOL");
  EXPECT_REFUSED(program("a : BOOL; i : INT;", "i := a + 1;"), 3, 6, "different types BOOL and DINT");
  EXPECT_REFUSED(program("i : INT; d : DINT;", "d := i + d;"), 3, 6, "different types INT and DINT");
  EXPECT_REFUSED(program("a : BOOL; i : INT;", "IF i THEN a := TRUE; END_IF;"), 3, 4, "IF condition must be a BOOL");
  EXPECT_REFUSED(program("a : BOOL; i : INT;", "a := i AND a;"), 3, 6, "'AND' takes BOOL operands");
  EXPECT_REFUSED(program("a, b : BOOL;", "a := a < b;"), 3, 6, "of BOOL values");
  EXPECT_REFUSED(program("i : INT;", "i := 40000;"), 3, 6, "out of the range of INT");
  EXPECT_REFUSED(program("t : TIME;", "t := 5;"), 3, 6, "a DINT assigned to 't'");
  EXPECT_REFUSED(program("t : TON; a : BOOL;", "a := t;"), 3, 6, "block instance 't' used as a value");
}

TEST(PlcRefused, DivisionOnlyByNonZeroConstants) {
  EXPECT_REFUSED(program("i, j : INT;", "i := i / j;"), 3, 10, "divisor of '/'");
  EXPECT_REFUSED(program("i : INT;", "i := i MOD 0;"), 3, 12, "division by zero");
  EXPECT_REFUSED(program("r : REAL;", "r := r / 0.0;"), 3, 10, "division by zero");
  EXPECT_NO_THROW(parse_st(program("i : INT; r : REAL;", "i := i / -3 + i MOD 7; r := r / 2.5;"), "ok.st"));
}

TEST(PlcRefused, CaseLabels) {
  EXPECT_REFUSED(program("i : INT;", "CASE i OF 1..3: i := 0; 2: i := 1; END_CASE;"), 3, 25, "label 2 appears twice");
  EXPECT_REFUSED(program("i : INT; a : BOOL;", "CASE a OF 1: i := 0; END_CASE;"), 3, 6, "selector must be an INT");
}

TEST(PlcRefused, SyntaxErrorsArePlaced) {
  EXPECT_REFUSED(program("a : BOOL;", "a := TRUE"), 4, 1, "expected ';'");
  EXPECT_REFUSED(program("a : BOOL;", "IF a THEN a := FALSE;"), 4, 1, "expected END_IF");
  EXPECT_REFUSED(program("a : BOOL;", "(* never closed"), 3, 1, "comment not closed");
  EXPECT_REFUSED("PROGRAM P VAR a : BOOL; END_VAR a := TRUE;", 1, 43, "expected END_PROGRAM");
}

}  // namespace
}  // namespace cemv::plc
