// The differential test of the program's two semantics (docs/plc.md): seeded
// random programs of the whole subset, written as Structured Text and read by
// plc/'s parser, run on random inputs by plc/'s interpreter and by
// plc_encoder/'s transition system evaluated concretely; every variable, pin
// and output compared after every scan.
#include <cmath>
#include <cstring>
#include <random>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "plc/interpreter.hpp"
#include "plc/parser.hpp"
#include "plc_encoder/encode.hpp"

namespace {

using namespace cemv;

constexpr std::uint32_t kScanMs = 100;

class ProgramGenerator {
 public:
  explicit ProgramGenerator(unsigned seed) : rng_(seed) {}

  std::string program() {
    std::ostringstream s;
    s << "PROGRAM RANDOM_P\nVAR_INPUT\n  IB1 : BOOL; IB2 : BOOL; IB3 : BOOL; II1 : INT; II2 : INT; IR1 : REAL; IR2 : REAL;"
         " IT1 : TIME; ID1 : DINT;\nEND_VAR\n"
         "VAR_OUTPUT\n  OB1 : BOOL; OI1 : INT; OR1 : REAL;\nEND_VAR\n"
         "VAR\n  LB1 : BOOL := TRUE; LB2 : BOOL; LI1 : INT := 3; LI2 : INT; LR1 : REAL := 1.5; LT1 : TIME; LD1 : DINT;\n"
         "  TN1 : TON; TF1 : TOF; TP1 : TP; RT1 : R_TRIG; FT1 : F_TRIG; SR1 : SR; RS1 : RS;\nEND_VAR\n";
    for (int i = pick(6) + 2; i > 0; --i) s << statement(2, true);
    // Every timer exactly once per scan, outside any branch (docs/plc.md).
    s << "TN1(IN := " << boolean(2) << ", PT := " << time(1) << ");\n";
    s << "TF1(IN := " << boolean(2) << ", PT := " << time(1) << ");\n";
    s << "TP1(IN := " << boolean(2) << ", PT := " << time(1) << ");\n";
    for (int i = pick(6) + 2; i > 0; --i) s << statement(2, true);
    s << "END_PROGRAM\n";
    return s.str();
  }

 private:
  int pick(int n) { return static_cast<int>(rng_() % static_cast<unsigned>(n)); }

  std::string boolean(int d) {
    const int k = d <= 0 ? pick(3) : pick(12);
    switch (k) {
      case 0: return pick(2) ? "TRUE" : "FALSE";
      case 1: { const char* v[] = {"IB1", "IB2", "IB3", "LB1", "LB2", "OB1"}; return v[pick(6)]; }
      case 2: { const char* v[] = {"TN1.Q", "TF1.Q", "TP1.Q", "RT1.Q", "FT1.Q", "SR1.Q1", "RS1.Q1"}; return v[pick(7)]; }
      case 3: return "NOT " + boolean(d - 1);
      case 4: return "(" + boolean(d - 1) + " AND " + boolean(d - 1) + ")";
      case 5: return "(" + boolean(d - 1) + " OR " + boolean(d - 1) + ")";
      case 6: return "(" + boolean(d - 1) + " XOR " + boolean(d - 1) + ")";
      case 7: { const char* op[] = {"=", "<>", "<", "<=", ">", ">="}; return "(" + integer(d - 1) + " " + op[pick(6)] + " " + integer(d - 1) + ")"; }
      case 8: { const char* op[] = {"=", "<>", "<", "<=", ">", ">="}; return "(" + real(d - 1) + " " + op[pick(6)] + " " + real(d - 1) + ")"; }
      case 9: { const char* op[] = {"=", "<", ">="}; return "(" + time(d - 1) + " " + op[pick(3)] + " " + time(d - 1) + ")"; }
      case 10: return "(" + dint(d - 1) + " > " + dint(d - 1) + ")";
      default: return "(" + boolean(d - 1) + " = " + boolean(d - 1) + ")";
    }
  }

  std::string integer(int d) {
    const int k = d <= 0 ? pick(2) : pick(11);
    switch (k) {
      case 0: return std::to_string(pick(201) - 100);
      case 1: { const char* v[] = {"II1", "II2", "LI1", "LI2", "OI1"}; return v[pick(5)]; }
      case 2: return "(" + integer(d - 1) + " + " + integer(d - 1) + ")";
      case 3: return "(" + integer(d - 1) + " - " + integer(d - 1) + ")";
      case 4: return "(" + integer(d - 1) + " * " + integer(d - 1) + ")";
      case 5: return "(" + integer(d - 1) + " / " + std::to_string(pick(2) ? pick(9) + 1 : -(pick(9) + 1)) + ")";
      case 6: return "(" + integer(d - 1) + " MOD " + std::to_string(pick(9) + 1) + ")";
      case 7: return "(-" + integer(d - 1) + ")";
      case 8: return std::string(pick(2) ? "MIN(" : "MAX(") + integer(d - 1) + ", " + integer(d - 1) + ")";
      case 9: return "SEL(" + boolean(d - 1) + ", " + integer(d - 1) + ", " + integer(d - 1) + ")";
      default: return pick(2) ? "ABS(" + integer(d - 1) + ")" : "LIMIT(" + integer(d - 1) + ", " + integer(d - 1) + ", " + integer(d - 1) + ")";
    }
  }

  std::string dint(int d) {
    switch (d <= 0 ? pick(2) : pick(4)) {
      case 0: return std::to_string(pick(200001) - 100000);
      case 1: return pick(2) ? "ID1" : "LD1";
      case 2: return "(" + dint(d - 1) + " * " + dint(d - 1) + ")";
      default: return "(" + dint(d - 1) + " - " + dint(d - 1) + ")";
    }
  }

  std::string real(int d) {
    const int k = d <= 0 ? pick(2) : pick(9);
    switch (k) {
      case 0: { const char* v[] = {"0.0", "1.5", "-2.25", "90.0", "0.1", "1.0E30"}; return v[pick(6)]; }
      case 1: { const char* v[] = {"IR1", "IR2", "LR1", "OR1"}; return v[pick(4)]; }
      case 2: return "(" + real(d - 1) + " + " + real(d - 1) + ")";
      case 3: return "(" + real(d - 1) + " - " + real(d - 1) + ")";
      case 4: return "(" + real(d - 1) + " * " + real(d - 1) + ")";
      case 5: { const char* v[] = {"4.0", "-0.5", "3.0", "1.0E-3"}; return "(" + real(d - 1) + " / " + v[pick(4)] + ")"; }
      case 6: return "ABS(" + real(d - 1) + ")";
      case 7: return std::string(pick(2) ? "MIN(" : "MAX(") + real(d - 1) + ", " + real(d - 1) + ")";
      default: return "(-" + real(d - 1) + ")";
    }
  }

  std::string time(int d) {
    switch (d <= 0 ? pick(3) : pick(5)) {
      case 0: { const char* v[] = {"T#0ms", "T#100ms", "T#250ms", "T#300ms", "T#1s"}; return v[pick(5)]; }
      case 1: return pick(2) ? "IT1" : "LT1";
      case 2: { const char* v[] = {"TN1.ET", "TF1.ET", "TP1.ET"}; return v[pick(3)]; }
      case 3: return "(" + time(d - 1) + " + " + time(d - 1) + ")";
      default: return "(" + time(d - 1) + " - T#100ms)";
    }
  }

  std::string pad(int indent) { return std::string(static_cast<std::size_t>(indent), ' '); }

  std::string body(int indent, int n) {
    std::string s;
    for (int i = 0; i < n; ++i) s += statement(indent, false);
    return s;
  }

  std::string statement(int indent, bool top) {
    const int k = pick(top ? 14 : 11);
    const std::string p = pad(indent);
    switch (k) {
      case 0: case 1: { const char* v[] = {"LB1", "LB2", "OB1"}; return p + v[pick(3)] + " := " + boolean(3) + ";\n"; }
      case 2: case 3: { const char* v[] = {"LI1", "OI1"}; return p + v[pick(2)] + " := " + integer(3) + ";\n"; }
      case 4: { const char* v[] = {"LR1", "OR1"}; return p + v[pick(2)] + " := " + real(3) + ";\n"; }
      case 5: return p + "LT1 := " + time(2) + ";\n";
      case 6: return p + "LD1 := " + dint(2) + ";\n";
      case 7: return p + "RT1(CLK := " + boolean(2) + ");\n" + (pick(2) ? p + "FT1(CLK := " + boolean(2) + ");\n" : "");
      case 8: return pick(2) ? p + "SR1(S1 := " + boolean(2) + ", R := " + boolean(2) + ");\n"
                             : p + "RS1(S := " + boolean(2) + ", R1 := " + boolean(2) + ");\n";
      case 9: return p + "RT1(CLK := " + boolean(2) + ", Q => LB2);\n";
      case 10: return p + "LB1 := NOT LB1;\n";
      case 11: {
        std::string s = p + "IF " + boolean(3) + " THEN\n" + body(indent + 2, pick(3) + 1);
        if (pick(2)) s += p + "ELSIF " + boolean(2) + " THEN\n" + body(indent + 2, pick(2) + 1);
        if (pick(2)) s += p + "ELSE\n" + body(indent + 2, pick(2) + 1);
        return s + p + "END_IF;\n";
      }
      case 12: {
        std::string s = p + "CASE " + integer(1) + " OF\n";
        s += p + "  1: \n" + body(indent + 4, pick(2) + 1);
        s += p + "  2..4, 7:\n" + body(indent + 4, pick(2) + 1);
        s += p + "  -5:\n" + body(indent + 4, 1);
        if (pick(2)) s += p + "ELSE\n" + body(indent + 2, pick(2) + 1);
        return s + p + "END_CASE;\n";
      }
      default: {
        const int from = pick(3), to = from + pick(4);
        return p + "FOR LI2 := " + std::to_string(from) + " TO " + std::to_string(to) + (pick(3) == 0 ? " BY 2" : "") +
               " DO\n" + body(indent + 2, pick(2) + 1) + p + "END_FOR;\n";
      }
    }
  }

  std::mt19937 rng_;
};

// A value of the encoding's terms after substitution, as the interpreter's Value.
plc::Value value_of(const z3::expr& e, plc::Type t) {
  plc::Value v;
  v.type = t;
  if (t == plc::Type::Bool) {
    EXPECT_TRUE(e.is_true() || e.is_false()) << e;
    v.integer = e.is_true();
  } else if (t == plc::Type::Real) {
    if (Z3_fpa_is_numeral_nan(e.ctx(), e)) {
      v.real = NAN;
      return v;
    }
    z3::expr bits = z3::expr(e.ctx(), Z3_mk_fpa_to_ieee_bv(e.ctx(), e)).simplify();
    EXPECT_TRUE(bits.is_numeral()) << e;
    if (!bits.is_numeral()) return v;
    std::uint32_t u = static_cast<std::uint32_t>(bits.get_numeral_uint64());
    std::memcpy(&v.real, &u, sizeof u);
  } else {
    EXPECT_TRUE(e.is_numeral()) << e;
    if (!e.is_numeral()) return v;
    const unsigned w = e.get_sort().bv_size();
    std::int64_t x = static_cast<std::int64_t>(e.get_numeral_uint64());
    if (x >= (std::int64_t{1} << (w - 1))) x -= std::int64_t{1} << w;
    v.integer = x;
  }
  return v;
}

bool same(const plc::Value& a, const plc::Value& b) {
  if (a.type == plc::Type::Real) return (std::isnan(a.real) && std::isnan(b.real)) || std::memcmp(&a.real, &b.real, sizeof(float)) == 0;
  return a.integer == b.integer;
}

std::string text(const plc::Value& v) {
  return v.type == plc::Type::Real ? std::to_string(v.real) : std::to_string(v.integer);
}

plc::Type type_of_state(const plc::Program& p, const std::string& key, const z3::expr& var) {
  if (var.is_bool()) return plc::Type::Bool;
  if (var.is_fpa()) return plc::Type::Real;
  if (var.get_sort().bv_size() == 16) return plc::Type::Int;
  (void)p;
  (void)key;
  return plc::Type::Dint;  // TIME and DINT compare as 32-bit integers
}

// What the interpreter names: variables and the outputs of the blocks (their
// inputs and internal state have no name outside the block).
bool observable(const std::string& name) {
  const auto dot = name.find('.', 4);
  if (dot == std::string::npos) return true;
  const std::string pin = name.substr(dot + 1);
  return pin == "Q" || pin == "Q1" || pin == "ET";
}

// Inputs of one scan, at random, with the corner values that matter.
std::map<std::string, plc::Value> random_inputs(std::mt19937& rng) {
  auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  std::map<std::string, plc::Value> in;
  for (const char* b : {"IB1", "IB2", "IB3"}) in[b] = plc::Value{plc::Type::Bool, pick(2), 0};
  const std::int64_t ints[] = {0, 1, -1, 32767, -32768, 5, 100};
  for (const char* i : {"II1", "II2"}) in[i] = plc::Value{plc::Type::Int, pick(2) ? ints[pick(7)] : pick(201) - 100, 0};
  const float reals[] = {0.0f, -0.0f, 90.0f, 1e30f, -1e-30f, NAN, INFINITY, 0.1f};
  for (const char* r : {"IR1", "IR2"}) in[r] = plc::Value{plc::Type::Real, 0, pick(2) ? reals[pick(8)] : static_cast<float>(pick(2001) - 1000) / 8.0f};
  in["IT1"] = plc::Value{plc::Type::Time, pick(6) * 100 - pick(2) * 50, 0};
  in["ID1"] = plc::Value{plc::Type::Dint, pick(2) ? 2147483647 : pick(200001) - 100000, 0};
  return in;
}

TEST(PlcEncoderDiff, RandomProgramsAgreeWithTheInterpreter) {
  int programs = 0;
  for (unsigned seed = 1; seed <= 150; ++seed) {
    const std::string st = ProgramGenerator(seed).program();
    plc::Program program;
    try {
      program = plc::parse_st(st, "random.st");
    } catch (const std::exception& e) {
      FAIL() << "seed " << seed << ": the generator wrote a program the parser refuses: " << e.what() << "\n" << st;
    }
    ++programs;
    const plc::Pou& pou = *plc::find_pou(program, "RANDOM_P");
    z3::context ctx;
    const auto sys = plc_encoder::encode(ctx, program, pou, kScanMs, "plc.");
    plc::Interpreter interp(program, "RANDOM_P");
    std::mt19937 rng(seed * 7919u);
    // The encoding's state, concretely: one value per state variable.
    z3::expr_vector vars(ctx), values(ctx);
    for (const auto& s : sys.states) {
      vars.push_back(s.var);
      values.push_back(s.init);
    }
    for (int scan = 1; scan <= 25; ++scan) {
      const auto in = random_inputs(rng);
      interp.step(in, kScanMs);
      z3::expr_vector from(ctx), to(ctx);
      for (unsigned i = 0; i < vars.size(); ++i) {
        from.push_back(vars[i]);
        to.push_back(values[i]);
      }
      for (const auto& i : sys.inputs) {
        const plc::Value& v = in.at(i.variable);
        from.push_back(i.var);
        to.push_back(i.type == plc::Type::Bool   ? ctx.bool_val(v.integer != 0)
                     : i.type == plc::Type::Real ? ctx.fpa_val(v.real)
                     : i.type == plc::Type::Int  ? ctx.bv_val(static_cast<int>(v.integer), 16)
                                                 : ctx.bv_val(v.integer, 32));
      }
      z3::expr_vector next(ctx);
      for (const auto& s : sys.states) next.push_back(z3::expr(s.next).substitute(from, to).simplify());
      for (unsigned i = 0; i < sys.states.size(); ++i) {
        const std::string& name = sys.states[i].name;
        if (!observable(name)) continue;
        const plc::Type t = type_of_state(program, name, sys.states[i].var);
        const plc::Value enc = value_of(next[i], t);
        const plc::Value run = interp.value(name.substr(4));
        ASSERT_TRUE(same(enc, run)) << "seed " << seed << ", scan " << scan << ": " << name.substr(4) << " is "
                                    << text(run) << " on the interpreter, " << text(enc) << " in the encoding\n"
                                    << st;
      }
      for (const auto& o : sys.outputs) {
        const plc::Value enc = value_of(z3::expr(o.term).substitute(from, to).simplify(), o.type);
        ASSERT_TRUE(same(enc, interp.value(o.variable))) << "seed " << seed << ", scan " << scan << ": output " << o.variable << "\n" << st;
      }
      values = next;
    }
  }
  EXPECT_EQ(programs, 150);
}

// A timer called inside a branch is refused by the encoding, at its call.
TEST(PlcEncoderDiff, TimerInsideABranchIsRefused) {
  const plc::Program p = plc::parse_st(
      "PROGRAM P\nVAR_INPUT A : BOOL; END_VAR\nVAR_OUTPUT Q : BOOL; END_VAR\nVAR T : TON; END_VAR\n"
      "IF A THEN\n  T(IN := A, PT := T#1s);\nEND_IF;\nQ := T.Q;\nEND_PROGRAM\n", "branch.st");
  z3::context ctx;
  try {
    plc_encoder::encode(ctx, p, p.pous.front(), 100, "plc.");
    FAIL() << "accepted";
  } catch (const plc_encoder::Unsupported& e) {
    EXPECT_EQ(e.at.line, 6u);
    EXPECT_NE(std::string(e.what()).find("called inside IF, CASE or FOR"), std::string::npos) << e.what();
  }
}

}  // namespace
