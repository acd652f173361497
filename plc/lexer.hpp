// Tokens of the Structured Text subset (docs/plc.md P.1): identifiers and
// keywords (case-insensitive), integer, REAL and TIME literals, operators and
// punctuation. Comments `(* *)`, `/* */` and `//` are skipped. What the subset
// refuses at the character level (strings, pragmas `{...}`, direct addresses
// `%IX0.0`, typed literals `INT#5`, sub-millisecond times) is a LoadError at
// its place.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "plc/ast.hpp"

namespace cemv::plc {

enum class Tok {
  End, Identifier, Integer, Real, Time,
  Assign, Arrow, LParen, RParen, Comma, Semicolon, Colon, Dot, DotDot,
  Plus, Minus, Star, Slash, Power, Eq, Ne, Lt, Le, Gt, Ge, Ampersand,
  LBracket, RBracket, Caret,
};

struct Token {
  Tok kind = Tok::End;
  std::string text;  // as written
  Position position;
  std::int64_t integer = 0;  // Integer; Time in milliseconds
  float real = 0;            // Real
};

// Where a text starts in its file: the ST body of a PLCopen POU starts inside
// the XML, so its first line starts at a column other than 1.
struct Origin {
  std::string file;
  std::size_t line = 1;
  std::size_t column = 1;
};

// Throws formats::LoadError at the first problem.
std::vector<Token> tokenize(std::string_view text, const Origin& origin);

// The same tokens read on demand, so that a problem further on in the text
// is reported only once the parser reaches it (problems come in file order).
class TokenStream {
 public:
  TokenStream(std::string_view text, const Origin& origin);
  ~TokenStream();
  // The token `ahead` places on (the End token once the text is exhausted).
  const Token& peek(std::size_t ahead = 0);
  void advance();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Throws formats::LoadError with one issue `FILE:LINE:COL: what`.
[[noreturn]] void refuse(const std::string& file, Position at, std::string what);

}  // namespace cemv::plc
