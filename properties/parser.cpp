// Property files: top-level assumptions and property blocks
// (docs/properties.md, "Files and properties").
#include "properties/parser.hpp"

#include <cctype>
#include <cstring>
#include <map>

#include "formats/diagnostics.hpp"
#include "formats/text_encoding.hpp"
#include "properties/parser_impl.hpp"
#include "properties/traps.hpp"

namespace cemv::properties {

namespace {

constexpr const char* kVerdicts[] = {"proved", "falsified", "reachable", "unreachable", "vacuous"};

// Durations longer than this are refused: no requirement of a matrix needs
// them (the longest timers of 3.4 are hours), and they guard the evaluator.
constexpr std::uint64_t kMaxDurationCycles = 10'000'000;

}  // namespace

bool is_verdict(std::string_view word) {
  for (const char* v : kVerdicts)
    if (word == v) return true;
  return false;
}

Parser::Parser(std::string_view text, const model::Matrix& m, const std::string& file)
    : file_(file.empty() ? "<properties>" : file), names_(m), lex_(tokenize(text, file_)) {}

// ---- tokens -------------------------------------------------------------------

const Token& Parser::peek(std::size_t ahead) const {
  return lex_.tokens[std::min(pos_ + ahead, lex_.tokens.size() - 1)];
}

const Token& Parser::next() {
  const Token& t = peek();
  if (pos_ + 1 < lex_.tokens.size()) ++pos_;
  return t;
}

bool Parser::symbol(const char* s, std::size_t ahead) const {
  const Token& t = peek(ahead);
  return t.kind == Token::Kind::Symbol && t.text == s;
}

bool Parser::keyword(const char* k, std::size_t ahead) const {
  const Token& t = peek(ahead);
  return t.kind == Token::Kind::Identifier && t.text == k;
}

bool Parser::accept_symbol(const char* s) {
  if (!symbol(s)) return false;
  next();
  return true;
}

void Parser::expect_symbol(const char* s) {
  if (!accept_symbol(s)) fail_expected(std::string("'") + s + "'");
}

void Parser::expect_keyword(const char* k) {
  if (!keyword(k)) fail_expected(std::string("'") + k + "'");
  next();
}

void Parser::fail_expected(const std::string& expected) const {
  fail_at(peek().loc, "expected " + expected + ", found " + describe(peek()));
}

void Parser::fail_at(SourceLoc loc, const std::string& what) const {
  throw formats::LoadError({{place(file_, loc), what}});
}

// ---- file -----------------------------------------------------------------------

PropertyFile Parser::parse_file() {
  PropertyFile out;
  out.file_name = file_;
  std::vector<std::string> file_notes;
  std::map<std::string, int> defined;  // name -> line
  int previous_end = 0;
  while (peek().kind != Token::Kind::End) {
    if (keyword("assume")) {
      notes_ = &file_notes;
      out.assumptions.push_back(assumption());
      previous_end = lex_.tokens[pos_ - 1].loc.line;
    } else if (keyword("property")) {
      Property p = property();
      if (auto [it, fresh] = defined.emplace(p.name, p.loc.line); !fresh)
        fail_at(p.loc, "property " + in_quotes(p.name) + " is already defined at line " + std::to_string(it->second));
      int end = lex_.tokens[pos_ - 1].loc.line;
      attach_expect(p, previous_end + 1, end);
      previous_end = end;
      out.properties.push_back(std::move(p));
    } else {
      fail_expected("'property' or 'assume'");
    }
  }
  for (const auto& e : lex_.expects)
    if (e.line > previous_end)
      fail_at({e.line, 1}, "'# expect:' comment after the last property (it must precede its property)");
  for (auto& p : out.properties) p.notes.insert(p.notes.begin(), file_notes.begin(), file_notes.end());
  return out;
}

// The `# expect:` comment between the previous property (or assumption) and
// the end of this one.
void Parser::attach_expect(Property& p, int first_line, int last_line) {
  for (const auto& e : lex_.expects) {
    if (e.line < first_line || e.line > last_line) continue;
    if (!is_verdict(e.verdict))
      fail_at({e.line, 1}, "expected a verdict (proved, falsified, reachable, unreachable, vacuous), found " +
                               in_quotes(e.verdict));
    if (!p.expect.empty())
      fail_at({e.line, 1}, "second '# expect:' comment for property " + in_quotes(p.name));
    p.expect = e.verdict;
  }
}

Assumption Parser::assumption() {
  Assumption a;
  expect_keyword("assume");
  a.loc = peek().loc;
  a.expr = bool_expression();
  return a;
}

std::string Parser::property_name() {
  if (peek().kind != Token::Kind::Identifier || is_reserved(peek().text)) fail_expected("a property name");
  std::string name = next().text;
  while (symbol(".") && (peek(1).kind == Token::Kind::Identifier || peek(1).kind == Token::Kind::Number ||
                         peek(1).kind == Token::Kind::Word)) {
    next();
    name += "." + next().text;
  }
  return name;
}

Property Parser::property() {
  Property p;
  expect_keyword("property");
  p.loc = peek().loc;
  p.name = property_name();
  if (peek().kind == Token::Kind::String) p.description = next().text;
  expect_symbol("{");
  notes_ = &p.notes;
  bool have_statement = false;
  while (!symbol("}")) {
    if (keyword("assume")) {
      p.assumptions.push_back(assumption());
      continue;
    }
    if (have_statement) fail_expected("'assume' or '}'");
    if (keyword("always") || keyword("never") || keyword("reachable")) {
      std::string k = next().text;
      p.kind = k == "always" ? PropertyKind::Invariant : k == "never" ? PropertyKind::Never : PropertyKind::Reachable;
      p.body = bool_expression();
    } else if (keyword("whenever")) {
      next();
      p.kind = PropertyKind::Response;
      p.trigger = bool_expression();
      expect_keyword("then");
      p.response = bool_expression();
      expect_keyword("within");
      p.within_cycles = duration();
    } else {
      fail_expected("'always', 'never', 'reachable', 'whenever' or 'assume'");
    }
    have_statement = true;
  }
  if (!have_statement) fail_expected("'always', 'never', 'reachable', 'whenever' or 'assume'");
  expect_symbol("}");
  notes_ = nullptr;
  return p;
}

// Milliseconds per unit of a duration; 0 for "cycles", which counts cycles.
std::uint64_t unit_ms(const std::string& unit) {
  if (unit == "ms") return 1;
  if (unit == "s") return 1000;
  if (unit == "min") return 60'000;
  if (unit == "h") return 3'600'000;
  return 0;
}

int Parser::duration() {
  SourceLoc loc = peek().loc;
  std::string number, unit;
  if (peek().kind == Token::Kind::Number) {
    number = next().text;
    if (peek().kind != Token::Kind::Identifier) fail_expected("a unit (ms, s, min, h or cycles)");
    unit = next().text;
  } else if (peek().kind == Token::Kind::Word) {
    const std::string& w = peek().text;
    std::size_t i = 0;
    while (i < w.size() && (std::isdigit(static_cast<unsigned char>(w[i])) || w[i] == '.')) ++i;
    number = w.substr(0, i);
    unit = w.substr(i);
    next();
  } else {
    fail_expected("a duration (e.g. 500 ms, 2 s, 10 min, 3 cycles)");
  }
  if (unit != "ms" && unit != "s" && unit != "min" && unit != "h" && unit != "cycle" && unit != "cycles")
    fail_at(loc, "expected a unit (ms, s, min, h or cycles), found " + in_quotes(unit));
  // Whole milliseconds in exact decimal arithmetic: "2.5 s" is 2500 ms,
  // "1.5 min" 90000 ms, "0.0001 s" is refused.
  std::size_t dot = number.find('.');
  std::string whole = number.substr(0, dot);
  std::string fraction = dot == std::string::npos ? "" : number.substr(dot + 1);
  while (!fraction.empty() && fraction.back() == '0') fraction.pop_back();
  if (number.find_first_of("eE-") != std::string::npos || whole.size() > 12 || fraction.size() > 9 ||
      whole + fraction == "")
    fail_at(loc, "expected a duration (e.g. 500 ms, 2 s, 10 min, 3 cycles), found " + in_quotes(number + " " + unit));
  const std::uint64_t scale = unit_ms(unit);
  unsigned __int128 digits = std::stoull(whole.empty() ? "0" : whole);
  unsigned __int128 ten = 1;
  for (char c : fraction) digits = digits * 10 + static_cast<unsigned>(c - '0'), ten *= 10;
  const unsigned __int128 scaled = digits * (scale ? scale : 1);
  if (scaled % ten != 0)
    fail_at(loc, scale ? "a duration must be a whole number of milliseconds"
                       : "a duration in " + unit + " must be a whole number");
  const unsigned __int128 value128 = scaled / ten;
  if (value128 > static_cast<unsigned __int128>(kMaxDurationCycles) * 4'294'967'295ULL)
    fail_at(loc, "duration of " + number + " " + unit + " is longer than the limit of " +
                     std::to_string(kMaxDurationCycles) + " cycles");
  const auto value = static_cast<std::uint64_t>(value128);
  std::uint64_t cycles = value;
  std::uint64_t cycle_ms = names_.matrix().cycle_ms;
  if (scale) {
    cycles = (value + cycle_ms - 1) / cycle_ms;  // docs/semantics.md T.2: D = ceil(ms / cycle_ms)
    if (value % cycle_ms != 0 && notes_)
      notes_->push_back("line " + std::to_string(loc.line) + ": " + number + " " + unit + " rounded up to " +
                        std::to_string(cycles) + (cycles == 1 ? " cycle" : " cycles") + " of " +
                        std::to_string(cycle_ms) + " ms (" + std::to_string(cycles * cycle_ms) +
                        " ms), as the runtime rounds timers");
  }
  if (cycles > kMaxDurationCycles)
    fail_at(loc, "duration of " + std::to_string(cycles) + " cycles is longer than the limit of " +
                     std::to_string(kMaxDurationCycles) + " cycles");
  return static_cast<int>(cycles);
}

PropertyFile parse_properties(std::string_view text, const model::Matrix& m, const std::string& file_name) {
  if (text.size() > formats::kMaxFileBytes)
    throw formats::LoadError({{file_name, "file larger than " + std::to_string(formats::kMaxFileBytes) + " bytes"}});
  // Text is UTF-8 (docs/properties.md): a file in another encoding is refused
  // at its first bad byte, never read as garbled names or descriptions.
  if (auto bad = formats::first_invalid_utf8(text)) {
    auto [line, byte_column] = formats::line_and_column(text, *bad);
    std::size_t column = 1;  // in characters, as every message of the language counts them
    for (std::size_t i = *bad - (byte_column - 1); i < *bad; ++i) column += (text[i] & 0xC0) != 0x80;
    throw formats::LoadError({{place(file_name.empty() ? "<properties>" : file_name,
                                     {static_cast<int>(line), static_cast<int>(column)}),
                               "this byte is not UTF-8; save the file as UTF-8"}});
  }
  PropertyFile f = Parser(text, m, file_name).parse_file();
  f.warnings = find_traps(f, m);
  return f;
}

void check_distinct_names(const std::vector<PropertyFile>& files) {
  struct First {
    std::string file, name;
    SourceLoc loc;
  };
  std::map<std::string, First> seen;  // lower-case name -> first definition
  for (const auto& f : files)
    for (const auto& p : f.properties) {
      std::string key = p.name;
      for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      auto [it, fresh] = seen.emplace(key, First{f.file_name, p.name, p.loc});
      if (fresh) continue;
      const First& first = it->second;
      const bool first_standard = first.loc.line == 0, this_standard = p.loc.line == 0;
      const std::string same = first.name == p.name ? "" : " (differs only in case: their counterexample files "
                                                           "would be one file on a case-insensitive file system)";
      if (first_standard || this_standard) {  // the place to fix is the user's file
        const std::string file = this_standard ? first.file : f.file_name;
        const SourceLoc loc = this_standard ? first.loc : p.loc;
        throw formats::LoadError({{place(file, loc), "property " + in_quotes(this_standard ? first.name : p.name) +
                                                         " is also the name of a standard property (--standard)" +
                                                         same + "; rename it: the standard set's names are fixed"}});
      }
      throw formats::LoadError({{place(f.file_name, p.loc),
                                 "property " + in_quotes(p.name) + " is already defined at " +
                                     place(first.file, first.loc) + same +
                                     "; every property of one run needs its own name (the reports and the "
                                     "counterexample files are named after it)"}});
    }
}

PropertyFile load_properties(const std::filesystem::path& file, const model::Matrix& m) {
  return parse_properties(formats::read_text_file(file), m, file.string());
}

}  // namespace cemv::properties
