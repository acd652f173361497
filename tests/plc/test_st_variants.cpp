// Structured Text as people write it, generated from seeded random programs
// (docs/plc.md P.1.3, P.2.3): keywords in any case, comments of the three
// kinds and line breaks between any two tokens, integers in hexadecimal,
// REAL literals with an exponent, durations spelt in their several ways. Each
// variant reads back as the program it was written from.
#include <gtest/gtest.h>

#include <random>

#include "formats/diagnostics.hpp"
#include "plc/check.hpp"
#include "plc/lexer.hpp"
#include "plc/parser.hpp"
#include "plc/print.hpp"
#include "random_program.hpp"

namespace cemv::plc {
namespace {

const char* kWords[] = {"PROGRAM", "END_PROGRAM", "FUNCTION_BLOCK", "END_FUNCTION_BLOCK", "VAR", "VAR_INPUT",
                        "VAR_OUTPUT", "VAR_IN_OUT", "END_VAR", "CONSTANT", "IF", "THEN", "ELSIF", "ELSE", "END_IF",
                        "CASE", "OF", "END_CASE", "FOR", "TO", "BY", "DO", "END_FOR", "AND", "OR", "XOR", "NOT",
                        "MOD", "TRUE", "FALSE", "BOOL", "INT", "DINT", "REAL", "TIME", "TON", "TOF", "TP", "R_TRIG",
                        "F_TRIG", "SR", "RS", "MIN", "MAX", "ABS", "SEL", "LIMIT"};

class Scrambler {
 public:
  explicit Scrambler(std::uint64_t seed) : rng_(seed) {}

  std::string run(const std::string& text) {
    const std::vector<Token> tokens = tokenize(text, Origin{"printed.st", 1, 1});
    std::string out;
    for (std::size_t i = 0; i + 1 < tokens.size(); ++i) {
      const Token& t = tokens[i];
      out += spelling(t);
      const Token& n = tokens[i + 1];
      // `-5` written together is a signed literal, `- 5` is not
      const bool glued = t.kind == Tok::Minus && n.position.line == t.position.line &&
                         n.position.column == t.position.column + 1;
      if (!glued) out += separator();
    }
    return out;
  }

 private:
  std::mt19937_64 rng_;
  int pick(int n) { return static_cast<int>(rng_() % static_cast<std::uint64_t>(n)); }

  std::string separator() {
    static const char* kSeparators[] = {" ", "  ", "\n", "\t", " (* note *) ", " // note\n", " /* note */ ", "\r\n  "};
    return kSeparators[pick(8)];
  }

  std::string any_case(std::string w) {
    for (char& c : w)
      if (pick(2)) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return w;
  }

  std::string spelling(const Token& t) {
    switch (t.kind) {
      case Tok::Identifier:
        for (const char* w : kWords)
          if (same_name(t.text, w)) return any_case(t.text);
        return t.text;
      case Tok::Integer: {
        if (pick(3) != 0) return t.text;
        char hex[32];
        std::snprintf(hex, sizeof hex, pick(2) ? "16#%llX" : "16#%llx", static_cast<unsigned long long>(t.integer));
        return hex;
      }
      case Tok::Real: return pick(2) ? t.text + "0" : t.text + (pick(2) ? "E0" : "e+00");
      case Tok::Time: return duration(t.integer);
      default: return t.text;
    }
  }

  std::string duration(std::int64_t ms) {
    const std::string prefix = std::string(pick(2) ? "T#" : "TIME#") + (ms < 0 ? "-" : "");
    const std::int64_t a = ms < 0 ? -ms : ms;
    std::string body;
    switch (pick(3)) {
      case 0: body = std::to_string(a) + "ms"; break;
      case 1:
        if (a % 100 == 0) body = std::to_string(a / 1000) + "." + std::to_string(a % 1000 / 100) + "s";
        else body = std::to_string(a / 1000) + "s_" + std::to_string(a % 1000) + "ms";
        break;
      default:
        body = std::to_string(a / 60000) + "m" + std::to_string(a % 60000 / 1000) + "s" + std::to_string(a % 1000) + "ms";
    }
    return any_case(prefix.substr(0, prefix.find('#'))) + prefix.substr(prefix.find('#')) + any_case(body);
  }
};

TEST(PlcStVariants, RandomProgramsReadBackFromEachSpelling) {
  for (std::uint64_t seed = 1; seed <= 150; ++seed) {
    Program p = test::Generator(seed).program();
    p.file = "random.st";
    check_program(p);
    const std::string text = Scrambler(seed).run(print_program(p));
    Program back;
    try {
      back = parse_st(text, "variant.st");
    } catch (const formats::LoadError& e) {
      FAIL() << "seed " << seed << ": " << e.issues()[0].message() << "\n" << text;
    }
    ASSERT_EQ(without_positions(back), without_positions(p)) << "seed " << seed << "\n" << text;
  }
}

}  // namespace
}  // namespace cemv::plc
