#include "plc/parser.hpp"

#include <algorithm>
#include <array>

#include "formats/diagnostics.hpp"
#include "model/text.hpp"
#include "plc/check.hpp"
#include "plc/plcopen.hpp"
#include "plc/parse_support.hpp"

namespace cemv::plc {

namespace parse {

constexpr std::string_view kKeywords[] = {
    "PROGRAM", "END_PROGRAM", "FUNCTION_BLOCK", "END_FUNCTION_BLOCK", "FUNCTION", "END_FUNCTION",
    "VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_TEMP", "VAR_GLOBAL", "VAR_EXTERNAL",
    "VAR_ACCESS", "VAR_CONFIG", "VAR_STAT", "VAR_INST", "END_VAR", "CONSTANT", "RETAIN", "NON_RETAIN", "PERSISTENT",
    "AT", "IF", "THEN", "ELSIF", "ELSE", "END_IF", "CASE", "OF", "END_CASE", "FOR", "TO", "BY", "DO",
    "END_FOR", "WHILE", "END_WHILE", "REPEAT", "UNTIL", "END_REPEAT", "RETURN", "EXIT", "CONTINUE",
    "JMP", "AND", "OR", "XOR", "NOT", "MOD", "TRUE", "FALSE", "TYPE", "END_TYPE", "STRUCT",
    "END_STRUCT", "ARRAY", "CONFIGURATION", "END_CONFIGURATION", "RESOURCE", "END_RESOURCE", "TASK",
    "METHOD", "END_METHOD", "INTERFACE", "END_INTERFACE", "CLASS", "END_CLASS", "NAMESPACE",
    "END_NAMESPACE", "ACTION", "END_ACTION", "STEP", "END_STEP", "TRANSITION", "END_TRANSITION",
    "INITIAL_STEP", "SUPER", "THIS", "REF_TO", "POINTER"};

// Types of IEC 61131-3 outside the subset (P.2), named as such when declared.
constexpr std::string_view kRefusedTypes[] = {
    "STRING", "WSTRING", "CHAR", "WCHAR", "ARRAY", "STRUCT", "POINTER", "REF_TO", "REFERENCE", "SINT",
    "USINT", "UINT", "UDINT", "LINT", "ULINT", "LREAL", "BYTE", "WORD", "DWORD", "LWORD", "DATE",
    "TIME_OF_DAY", "TOD", "DATE_AND_TIME", "DT", "LTIME", "LDATE", "LTOD", "LDT", "LTIME_OF_DAY",
    "LDATE_AND_TIME", "ANY", "ANY_NUM", "ANY_INT", "ANY_REAL", "ANY_BIT"};

// Standard function blocks outside the subset (P.6).
constexpr std::string_view kRefusedBlocks[] = {"CTU", "CTD", "CTUD", "CTU_INT", "CTU_DINT", "CTU_LINT",
                                               "CTU_UDINT", "CTU_ULINT", "CTD_INT", "CTD_DINT", "CTD_LINT",
                                               "CTD_UDINT", "CTD_ULINT", "CTUD_INT", "CTUD_DINT", "CTUD_LINT",
                                               "CTUD_UDINT", "CTUD_ULINT", "RTC", "SEMA", "LTON", "LTOF", "LTP"};

// Standard functions outside the subset (P.5).
constexpr std::string_view kRefusedFunctions[] = {
    "SQRT", "LN", "LOG", "EXP", "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "ATAN2", "ADD", "SUB",
    "MUL", "DIV", "EXPT", "MOVE", "SHL", "SHR", "ROL", "ROR", "MUX", "GT", "GE", "EQ", "LE", "LT",
    "NE", "LEN", "LEFT", "RIGHT", "MID", "CONCAT", "INSERT", "DELETE", "REPLACE", "FIND", "TRUNC",
    "ROUND", "AND", "OR", "XOR", "NOT", "SIZEOF", "ADR", "REF"};

template <std::size_t N>
bool in(const std::string_view (&set)[N], std::string_view word) {
  return std::any_of(std::begin(set), std::end(set), [&](std::string_view k) { return same_name(k, word); });
}

bool is_keyword(std::string_view w) { return in(kKeywords, w); }

bool is_conversion(std::string_view w) {  // INT_TO_REAL, TO_DINT, REAL_TRUNC_INT...
  std::string up;
  for (char c : w) up += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return up.find("_TO_") != std::string::npos || up.rfind("TO_", 0) == 0 || up.find("TRUNC") != std::string::npos;
}

bool refused_function(std::string_view word) { return in(kRefusedFunctions, word) || is_conversion(word); }
bool refused_type(std::string_view word) { return in(kRefusedTypes, word); }
bool refused_block(std::string_view word) { return in(kRefusedBlocks, word); }

std::string upper(std::string_view word) {
  std::string s;
  for (char c : word) s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace parse

namespace {

using namespace parse;

// POUs and their declarations (P.1, P.3), over the statements of
// parse_statements.cpp.
class Parser : public StatementParser {
 public:
  using StatementParser::StatementParser;

  Program program() {
    Program p;
    p.file = file_;
    while (!at(Tok::End)) p.pous.push_back(pou());
    if (p.pous.empty()) fail(peek().position, "no PROGRAM or FUNCTION_BLOCK in the file");
    return p;
  }

  std::vector<Statement> statements_to_end() {
    auto body = statement_list();
    if (!at(Tok::End)) unexpected("a statement");
    return body;
  }

  Literal initial_value_to_end(Position& at_pos) {
    at_pos = peek().position;
    Literal l = initial_value();
    if (!at(Tok::End)) unexpected("the end of the initial value");
    return l;
  }

 private:
  Pou pou() {
    Pou p;
    p.position = peek().position;
    std::string_view end;
    if (at_word("PROGRAM")) {
      p.kind = PouKind::Program;
      end = "END_PROGRAM";
    } else if (at_word("FUNCTION_BLOCK")) {
      p.kind = PouKind::FunctionBlock;
      end = "END_FUNCTION_BLOCK";
    } else if (at(Tok::Identifier) && (at_word("FUNCTION") || at_word("TYPE") || at_word("CONFIGURATION") ||
                                       at_word("VAR_GLOBAL") || at_word("CLASS") || at_word("INTERFACE") ||
                                       at_word("NAMESPACE") || at_word("ACTION") || at_word("METHOD"))) {
      fail(peek().position, std::string(model::in_quotes(peek().text)) +
                                " is not in the subset: a file holds PROGRAM and FUNCTION_BLOCK POUs (docs/plc.md P.1)");
    } else {
      unexpected("PROGRAM or FUNCTION_BLOCK");
    }
    next();
    p.name = identifier("the POU's name");
    if (at_word("EXTENDS") || at_word("IMPLEMENTS"))
      fail(peek().position, model::in_quotes(peek().text) + " (object orientation) is not in the subset (docs/plc.md P.1)");
    while (at(Tok::Identifier) && is_keyword(peek().text) && peek().text.size() >= 3 &&
           same_name(std::string_view(peek().text).substr(0, 3), "VAR"))
      declarations(p);
    p.body = statement_list();
    if (at_word("METHOD") || at_word("ACTION") || at_word("VAR") || at_word("VAR_INPUT"))
      fail(peek().position, model::in_quotes(peek().text) + " here is not in the subset (docs/plc.md P.1)");
    expect_word(end);
    return p;
  }

  void declarations(Pou& p) {
    const Token& head = next();
    Section section;
    if (same_name(head.text, "VAR")) {
      section = Section::Local;
      if (at_word("CONSTANT")) {
        next();
        section = Section::Constant;
      }
    } else if (same_name(head.text, "VAR_INPUT")) {
      section = Section::Input;
    } else if (same_name(head.text, "VAR_OUTPUT")) {
      section = Section::Output;
    } else if (same_name(head.text, "VAR_IN_OUT")) {
      section = Section::InOut;
    } else {
      fail(head.position, "variable section " + model::in_quotes(head.text) + " is not in the subset (docs/plc.md P.3)");
    }
    if (at_word("RETAIN") || at_word("NON_RETAIN") || at_word("PERSISTENT") || at_word("CONSTANT"))
      fail(peek().position, "qualifier " + model::in_quotes(peek().text) + " on " + head.text +
                                " is not in the subset (docs/plc.md P.3)");
    while (!at_word("END_VAR")) {
      std::vector<std::pair<std::string, Position>> names;
      do {
        if (!names.empty()) next();
        const Position pos = peek().position;
        names.emplace_back(identifier("a variable name or END_VAR"), pos);
      } while (at(Tok::Comma));
      if (at_word("AT"))
        fail(peek().position, "located variable (AT %...) is not in the subset (docs/plc.md P.3)");
      expect(Tok::Colon, ":");
      const Position type_pos = peek().position;
      if (!at(Tok::Identifier)) unexpected("a type");
      VarType type = parse_type_name(next().text, file_, type_pos);
      if (at(Tok::LBracket) || at(Tok::LParen))
        fail(peek().position, "a subrange, array or string length is not in the subset (docs/plc.md P.2)");
      std::optional<Literal> initial;
      Position initial_pos;
      if (at(Tok::Assign)) {
        next();
        initial_pos = peek().position;
        if (type.kind != VarType::Kind::Elementary)
          fail(initial_pos, "an initial value of a block instance is not in the subset (docs/plc.md P.3)");
        initial = initial_value();
      }
      expect(Tok::Semicolon, ";");
      for (auto& [name, pos] : names)
        p.variables.push_back(Variable{pos, name, section, type, initial, initial_pos, {}});
    }
    next();  // END_VAR
  }

  Literal initial_value() {
    const Position at_pos = peek().position;
    Expr e = unary();
    if (e.kind != Expr::Kind::Literal)
      fail(at_pos, "an initial value must be a literal (TRUE, 5, -1.5, T#5s) (docs/plc.md P.3)");
    return e.literal;
  }

};

}  // namespace


VarType parse_type_name(const std::string& word, const std::string& file, Position at) {
  VarType t;
  if (auto e = type_from_name(word)) {
    t.type = *e;
    return t;
  }
  if (auto b = block_from_name(word)) {
    t.kind = VarType::Kind::Standard;
    t.block = *b;
    return t;
  }
  if (in(kRefusedTypes, word))
    refuse(file, at, "type " + model::in_quotes(word) + " is not in the subset (BOOL, INT, DINT, REAL, TIME; docs/plc.md P.2)");
  if (in(kRefusedBlocks, word))
    refuse(file, at, "standard block " + model::in_quotes(word) + " is not in the subset (docs/plc.md P.6)");
  if (is_keyword(word)) refuse(file, at, "expected a type, found " + model::in_quotes(word));
  t.kind = VarType::Kind::User;
  t.user = word;
  return t;
}

std::vector<Statement> parse_statements(std::string_view text, const Origin& origin) {
  return Parser(text, origin).statements_to_end();
}

Literal parse_initial_value(std::string_view text, const Origin& origin, Position& at) {
  return Parser(text, origin).initial_value_to_end(at);
}

Program parse_st(std::string_view text, const std::string& file) {
  Program p = Parser(text, Origin{file, 1, 1}).program();
  check_program(p);
  return p;
}

Program parse_program_text(std::string_view text, const std::string& file) {
  std::size_t i = 0;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") i = 3;  // a UTF-8 byte order mark
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  if (i < text.size() && text[i] == '<') return parse_plcopen(text, file);
  return parse_st(text.substr(text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0), file);
}

Program read_program(const std::filesystem::path& file) {
  return parse_program_text(formats::read_text_file(file), file.string());
}

bool is_reserved_word(std::string_view word) {
  return is_keyword(word) || in(kRefusedTypes, word) || in(kRefusedBlocks, word) || in(kRefusedFunctions, word) ||
         is_conversion(word) || type_from_name(word) || block_from_name(word) || function_from_name(word) ||
         same_name(word, "TIME") || same_name(word, "T") || same_name(word, "EN") || same_name(word, "ENO");
}

}  // namespace cemv::plc
