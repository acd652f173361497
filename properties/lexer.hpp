// Tokens of the property language (docs/properties.md, "Lexical structure").
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "properties/ast.hpp"

namespace cemv::properties {

struct Token {
  enum class Kind {
    Identifier,  // letters, digits, '_' (not starting with a digit)
    Number,      // 12, 90.0, 1.5e3, -40.5 (no subtraction exists, so '-' before a digit is a sign)
    Word,        // a number glued to letters: 2oo3, 500ms
    String,      // "..." (escapes \" and \\), text holds the content
    Symbol,      // ( ) [ ] { } , . : = == != < <= > >= -> <->
    End,
  };
  Kind kind = Kind::End;
  std::string text;
  SourceLoc loc;
};

// A `# expect: VERDICT` comment, attached by the parser to the next property.
struct ExpectComment {
  int line = 0;
  std::string verdict;
};

struct LexResult {
  std::vector<Token> tokens;  // ends with one End token
  std::vector<ExpectComment> expects;
};

// Splits a property file into tokens; `#` starts a comment to the end of the
// line. Throws LoadError ("FILE:LINE:COL" places) on a character that starts
// no token or an unterminated string.
LexResult tokenize(std::string_view text, const std::string& file_name);

// How a token is named in "expected X, found Y" messages.
std::string describe(const Token& t);

// "FILE:LINE:COL" of a place in the file.
std::string place(const std::string& file_name, SourceLoc loc);

}  // namespace cemv::properties
