// The Structured Text reader (docs/plc.md P.1-P.9): a file of PROGRAM and
// FUNCTION_BLOCK POUs in, a resolved and type-checked Program out. Anything
// outside the subset is refused with a formats::LoadError at FILE:LINE:COL
// naming the construct; nothing is skipped and nothing is guessed.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "plc/ast.hpp"
#include "plc/lexer.hpp"

namespace cemv::plc {

// A whole ST text (one or more POUs), checked (check.hpp). `file` names it in
// messages and in Program::file.
Program parse_st(std::string_view text, const std::string& file);

// A program's text: PLCopen TC6 XML 2.01 when its first non-blank character
// is '<' (plcopen.hpp), Structured Text otherwise.
Program parse_program_text(std::string_view text, const std::string& file);
// The same for a file (formats::read_text_file's size guard; the CLI reads
// "-" itself and calls parse_program_text).
Program read_program(const std::filesystem::path& file);

// The pieces the PLCopen reader takes from the ST grammar, unchecked: a
// statement list (a POU body) and the value of a declaration's initial value
// (`TRUE`, `-5`, `1.5`, `T#5s`), each read from a text that starts at `origin`.
std::vector<Statement> parse_statements(std::string_view text, const Origin& origin);
Literal parse_initial_value(std::string_view text, const Origin& origin, Position& at);
// The declared type named `word` (BOOL, TON, a user block's name), refusing
// the types outside the subset at `at`.
VarType parse_type_name(const std::string& word, const std::string& file, Position at);

// Whether an identifier is a word of the language or a name of a type, block
// or function (inside the subset or refused by it): a generator never names a
// variable so.
bool is_reserved_word(std::string_view word);

}  // namespace cemv::plc
