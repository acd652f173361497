// Malformed property files: the exact message, with FILE:LINE:COL.
#include <gtest/gtest.h>

#include "formats/diagnostics.hpp"
#include "formats/matrix_json.hpp"
#include "properties/parser.hpp"

namespace cemv::properties {
namespace {

std::string error_of(const std::string& text) {
  static const model::Matrix m = formats::load_matrix(CEMV_SOURCE_DIR "/examples/tank-overfill/matrix.json");
  try {
    parse_properties(text, m, "req.props");
  } catch (const formats::LoadError& e) {
    if (e.issues().size() != 1) return "more than one issue";
    return e.issues()[0].where + ": error: " + e.issues()[0].what;
  }
  return "no error";
}

struct Case {
  const char* text;
  const char* message;
};

TEST(PropertiesParserErrors, ExactMessages) {
  const Case cases[] = {
      {"property p { always effect[1].active and }",
       "req.props:1:42: error: expected an expression, found '}'"},
      {"property p {\n  always (cause[1].active\n}",
       "req.props:3:1: error: expected ')', found '}'"},
      {"property p { always cause[1].actve }",
       "req.props:1:30: error: unknown cause field 'actve' (did you mean 'active'?)"},
      {"property p { always effect[1].overide_active }",
       "req.props:1:31: error: unknown effect field 'overide_active' (did you mean 'override_active'?)"},
      {"property p { always LT_10OA >= 90.0 }",
       "req.props:1:21: error: unknown tag 'LT_10OA' (did you mean 'LT_100A'?)"},
      {"property p { always cause[LT100_HHH].active }",
       "req.props:1:27: error: unknown cause 'LT100_HHH' (did you mean 'LT100_HH'?)"},
      {"property p { always cause[9].active }", "req.props:1:27: error: no cause with id 9"},
      {"property p { always effect[1].tag[2] }",
       "req.props:1:35: error: effect 1 has no tag[2] (it has 1 tag)"},
      {"property p { always issued(overide_effect, effect = 1) }",
       "req.props:1:28: error: unknown command 'overide_effect' (did you mean 'override_effect'?)"},
      {"property p { always issued(reset_effect, cause = 1) }",
       "req.props:1:42: error: expected an argument of reset_effect (effect), found 'cause'"},
      {"property p { always LT_100A }",
       "req.props:1:21: error: expected a Boolean expression, found an analog value expression"},
      {"property p { always LT_100A >= HS_100_ESD }",
       "req.props:1:29: error: cannot compare an analog value with a Boolean using '>='"},
      {"property p { always LT_100A > LT_100B }",
       "req.props:1:29: error: two analog values cannot be compared with each other (compare each with a number)"},
      {"property p { always cause[1].tripped_tags > 1.5 }",
       "req.props:1:45: error: expected an integer, found number 1.5"},
      {"property p { always cause[1].voting == 4oo5 }",
       "req.props:1:40: error: expected a voting (1oo1, 1oo2, 2oo2, 1oo3, 2oo3, 3oo3, bypass), found '4oo5'"},
      {"property p { always cause[1].voting < 2oo3 }",
       "req.props:1:37: error: votings compare only with '==' and '!=', found '<'"},
      {"property p { always 90.0 }", "req.props:1:21: error: expected a Boolean expression, found number 90.0"},
      {"property p { always held(cause[1].active, 2 hours) }",
       "req.props:1:43: error: expected a unit (ms, s, min, h or cycles), found 'hours'"},
      {"property p { always held(cause[1].active, 1.5 cycles) }",
       "req.props:1:43: error: a duration in cycles must be a whole number"},
      {"property p { always held(cause[1].active, 0.00001 min) }",
       "req.props:1:43: error: a duration must be a whole number of milliseconds"},
      {"property p { always held(cause[1].active, 2.0001 s) }",
       "req.props:1:43: error: a duration must be a whole number of milliseconds"},
      {"property p { always held(cause[1].active) }", "req.props:1:41: error: expected ',', found ')'"},
      {"property p { whenever cause[1].active then effect[1].active }",
       "req.props:1:61: error: expected 'within', found '}'"},
      {"property p { always bad(XV_101) }",
       "req.props:1:25: error: expected an input tag, found 'XV_101' (only input tags have a quality)"},
      {"property p { always any(c in sif[7].causes: c.active) }",
       "req.props:1:30: error: no SIF group 7 in the matrix"},
      {"property p { always true }\nproperty p { never false }",
       "req.props:2:10: error: property 'p' is already defined at line 1"},
      {"property p { always true always false }", "req.props:1:26: error: expected 'assume' or '}', found 'always'"},
      {"property p { }", "req.props:1:14: error: expected 'always', 'never', 'reachable', 'whenever' or 'assume', found '}'"},
      {"proprety p { always true }", "req.props:1:1: error: expected 'property' or 'assume', found 'proprety'"},
      {"property { always true }", "req.props:1:10: error: expected a property name, found '{'"},
      {"property p { always cause[1].active & true }", "req.props:1:37: error: unexpected character '&'"},
      {"property p \"never closed\n{ always true }", "req.props:1:12: error: string never closed (missing '\"')"},
      {"# expect: provd\nproperty p { always true }",
       "req.props:1:1: error: expected a verdict (proved, falsified, reachable, unreachable, vacuous), found 'provd'"},
      {"property p { always true }\n# expect: proved\n",
       "req.props:2:1: error: '# expect:' comment after the last property (it must precede its property)"},
      {"property p { always effect[1].active implies }",
       "req.props:1:46: error: expected an expression, found '}'"},
      {"property p { always count(cause[1].active, cause[2].active) }",
       "req.props:1:21: error: expected a Boolean expression, found an integer expression"},
      {"property p { always issued(soft_bypass_tag, cause = 2, tag = 2) }",
       "req.props:1:28: error: cause 2 has no tag 2"},
  };
  for (const auto& c : cases) EXPECT_EQ(error_of(c.text), c.message) << c.text;
}

TEST(PropertiesParserErrors, DeepNestingIsAnErrorNotACrash) {
  std::string text = "property p { always " + std::string(5000, '(') + "true" + std::string(5000, ')') + " }";
  EXPECT_EQ(error_of(text), "req.props:1:221: error: expression nested deeper than 200 levels");
  text = "property p { always ";
  for (int i = 0; i < 5000; ++i) text += "not ";
  EXPECT_EQ(error_of(text + "true }"), "req.props:1:817: error: expression nested deeper than 200 levels");
}

TEST(PropertiesParserErrors, UnicodeColumnsCountCharacters) {
  // "ü" is two bytes but one column.
  EXPECT_EQ(error_of("property p \"über\" { always § }"), "req.props:1:28: error: unexpected character byte 0xC2");
}

}  // namespace
}  // namespace cemv::properties

namespace cemv::properties {
namespace {

TEST(PropertiesParserErrors, SignsAreForNumbersOnly) {
  EXPECT_EQ(error_of("property p { always held(cause[1].active, -5 ms) }"),
            "req.props:1:43: error: expected a duration (e.g. 500 ms, 2 s, 10 min, 3 cycles), found '-5 ms'");
  EXPECT_EQ(error_of("property p { always cause[1].active - true }"), "req.props:1:37: error: unexpected character '-'");
  EXPECT_EQ(error_of("property p { always cause[-1].active }"), "req.props:1:27: error: no cause with id -1");
}

}  // namespace
}  // namespace cemv::properties

namespace cemv::properties {
namespace {

TEST(PropertiesParserErrors, NestedAggregatesAreBounded) {
  std::string text = "property p { always ";
  for (int i = 0; i < 12; ++i) text += "any(c" + std::to_string(i) + " in causes: ";
  text += "true" + std::string(12, ')') + " }";
  EXPECT_EQ(error_of(text), "req.props:1:239: error: aggregates expand to more than 100000 terms");
}

// Mangled requirement files: every outcome is a parsed file or one LoadError
// with a FILE:LINE:COL place, never another exception or a crash.
TEST(PropertiesParserErrors, MangledFilesFailCleanly) {
  const model::Matrix m = formats::load_matrix(CEMV_SOURCE_DIR "/examples/tank-overfill/matrix.json");
  std::string original = formats::read_text_file(CEMV_SOURCE_DIR "/examples/tank-overfill/requirements.props");
  std::uint64_t state = 12345;
  auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<std::size_t>(state >> 33);
  };
  const std::string alphabet = "(){}[],.:=<>!-#\"\\ \nabz019_\x01\xC3";
  int errors = 0;
  for (int i = 0; i < 1500; ++i) {
    std::string text = original;
    for (int edits = 1 + static_cast<int>(next() % 4); edits > 0; --edits) {
      std::size_t at = next() % text.size();
      switch (next() % 3) {
        case 0: text.erase(at, 1 + next() % 8); break;
        case 1: text.insert(at, 1, alphabet[next() % alphabet.size()]); break;
        default: text[at] = alphabet[next() % alphabet.size()]; break;
      }
    }
    try {
      parse_properties(text, m, "mangled.props");
    } catch (const formats::LoadError& e) {
      ++errors;
      ASSERT_EQ(e.issues().size(), 1u);
      EXPECT_EQ(e.issues()[0].where.rfind("mangled.props:", 0), 0u) << e.issues()[0].where;
    }
  }
  EXPECT_GT(errors, 500);
}

}  // namespace
}  // namespace cemv::properties
