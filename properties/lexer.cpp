#include "properties/lexer.hpp"

#include <cctype>
#include <cstdio>

#include "formats/diagnostics.hpp"
#include "model/text.hpp"

namespace cemv::properties {

namespace {

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// A character as a message may show it: printable ASCII as is, anything else
// as a byte escape (messages never carry control characters to the terminal).
std::string shown_char(char c) {
  auto u = static_cast<unsigned char>(c);
  if (u >= 0x20 && u < 0x7f) return std::string("'") + c + "'";
  char buf[16];
  std::snprintf(buf, sizeof buf, "byte 0x%02X", u);
  return buf;
}

class Lexer {
 public:
  Lexer(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  LexResult run() {
    LexResult out;
    while (true) {
      skip_blanks_and_comments(out.expects);
      Token t;
      t.loc = {line_, column_};
      if (pos_ >= text_.size()) {
        out.tokens.push_back(t);
        return out;
      }
      char c = text_[pos_];
      if (ident_start(c)) {
        t.kind = Token::Kind::Identifier;
        while (pos_ < text_.size() && ident_char(text_[pos_])) t.text += advance();
      } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                 (c == '-' && pos_ + 1 < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_ + 1])))) {
        // The language has no subtraction, so '-' before a digit is a sign.
        if (c == '-') t.text += advance();
        number(t);
      } else if (c == '"') {
        string(t);
      } else {
        symbol(t);
      }
      out.tokens.push_back(std::move(t));
    }
  }

 private:
  char advance() {
    char c = text_[pos_++];
    if (c == '\n') {
      ++line_;
      column_ = 1;
    } else if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) {
      ++column_;  // columns count characters (UTF-8 lead bytes), not bytes
    }
    return c;
  }
  bool at(char c) const { return pos_ < text_.size() && text_[pos_] == c; }

  [[noreturn]] void fail(SourceLoc loc, const std::string& what) const {
    throw formats::LoadError({{place(file_, loc), what}});
  }

  void skip_blanks_and_comments(std::vector<ExpectComment>& expects) {
    while (pos_ < text_.size()) {
      char c = text_[pos_];
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
        advance();
      } else if (c == '#') {
        int line = line_;
        std::string comment;
        while (pos_ < text_.size() && text_[pos_] != '\n') comment += advance();
        expect_comment(line, comment, expects);
      } else {
        return;
      }
    }
  }

  // `# expect: VERDICT` (blanks around the colon allowed).
  static void expect_comment(int line, std::string_view comment, std::vector<ExpectComment>& out) {
    std::size_t i = 1;
    auto blanks = [&] { while (i < comment.size() && (comment[i] == ' ' || comment[i] == '\t')) ++i; };
    blanks();
    if (comment.substr(i, 6) != "expect") return;
    i += 6;
    blanks();
    if (i >= comment.size() || comment[i] != ':') return;
    ++i;
    blanks();
    std::size_t start = i;
    while (i < comment.size() && ident_char(comment[i])) ++i;
    if (i > start) out.push_back({line, std::string(comment.substr(start, i - start))});
  }

  void number(Token& t) {
    t.kind = Token::Kind::Number;
    auto digits = [&] { while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) t.text += advance(); };
    digits();
    if (at('.') && pos_ + 1 < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_ + 1]))) {
      t.text += advance();
      digits();
    }
    if ((at('e') || at('E')) && pos_ + 1 < text_.size() &&
        (std::isdigit(static_cast<unsigned char>(text_[pos_ + 1])) ||
         ((text_[pos_ + 1] == '+' || text_[pos_ + 1] == '-') && pos_ + 2 < text_.size() &&
          std::isdigit(static_cast<unsigned char>(text_[pos_ + 2]))))) {
      t.text += advance();
      if (at('+') || at('-')) t.text += advance();
      digits();
    }
    if (pos_ < text_.size() && ident_start(text_[pos_])) {
      t.kind = Token::Kind::Word;  // 2oo3, 500ms
      while (pos_ < text_.size() && ident_char(text_[pos_])) t.text += advance();
    }
  }

  void string(Token& t) {
    t.kind = Token::Kind::String;
    advance();
    while (true) {
      if (pos_ >= text_.size() || text_[pos_] == '\n') fail(t.loc, "string never closed (missing '\"')");
      char c = advance();
      if (c == '"') return;
      if (c == '\\' && (at('"') || at('\\'))) c = advance();
      t.text += c;
    }
  }

  void symbol(Token& t) {
    t.kind = Token::Kind::Symbol;
    static const char* const kSymbols[] = {"<->", "==", "!=", "<=", ">=", "->", "(", ")", "[", "]",
                                           "{",   "}",  ",",  ".",  ":",  "=",  "<", ">"};
    for (const char* s : kSymbols) {
      std::string_view sv(s);
      if (text_.substr(pos_, sv.size()) == sv) {
        for (std::size_t i = 0; i < sv.size(); ++i) t.text += advance();
        return;
      }
    }
    fail(t.loc, "unexpected character " + shown_char(text_[pos_]));
  }

  std::string_view text_;
  const std::string& file_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;
};

}  // namespace

LexResult tokenize(std::string_view text, const std::string& file_name) {
  return Lexer(text, file_name).run();
}

std::string describe(const Token& t) {
  switch (t.kind) {
    case Token::Kind::End: return "end of file";
    case Token::Kind::Number: return "number " + t.text;
    case Token::Kind::String: return "string " + model::in_quotes(t.text, 40);
    default: return model::in_quotes(t.text, 40);
  }
}

std::string place(const std::string& file_name, SourceLoc loc) {
  return file_name + ":" + std::to_string(loc.line) + ":" + std::to_string(loc.column);
}

}  // namespace cemv::properties
