// What a header of a C&E grid says it holds (docs/csv.md "Attributes"): the
// common spellings of id, description, tag, setpoint, unit, voting, SIL, trip
// side, action and remarks, and the words that name causes or effects.
#include <map>
#include <optional>

#include "sheets/csv_grid.hpp"
#include "formats/csv_text.hpp"

namespace cemv::formats::grid {

using namespace csv_text;

namespace {

std::vector<std::string> lower_words(const std::string& text) {
  std::vector<std::string> out;
  std::string w;
  for (char c : text) {
    const bool digit = c >= '0' && c <= '9', letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    if (digit || letter) w += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    else if (!w.empty()) out.push_back(std::move(w)), w.clear();
  }
  if (!w.empty()) out.push_back(std::move(w));
  return out;
}

ElementKind kind_word(const std::string& w) {
  static const std::map<std::string, ElementKind> words{
      {"cause", ElementKind::Cause},       {"causes", ElementKind::Cause},      {"initiator", ElementKind::Cause},
      {"initiators", ElementKind::Cause},  {"input", ElementKind::Cause},       {"inputs", ElementKind::Cause},
      {"detection", ElementKind::Cause},   {"effect", ElementKind::Effect},     {"effects", ElementKind::Effect},
      {"output", ElementKind::Effect},     {"outputs", ElementKind::Effect},    {"final", ElementKind::Effect},
      {"element", ElementKind::Effect},    {"elements", ElementKind::Effect},   {"actuation", ElementKind::Effect},
      {"actuator", ElementKind::Effect},   {"of", ElementKind::Unknown}};
  auto it = words.find(w);
  return it == words.end() ? ElementKind::Unknown : it->second;
}

bool is_kind_word(const std::string& w) { return w == "of" || kind_word(w) != ElementKind::Unknown; }

// The spellings of each attribute (docs/csv.md "Attributes"), as lower-case
// words joined by blanks, kind words (cause, effect, output, ...) removed.
const std::map<std::string, SheetAttribute>& spellings() {
  static const std::map<std::string, SheetAttribute> table = [] {
    std::map<std::string, SheetAttribute> t;
    auto add = [&](SheetAttribute a, std::initializer_list<const char*> names) {
      for (const char* n : names) t[n] = a;
    };
    add(SheetAttribute::Id, {"id", "no", "nr", "num", "number", "item", "item no", "item nr", "item number", "ref",
                             "ref no", "reference", "line no", "pos", "position", "sr no", "s no", "serial no"});
    add(SheetAttribute::Description, {"description", "desc", "descr", "service", "service description",
                                      "narrative"});
    add(SheetAttribute::Tag, {"instrument", "instrument no", "instrument number", "loop", "loop no",
                              "equipment no"});
    add(SheetAttribute::Setpoint, {"setpoint", "set point", "set pt", "sp", "trip setpoint", "trip set point",
                                   "trip point", "trip value", "trip setting", "trip level", "trip limit",
                                   "limit", "setting", "alarm setpoint", "alarm setting", "alarm limit"});
    add(SheetAttribute::Unit, {"unit", "units", "eu", "eng unit", "eng units", "engineering unit",
                               "engineering units", "uom", "unit of measure"});
    add(SheetAttribute::Voting, {"voting", "vote", "votes", "voting logic", "logic", "architecture", "moon",
                                 "xooy", "redundancy", "voting arrangement"});
    add(SheetAttribute::Sil, {"sil", "sil level", "sil rating", "sil class", "required sil", "sil req",
                              "sil requirement", "safety integrity level"});
    add(SheetAttribute::TripSide, {"trip direction", "trip side", "direction", "limit type", "high low", "h l",
                                   "hi lo", "trip type", "alarm type"});
    add(SheetAttribute::Action, {"action", "actions", "final action", "operation", "command", "safe state"});
    add(SheetAttribute::Note, {"remark", "remarks", "note", "notes", "comment", "comments"});
    return t;
  }();
  return table;
}

}  // namespace

std::optional<HeaderMeaning> attribute_of_header(const std::string& text) {
  const std::string_view t = trim(text);
  if (t == "#") return HeaderMeaning{SheetAttribute::Id, ElementKind::Unknown};
  HeaderMeaning m;
  std::string phrase;
  bool tag = false;
  for (const auto& w : lower_words(std::string(t))) {
    if (is_kind_word(w)) {
      const ElementKind k = kind_word(w);
      if (k != ElementKind::Unknown) m.kind = m.kind == ElementKind::Unknown || m.kind == k ? k : ElementKind::Unknown;
      continue;
    }
    tag = tag || w == "tag" || w == "tags";
    join_to(phrase, " ", w);
  }
  if (phrase.empty()) return std::nullopt;
  if (tag) {
    m.attribute = SheetAttribute::Tag;
    return m;
  }
  const auto it = spellings().find(phrase);
  if (it == spellings().end()) return std::nullopt;
  m.attribute = it->second;
  return m;
}

}  // namespace cemv::formats::grid
