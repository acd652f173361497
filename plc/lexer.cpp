#include "plc/lexer.hpp"

#include <cctype>
#include <charconv>
#include <limits>

#include "formats/diagnostics.hpp"
#include "model/text.hpp"

namespace cemv::plc {

void refuse(const std::string& file, Position at, std::string what) {
  formats::LoadIssue issue{"", std::move(what), file, at.line, at.column};
  throw formats::LoadError({issue});
}

namespace {

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return c >= '0' && c <= '9'; }

// Largest TIME: a signed 32-bit count of milliseconds (P.2).
constexpr std::int64_t kMaxTimeMs = std::numeric_limits<std::int32_t>::max();

class Lexer {
 public:
  Lexer(std::string_view text, const Origin& origin)
      : text_(text), file_(origin.file), line_(origin.line), column_(origin.column) {}

  std::vector<Token> run() {
    std::vector<Token> out;
    do out.push_back(next());
    while (out.back().kind != Tok::End);
    return out;
  }

  Token next() {
    skip_space_and_comments();
    Token t;
    t.position = here();
    if (i_ < text_.size()) lex_one(t);
    return t;
  }

 private:
  std::string_view text_;
  std::string file_;
  std::size_t i_ = 0;
  std::size_t line_, column_;

  Position here() const { return {line_, column_}; }
  char peek(std::size_t ahead = 0) const { return i_ + ahead < text_.size() ? text_[i_ + ahead] : '\0'; }
  void advance(std::size_t n = 1) {
    for (std::size_t k = 0; k < n && i_ < text_.size(); ++k, ++i_) {
      if (text_[i_] == '\n') {
        ++line_;
        column_ = 1;
      } else {
        ++column_;
      }
    }
  }
  [[noreturn]] void fail(Position at, std::string what) const { refuse(file_, at, std::move(what)); }

  void skip_space_and_comments() {
    for (;;) {
      char c = peek();
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
        advance();
      } else if (c == '/' && peek(1) == '/') {
        while (i_ < text_.size() && peek() != '\n') advance();
      } else if ((c == '(' || c == '/') && peek(1) == '*') {
        const Position start = here();
        const char close = c == '(' ? ')' : '/';
        advance(2);
        while (!(peek() == '*' && peek(1) == close)) {
          if (i_ >= text_.size()) fail(start, "comment not closed");
          advance();
        }
        advance(2);
      } else {
        return;
      }
    }
  }

  void lex_one(Token& t) {
    const char c = peek();
    if (ident_start(c)) return identifier_or_prefixed(t);
    if (digit(c)) return number(t);
    struct Punct {
      std::string_view text;
      Tok kind;
    };
    static constexpr Punct puncts[] = {
        {":=", Tok::Assign}, {"=>", Tok::Arrow}, {"<>", Tok::Ne}, {"<=", Tok::Le}, {">=", Tok::Ge},
        {"**", Tok::Power},  {"..", Tok::DotDot}, {"(", Tok::LParen}, {")", Tok::RParen}, {",", Tok::Comma},
        {";", Tok::Semicolon}, {":", Tok::Colon}, {".", Tok::Dot}, {"+", Tok::Plus}, {"-", Tok::Minus},
        {"*", Tok::Star}, {"/", Tok::Slash}, {"=", Tok::Eq}, {"<", Tok::Lt}, {">", Tok::Gt},
        {"&", Tok::Ampersand}, {"[", Tok::LBracket}, {"]", Tok::RBracket}, {"^", Tok::Caret},
    };
    for (const Punct& p : puncts) {
      if (text_.substr(i_, p.text.size()) == p.text) {
        t.kind = p.kind;
        t.text = std::string(p.text);
        advance(p.text.size());
        return;
      }
    }
    if (c == '{') fail(t.position, "pragma '{...}' is not in the subset (docs/plc.md P.1)");
    if (c == '\'' || c == '"') fail(t.position, "string literal is not in the subset (docs/plc.md P.2)");
    if (c == '%') fail(t.position, "direct address '%...' is not in the subset (docs/plc.md P.3)");
    fail(t.position, "unexpected character " + model::in_quotes(text_.substr(i_, 1)));
  }

  void identifier_or_prefixed(Token& t) {
    std::size_t n = 0;
    while (ident_char(peek(n))) ++n;
    const std::string word(text_.substr(i_, n));
    if (peek(n) == '#') {
      if (same_name(word, "T") || same_name(word, "TIME")) {
        advance(n + 1);
        return time_literal(t, word);
      }
      fail(t.position, "typed literal " + model::in_quotes(word + "#...") +
                           " is not in the subset (docs/plc.md P.2); write the literal alone");
    }
    t.kind = Tok::Identifier;
    t.text = word;
    advance(n);
  }

  std::string digits_with_underscores(bool hex) {
    std::string out;
    while (hex ? std::isxdigit(static_cast<unsigned char>(peek())) || peek() == '_' : digit(peek()) || peek() == '_') {
      if (peek() != '_') out += peek();
      advance();
    }
    return out;
  }

  void number(Token& t) {
    const std::size_t start = i_;
    std::string whole = digits_with_underscores(false);
    if (peek() == '#') {  // 2#1010, 8#17, 16#FF
      advance();
      int base = 0;
      std::from_chars(whole.data(), whole.data() + whole.size(), base);
      if (base != 2 && base != 8 && base != 16) fail(t.position, "integer base " + whole + "# is not 2, 8 or 16");
      const std::string d = digits_with_underscores(true);
      std::uint64_t v = 0;
      auto r = std::from_chars(d.data(), d.data() + d.size(), v, base);
      if (d.empty() || r.ptr != d.data() + d.size()) fail(t.position, "malformed integer literal");
      if (r.ec != std::errc{} || v > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
        fail(t.position, "integer literal out of range");
      t.kind = Tok::Integer;
      t.integer = static_cast<std::int64_t>(v);
      t.text = std::string(text_.substr(start, i_ - start));
      return;
    }
    if (peek() == '.' && digit(peek(1))) {
      advance();
      std::string frac = digits_with_underscores(false);
      std::string s = whole + "." + frac;
      if (peek() == 'e' || peek() == 'E') {
        s += 'e';
        advance();
        if (peek() == '+' || peek() == '-') {
          s += peek();
          advance();
        }
        if (!digit(peek())) fail(t.position, "malformed REAL literal");
        s += digits_with_underscores(false);
      }
      float v = 0;
      auto r = std::from_chars(s.data(), s.data() + s.size(), v);
      if (r.ec != std::errc{} || r.ptr != s.data() + s.size())
        fail(t.position, "REAL literal " + model::in_quotes(s) + " is out of single-precision range");
      t.kind = Tok::Real;
      t.real = v;
      t.text = std::string(text_.substr(start, i_ - start));
      return;
    }
    std::int64_t v = 0;
    auto r = std::from_chars(whole.data(), whole.data() + whole.size(), v);
    if (r.ec != std::errc{}) fail(t.position, "integer literal out of range");
    t.kind = Tok::Integer;
    t.integer = v;
    t.text = std::string(text_.substr(start, i_ - start));
    if (ident_start(peek())) fail(here(), "unexpected " + model::in_quotes(std::string(1, peek())) + " after a number");
  }

  // T#5s, T#1m30s, T#1.5s, T#-200ms, TIME#1h_2m: units d, h, m, s, ms in
  // decreasing order, the total a whole number of milliseconds (P.2).
  void time_literal(Token& t, const std::string& prefix) {
    const std::size_t start = i_;
    bool negative = false;
    if (peek() == '-') {
      negative = true;
      advance();
    } else if (peek() == '+') {
      advance();
    }
    struct Unit {
      std::string_view name;
      std::int64_t ms;
    };
    static constexpr Unit units[] = {{"ms", 1}, {"d", 86400000}, {"h", 3600000}, {"m", 60000}, {"s", 1000}};
    std::int64_t last_unit = std::numeric_limits<std::int64_t>::max();
    // total in thousandths of a millisecond, so fractions are exact
    __int128 total = 0;
    bool any = false;
    for (;;) {
      if (peek() == '_' && any) advance();
      if (!digit(peek())) break;
      std::string whole = digits_with_underscores(false), frac;
      if (peek() == '.' && digit(peek(1))) {
        advance();
        frac = digits_with_underscores(false);
      }
      const Unit* unit = nullptr;
      for (const Unit& u : units) {
        const std::string_view w = text_.substr(i_, u.name.size());
        if (w.size() == u.name.size() && same_name(w, u.name) &&
            !std::isalpha(static_cast<unsigned char>(peek(u.name.size())))) {
          unit = &u;
          break;
        }
      }
      if (!unit) {
        std::size_t n = 0;
        while (ident_char(peek(n)) && !digit(peek(n))) ++n;
        fail(here(), "time unit " + model::in_quotes(text_.substr(i_, n)) +
                         " is not in the subset (d, h, m, s, ms; docs/plc.md P.2)");
      }
      if (unit->ms >= last_unit) fail(here(), "time units must decrease (d, h, m, s, ms)");
      last_unit = unit->ms;
      if (whole.size() > 12 || frac.size() > 9) fail(t.position, "TIME literal out of range");
      __int128 w = std::stoll(whole);
      __int128 f = 0, scale = 1;
      for (char ch : frac) {
        f = f * 10 + (ch - '0');
        scale *= 10;
      }
      total += w * unit->ms * 1000 + f * unit->ms * 1000 / scale;
      if (f * unit->ms * 1000 % scale != 0) fail(t.position, "TIME literal is finer than a microsecond");
      advance(unit->name.size());
      any = true;
      if (total > static_cast<__int128>(kMaxTimeMs) * 1000 + 999) fail(t.position, "TIME literal out of range (at most T#24d20h31m23s647ms)");
    }
    if (!any) fail(t.position, "malformed TIME literal " + model::in_quotes(prefix + "#" + std::string(text_.substr(start, i_ - start))));
    if (total % 1000 != 0) fail(t.position, "TIME literal is not a whole number of milliseconds (docs/plc.md P.2)");
    if (ident_char(peek())) fail(here(), "malformed TIME literal");
    t.kind = Tok::Time;
    t.integer = static_cast<std::int64_t>(total / 1000) * (negative ? -1 : 1);
    t.text = prefix + "#" + std::string(text_.substr(start, i_ - start));
  }
};

}  // namespace

std::vector<Token> tokenize(std::string_view text, const Origin& origin) { return Lexer(text, origin).run(); }

struct TokenStream::Impl {
  Lexer lexer;
  std::deque<Token> ahead;
};

TokenStream::TokenStream(std::string_view text, const Origin& origin)
    : impl_(std::make_unique<Impl>(Impl{Lexer(text, origin), {}})) {}
TokenStream::~TokenStream() = default;

const Token& TokenStream::peek(std::size_t ahead) {
  while (impl_->ahead.size() <= ahead) {
    if (!impl_->ahead.empty() && impl_->ahead.back().kind == Tok::End) return impl_->ahead.back();
    impl_->ahead.push_back(impl_->lexer.next());
  }
  return impl_->ahead[ahead];
}

void TokenStream::advance() {
  peek();
  if (impl_->ahead.front().kind != Tok::End) impl_->ahead.pop_front();
}

}  // namespace cemv::plc
