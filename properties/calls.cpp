// Operators written as calls (past-time operators, quality, commands,
// aggregates) and references to matrix elements (docs/properties.md).
#include <algorithm>
#include <charconv>

#include "properties/parser_impl.hpp"

namespace cemv::properties {

namespace {

using Kind = Expr::Kind;

// The resolved value, or the resolver's message reported through `fail` (which throws).
template <class T, class Fail>
T value_or_fail(std::variant<T, std::string> v, Fail&& fail) {
  if (auto* msg = std::get_if<std::string>(&v)) fail(*msg);
  return std::get<T>(std::move(v));
}

std::vector<std::string> allowed_keys(model::CommandOp op) {
  using Op = model::CommandOp;
  switch (op) {
    case Op::AckCause: return {"cause"};
    case Op::ResetEffect: case Op::OverrideEffect: case Op::StopOverride: return {"effect"};
    case Op::SoftBypassCause: return {"cause", "on"};
    case Op::SoftBypassTag: return {"cause", "tag", "on"};
    case Op::SoftBypassEffect: return {"effect", "on"};
    case Op::SimulateTag: case Op::StopSimulation: return {"tag"};
    case Op::ClearFirstOut: return {"group"};
    case Op::ClearAlarms: return {"cause", "effect"};
  }
  return {};
}

std::string join(const std::vector<std::string>& words, const char* last) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i)
    out += (i == 0 ? "" : i + 1 == words.size() ? std::string(" ") + last + " " : ", ") + words[i];
  return out;
}

}  // namespace

Expr Parser::call(const Token& name) {
  const std::string& f = name.text;
  if (f == "issued") return issued();
  if (f == "count" || f == "any" || f == "all") return aggregate(name);
  expect_symbol("(");
  if (f == "bad" || f == "good") {
    SourceLoc loc = peek().loc;
    TagRef t = tag_operand();
    expect_symbol(")");
    if (!t.input)
      fail_at(loc, "expected an input tag, found " + in_quotes(t.name) + " (only input tags have a quality)");
    Expr bad = Expr::input_bad(*t.input);
    bad.loc = loc;
    return f == "bad" ? bad : Expr::unary(Kind::Not, std::move(bad));
  }
  Expr a = bool_expression();
  if (f == "prev" || f == "rose" || f == "fell") {
    expect_symbol(")");
    return Expr::unary(f == "prev" ? Kind::Prev : f == "rose" ? Kind::Rose : Kind::Fell, std::move(a));
  }
  expect_symbol(",");
  if (f == "since") {
    Expr b = bool_expression();
    expect_symbol(")");
    return Expr::binary(Kind::Since, std::move(a), std::move(b));
  }
  int cycles = duration();  // held / within
  expect_symbol(")");
  return Expr::unary(f == "held" ? Kind::Held : Kind::Within, std::move(a), cycles);
}

// issued(OP, key = value, ...): a command matching the pattern is issued in this cycle.
Expr Parser::issued() {
  expect_symbol("(");
  if (peek().kind != Token::Kind::Identifier) fail_expected("a command name (e.g. override_effect)");
  const Token& op_token = next();
  auto op = model::command_op_from_string(op_token.text);
  std::vector<std::string> ops;
  for (int i = 0; i <= static_cast<int>(model::CommandOp::ClearAlarms); ++i)
    ops.push_back(model::to_string(static_cast<model::CommandOp>(i)));
  if (!op) fail_at(op_token.loc, "unknown command " + in_quotes(op_token.text) + did_you_mean(op_token.text, ops));
  CommandPattern p;
  p.op = *op;
  std::vector<std::string> allowed = allowed_keys(*op);
  std::vector<std::string> given;
  auto fail = [&](SourceLoc loc) { return [this, loc](const std::string& m) { fail_at(loc, m); }; };
  while (accept_symbol(",")) {
    if (peek().kind != Token::Kind::Identifier) fail_expected("an argument name (" + join(allowed, "or") + ")");
    const Token& key = next();
    if (std::find(allowed.begin(), allowed.end(), key.text) == allowed.end())
      fail_at(key.loc, "expected an argument of " + op_token.text + " (" + join(allowed, "or") + "), found " +
                           in_quotes(key.text));
    if (std::find(given.begin(), given.end(), key.text) != given.end())
      fail_at(key.loc, "argument " + in_quotes(key.text) + " given twice");
    given.push_back(key.text);
    expect_symbol("=");
    const Token& v = peek();
    SourceLoc loc = v.loc;
    const Element* var = v.kind == Token::Kind::Identifier ? variable(v.text) : nullptr;
    if (key.text == "cause" || key.text == "effect") {
      bool cause = key.text == "cause";
      int id = 0;
      if (var) {
        if (var->kind != (cause ? Element::Kind::Cause : Element::Kind::Effect))
          fail_at(loc, "expected " + std::string(cause ? "a cause" : "an effect") + ", found " + in_quotes(v.text));
        id = var->id;
        next();
      } else if (v.kind == Token::Kind::Number || v.kind == Token::Kind::Identifier || v.kind == Token::Kind::String) {
        bool is_number = v.kind == Token::Kind::Number;
        next();
        id = value_or_fail(cause ? names_.cause(v.text, is_number) : names_.effect(v.text, is_number), fail(loc));
      } else {
        fail_expected(cause ? "a cause id or name" : "an effect id or name");
      }
      (cause ? p.cause : p.effect) = id;
    } else if (key.text == "on") {
      if (!keyword("true") && !keyword("false")) fail_expected("true or false");
      p.on = next().text == "true";
    } else if (key.text == "group") {
      int g = 0;
      auto [ptr, ec] = std::from_chars(v.text.data(), v.text.data() + v.text.size(), g);
      if (v.kind != Token::Kind::Number || ec != std::errc() || ptr != v.text.data() + v.text.size() || g < 1 ||
          g > model::kMaxFirstOutGroup)
        fail_expected("a first-out group (1-15)");
      next();
      p.group = g;
    } else if (*op == model::CommandOp::SoftBypassTag) {  // tag = index among the cause's tags
      int k = 0;
      auto [ptr, ec] = std::from_chars(v.text.data(), v.text.data() + v.text.size(), k);
      if (v.kind != Token::Kind::Number || ec != std::errc() || ptr != v.text.data() + v.text.size() || k < 1 ||
          k > model::kMaxCauseTags)
        fail_expected("a tag index (1-3)");
      next();
      p.tag = k;
    } else {  // simulate_tag / stop_simulation: tag = a tag name
      TagRef t = tag_operand();
      p.tag_name = t.name;
    }
  }
  expect_symbol(")");
  if (p.tag && p.cause) {
    const model::Cause* c = names_.matrix().find_cause(*p.cause);
    if (*p.tag > static_cast<int>(c->tags.size()))
      fail_at(op_token.loc, "cause " + std::to_string(*p.cause) + " has no tag " + std::to_string(*p.tag));
  }
  return Expr::issued(std::move(p));
}

// count(...), any(...), all(...) over a list of expressions or a set:
// `any(c in sif[1].causes: c.active)`. Sets are expanded here, so the AST only
// holds and/or/count over the members.
Expr Parser::aggregate(const Token& name) {
  expect_symbol("(");
  std::vector<Expr> items;
  if (peek().kind == Token::Kind::Identifier && !is_reserved(peek().text) && keyword("in", 1)) {
    std::string var = next().text;
    next();  // in
    SourceLoc set_loc = peek().loc;
    std::vector<Element> set = element_set();
    expect_symbol(":");
    if (set.empty()) fail_at(set_loc, "the set is empty (an aggregate needs at least one element)");
    items = expand(set, var);
  } else {
    items.push_back(bool_expression());
    while (accept_symbol(",")) items.push_back(bool_expression());
  }
  expect_symbol(")");
  Kind k = name.text == "count" ? Kind::Count : name.text == "any" ? Kind::Or : Kind::And;
  return Expr::nary(k, std::move(items));
}

// Parses the body once per element, with the variable bound to it.
// Nested aggregates multiply: a guard keeps a hostile file from expanding forever.
std::vector<Expr> Parser::expand(const std::vector<Element>& set, const std::string& var) {
  constexpr std::size_t kMaxExpansions = 100'000;
  std::vector<Expr> out;
  std::size_t body = pos_;
  for (const auto& e : set) {
    pos_ = body;
    if (++expanded_ > kMaxExpansions)
      fail_at(peek().loc, "aggregates expand to more than " + std::to_string(kMaxExpansions) + " terms");
    scope_.emplace_back(var, e);
    out.push_back(bool_expression());
    scope_.pop_back();
  }
  return out;
}

// causes | effects | sif[N].causes | sif[N].effects | ELEMENT.causes | ELEMENT.effects | ELEMENT.tags
std::vector<Element> Parser::element_set() {
  SourceLoc loc = peek().loc;
  if (keyword("causes")) return next(), names_.all_causes();
  if (keyword("effects")) return next(), names_.all_effects();
  if (keyword("sif")) {
    next();
    expect_symbol("[");
    const Token& g = peek();
    int group = 0;
    auto [ptr, ec] = std::from_chars(g.text.data(), g.text.data() + g.text.size(), group);
    if (g.kind != Token::Kind::Number || ec != std::errc() || ptr != g.text.data() + g.text.size())
      fail_expected("a SIF group number");
    next();
    expect_symbol("]");
    expect_symbol(".");
    if (keyword("causes") || keyword("effects")) {
      bool causes = next().text == "causes";
      return value_or_fail(causes ? names_.sif_causes(group) : names_.sif_effects(group),
                           [&](const std::string& m) { fail_at(loc, m); });
    }
    fail_expected("'causes' or 'effects'");
  }
  if (keyword("cause") || keyword("effect") ||
      (peek().kind == Token::Kind::Identifier && variable(peek().text) &&
       variable(peek().text)->kind != Element::Kind::Tag)) {
    Element e = element_ref();
    expect_symbol(".");
    bool cause = e.kind == Element::Kind::Cause;
    if (keyword("tags")) return next(), cause ? names_.tags_of_cause(e.id) : names_.tags_of_effect(e.id);
    if (cause && keyword("effects")) return next(), names_.effects_of_cause(e.id);
    if (!cause && keyword("causes")) return next(), names_.causes_of_effect(e.id);
    fail_expected(cause ? "'effects' or 'tags'" : "'causes' or 'tags'");
  }
  fail_expected("a set (causes, effects, sif[N].causes, sif[N].effects, cause[X].effects, cause[X].tags, "
                "effect[X].causes, effect[X].tags)");
}

// cause[ID or NAME], effect[ID or NAME], or a variable bound to a cause or effect.
Element Parser::element_ref() {
  const Token& head = next();
  if (const Element* v = variable(head.text)) return *v;
  bool cause = head.text == "cause";
  expect_symbol("[");
  const Token& x = peek();
  if (x.kind != Token::Kind::Number && x.kind != Token::Kind::Identifier && x.kind != Token::Kind::String)
    fail_expected(cause ? "a cause id or name" : "an effect id or name");
  next();
  bool is_number = x.kind == Token::Kind::Number;
  int id = value_or_fail(cause ? names_.cause(x.text, is_number) : names_.effect(x.text, is_number),
                         [&](const std::string& m) { fail_at(x.loc, m); });
  expect_symbol("]");
  return {cause ? Element::Kind::Cause : Element::Kind::Effect, id, {}};
}

// .FIELD of a cause or effect, or .tag[k] of an effect.
Expr Parser::element_member(const Element& e, SourceLoc loc) {
  expect_symbol(".");
  if (peek().kind != Token::Kind::Identifier) fail_expected("a field name");
  const Token& field = next();
  auto fail = [&](const std::string& m) { fail_at(field.loc, m); };
  if (e.kind == Element::Kind::Cause) {
    Expr x = Expr::of_observable(value_or_fail(names_.cause_field(e.id, field.text), fail));
    x.loc = loc;
    return x;
  }
  if (field.text == "tag" && symbol("[")) {
    next();
    const Token& k = peek();
    long index = 0;
    auto [ptr, ec] = std::from_chars(k.text.data(), k.text.data() + k.text.size(), index);
    if (k.kind != Token::Kind::Number || ec != std::errc() || ptr != k.text.data() + k.text.size())
      fail_expected("a tag index");
    next();
    expect_symbol("]");
    Expr x = Expr::of_observable(value_or_fail(names_.effect_tag(e.id, index), [&](const std::string& m) {
      fail_at(k.loc, m);
    }));
    x.loc = loc;
    return x;
  }
  Expr x = Expr::of_observable(value_or_fail(names_.effect_field(e.id, field.text), fail));
  x.loc = loc;
  return x;
}

// A tag: its name (identifier or "quoted string") or a variable bound to a tag.
TagRef Parser::tag_operand() {
  const Token& t = peek();
  if (t.kind == Token::Kind::Identifier) {
    if (const Element* v = variable(t.text)) {
      if (v->kind != Element::Kind::Tag) fail_expected("a tag");
      next();
      return v->tag;
    }
    if (is_reserved(t.text)) fail_expected("a tag name");
  } else if (t.kind != Token::Kind::String) {
    fail_expected("a tag name");
  }
  next();
  return value_or_fail(names_.tag(t.text), [&](const std::string& m) { fail_at(t.loc, m); });
}

Expr Parser::tag_value(const TagRef& t, SourceLoc loc) {
  Expr e = t.input ? Expr::input_value(*t.input, names_.inputs().tags()[*t.input].kind) : Expr::of_observable(*t.value);
  e.loc = loc;
  return e;
}

}  // namespace cemv::properties
