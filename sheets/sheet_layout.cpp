// cemv-sheet-layout/1: reading and writing (docs/csv.md "The layout description").
#include "sheets/sheet_layout.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include <nlohmann/json.hpp>

#include "formats/diagnostics.hpp"
#include "formats/located_issues.hpp"
#include "model/text.hpp"

namespace cemv::formats {

namespace {

using nlohmann::ordered_json;

constexpr std::size_t kMaxMarkLength = 16;
constexpr std::size_t kMaxText = 1024;
constexpr int kMaxPosition = 16384;  // the XLSX column maximum; rows beyond a grid are no header
constexpr JsonLimits kLayoutLimits{256, "layout", 4};

struct AttributeName {
  SheetAttribute attribute;
  const char* name;
  bool cause, effect;  // which elements have it
};
constexpr AttributeName kAttributes[] = {
    {SheetAttribute::Id, "id", true, true},
    {SheetAttribute::Description, "description", true, true},
    {SheetAttribute::Tag, "tag", true, true},
    {SheetAttribute::Setpoint, "setpoint", true, false},
    {SheetAttribute::Unit, "unit", true, false},
    {SheetAttribute::Voting, "voting", true, false},
    {SheetAttribute::Sil, "sil", true, true},
    {SheetAttribute::TripSide, "trip_side", true, false},
    {SheetAttribute::Action, "action", false, true},
    {SheetAttribute::Note, "note", true, true},
};

struct TypeName {
  std::optional<model::IntersectionType> type;
  const char* name;
};
const TypeName kTypes[] = {{model::IntersectionType::N, "N"}, {model::IntersectionType::S, "S"},
                           {model::IntersectionType::V, "V"}, {model::IntersectionType::R, "R"},
                           {model::IntersectionType::X, "X"}, {model::IntersectionType::Note, "*"},
                           {std::nullopt, "none"}};

std::string json_type(const ordered_json& j) {
  if (j.is_string()) return "a string";
  if (j.is_number()) return "a number";
  if (j.is_boolean()) return "a boolean";
  if (j.is_array()) return "an array";
  if (j.is_object()) return "an object";
  return "null";
}

// "A" -> 1, "AB" -> 28; 0 when the text is no column name.
int letters_to_column(const std::string& s) {
  if (s.empty() || s.size() > 3) return 0;
  int c = 0;
  for (char ch : s) {
    if (ch >= 'a' && ch <= 'z') ch = static_cast<char>(ch - 'a' + 'A');
    if (ch < 'A' || ch > 'Z') return 0;
    c = c * 26 + (ch - 'A' + 1);
  }
  return c;
}

// A footnote key as grids write them: `*`, `**`, `(1)`.
bool footnote_key(const std::string& k) {
  if (!k.empty() && k.find_first_not_of('*') == std::string::npos) return k.size() <= 3;
  if (k.size() < 3 || k.front() != '(' || k.back() != ')') return false;
  return k.find_first_not_of("0123456789", 1) == k.size() - 1 && k.size() <= 8;
}

class LayoutParser {
 public:
  SheetLayout parse(const ordered_json& root) {
    SheetLayout out;
    if (!root.is_object()) {
      error("", "a layout description is a JSON object, not " + json_type(root));
      return out;
    }
    static const std::set<std::string> keys{"format", "sheet", "orientation", "causes", "effects", "marks",
                                            "footnotes", "remarks_sheet", "trip_sides", "deleted"};
    for (const auto& [key, value] : root.items())
      if (!keys.count(key)) error(key, "unknown key; a layout has " + list(keys));
    if (!root.contains("format") || root["format"] != kSheetLayoutFormat)
      error("format", std::string("expected \"") + kSheetLayoutFormat + "\"" +
                          (root.contains("format") ? ", got " + root["format"].dump() : ""));
    if (root.contains("sheet")) out.sheet = text(root["sheet"], "sheet");
    if (root.contains("orientation")) out.orientation = orientation(root["orientation"]);
    if (root.contains("causes")) out.causes = places(root["causes"], "causes", out.orientation, true);
    if (root.contains("effects")) out.effects = places(root["effects"], "effects", out.orientation, false);
    if (root.contains("marks")) out.marks = marks(root["marks"]);
    if (root.contains("footnotes")) out.footnotes = footnotes(root["footnotes"]);
    if (root.contains("remarks_sheet")) out.remarks_sheet = text(root["remarks_sheet"], "remarks_sheet");
    if (root.contains("trip_sides")) out.trip_sides = trip_sides(root["trip_sides"]);
    if (root.contains("deleted")) out.deleted = deleted(root["deleted"]);
    return out;
  }

  std::vector<LoadIssue> issues;

 private:
  void error(const std::string& path, std::string what) { issues.push_back({path, std::move(what)}); }

  static std::string list(const std::set<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
  }

  std::string text(const ordered_json& j, const std::string& path) {
    if (!j.is_string() || j.get<std::string>().empty() || j.get<std::string>().size() > kMaxText) {
      error(path, "must be a non-empty string of at most " + std::to_string(kMaxText) + " bytes, not " +
                      (j.is_string() ? model::in_quotes(j.get<std::string>()) : json_type(j)));
      return "";
    }
    return j.get<std::string>();
  }

  CsvOrientation orientation(const ordered_json& j) {
    for (auto o : {CsvOrientation::Auto, CsvOrientation::CausesAsRows, CsvOrientation::EffectsAsRows})
      if (j == to_string(o)) return o;
    error("orientation", "must be \"auto\", \"causes-as-rows\" or \"effects-as-rows\", not " + j.dump());
    return CsvOrientation::Auto;
  }

  // Columns for the elements on the rows (a letter or a number), rows for
  // those on the columns (a number).
  int position(const ordered_json& j, const std::string& path, bool columns) {
    int p = 0;
    if (j.is_number_integer()) p = j.get<int>();
    else if (columns && j.is_string()) p = letters_to_column(j.get<std::string>());
    if (p < 1 || p > kMaxPosition) {
      error(path, std::string("must be ") + (columns ? "a column (\"A\", or a number 1-16384)" : "a row number 1-16384") +
                      ", not " + j.dump());
      return 0;
    }
    return p;
  }

  std::vector<AttributePlace> places(const ordered_json& j, const std::string& path, CsvOrientation o, bool cause) {
    std::vector<AttributePlace> out;
    if (!j.is_object()) {
      error(path, "must be an object of attributes and their places, not " + json_type(j));
      return out;
    }
    if (o == CsvOrientation::Auto)
      error(path, "the places of the attributes need the orientation (\"causes-as-rows\" or \"effects-as-rows\")");
    // Without an orientation (an error above), letters are taken too.
    const bool columns = o == CsvOrientation::Auto || (o == CsvOrientation::CausesAsRows) == cause;
    std::map<int, SheetAttribute> used;  // an id may share its place (a tag or a description that is the id)
    for (const auto& [key, value] : j.items()) {
      const std::string at = member_path(path, key);
      const AttributeName* a = nullptr;
      for (const auto& n : kAttributes)
        if (key == n.name && (cause ? n.cause : n.effect)) a = &n;
      if (!a) {
        error(at, std::string("not an attribute of ") + (cause ? "a cause" : "an effect") + "; " +
                      (cause ? "id, description, tag, setpoint, unit, voting, sil, trip_side, note"
                             : "id, description, tag, sil, action, note"));
        continue;
      }
      std::vector<ordered_json> values;
      if (a->attribute == SheetAttribute::Note && value.is_array()) values.assign(value.begin(), value.end());
      else values.push_back(value);
      for (const auto& v : values) {
        const int p = position(v, at, columns);
        if (!p) continue;
        auto [other, fresh] = used.emplace(p, a->attribute);
        if (!fresh && other->second != SheetAttribute::Id && a->attribute != SheetAttribute::Id)
          error(at, "the same place as another attribute");
        if (!fresh && a->attribute != SheetAttribute::Id) other->second = a->attribute;
        out.push_back({a->attribute, p});
      }
    }
    return out;
  }

  std::map<std::string, MarkMeaning> marks(const ordered_json& j) {
    std::map<std::string, MarkMeaning> out;
    if (!j.is_object()) {
      error("marks", "must be an object of marks and their meanings, not " + json_type(j));
      return out;
    }
    for (const auto& [mark, value] : j.items()) {
      const std::string at = member_path("marks", mark);
      if (mark.empty() || mark.size() > kMaxMarkLength || mark.find_first_of(" \t") == 0)
        error(at, "a mark has 1-" + std::to_string(kMaxMarkLength) + " characters");
      if (!value.is_object() || !value.contains("type")) {
        error(at, "must be an object {\"type\": \"N\"|\"S\"|\"V\"|\"R\"|\"X\"|\"*\"|\"none\"[, \"footnote\": \"*\"]}");
        continue;
      }
      MarkMeaning m;
      bool known = false;
      for (const auto& t : kTypes)
        if (value["type"] == t.name) m.type = t.type, known = true;
      if (!known) error(member_path(at, "type"), "must be N, S, V, R, X, * or none, not " + value["type"].dump());
      for (const auto& [k, v] : value.items())
        if (k != "type" && k != "footnote") error(member_path(at, k), "unknown key; a mark has type and footnote");
      if (value.contains("footnote")) {
        m.footnote = text(value["footnote"], member_path(at, "footnote"));
        if (!m.footnote.empty() && !footnote_key(m.footnote))
          error(member_path(at, "footnote"), "must be a footnote key such as \"*\", \"**\" or \"(1)\"");
        if (!m.type && !m.footnote.empty()) error(member_path(at, "footnote"), "a mark of no intersection has no footnote");
      }
      out[mark] = m;
    }
    return out;
  }

  std::map<std::string, std::string> footnotes(const ordered_json& j) {
    std::map<std::string, std::string> out;
    if (!j.is_object()) {
      error("footnotes", "must be an object of footnote keys and texts, not " + json_type(j));
      return out;
    }
    for (const auto& [key, value] : j.items()) {
      const std::string at = member_path("footnotes", key);
      if (!footnote_key(key)) error(at, "not a footnote key such as \"*\", \"**\" or \"(1)\"");
      out[key] = text(value, at);
    }
    return out;
  }

  std::map<std::string, model::LimitType> trip_sides(const ordered_json& j) {
    std::map<std::string, model::LimitType> out;
    if (!j.is_object()) {
      error("trip_sides", "must be an object of cause sheet ids and \"high\" or \"low\", not " + json_type(j));
      return out;
    }
    for (const auto& [id, value] : j.items()) {
      if (value == "high") out[id] = model::LimitType::High;
      else if (value == "low") out[id] = model::LimitType::Low;
      else error(member_path("trip_sides", id), "must be \"high\" or \"low\", not " + value.dump());
    }
    return out;
  }

  DeletedRule deleted(const ordered_json& j) {
    DeletedRule out;
    if (!j.is_object()) {
      error("deleted", "must be an object {\"strikethrough\": true|false, \"words\": [...]}, not " + json_type(j));
      return out;
    }
    for (const auto& [k, v] : j.items()) {
      const std::string at = member_path("deleted", k);
      if (k == "strikethrough") {
        if (!v.is_boolean()) error(at, "must be true or false, not " + v.dump());
        else out.strikethrough = v.get<bool>();
      } else if (k == "words") {
        out.words.clear();
        if (!v.is_array()) error(at, "must be an array of words, not " + json_type(v));
        else
          for (std::size_t i = 0; i < v.size(); ++i) out.words.push_back(text(v[i], element_path(at, i)));
      } else {
        error(at, "unknown key; deleted has strikethrough and words");
      }
    }
    return out;
  }
};

ordered_json places_json(const std::vector<AttributePlace>& places, bool columns) {
  ordered_json out = ordered_json::object();
  for (const auto& a : kAttributes)
    for (const auto& p : places) {
      if (p.attribute != a.attribute) continue;
      ordered_json v = columns ? ordered_json(column_letters(p.position)) : ordered_json(p.position);
      if (a.attribute != SheetAttribute::Note) out[a.name] = v;
      else out[a.name].push_back(v);
    }
  return out;
}

}  // namespace

const char* to_string(SheetAttribute attribute) {
  for (const auto& a : kAttributes)
    if (a.attribute == attribute) return a.name;
  return "?";
}

const char* to_string(CsvOrientation o) {
  switch (o) {
    case CsvOrientation::CausesAsRows: return "causes-as-rows";
    case CsvOrientation::EffectsAsRows: return "effects-as-rows";
    default: return "auto";
  }
}

std::string column_letters(int column) {
  std::string letters;
  for (int c = column; c > 0; c = (c - 1) / 26) letters.insert(letters.begin(), static_cast<char>('A' + (c - 1) % 26));
  return letters;
}

SheetLayout parse_sheet_layout(std::string_view json_text, const std::string& source_name) {
  if (json_text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw LoadError({{source_name, "file is empty (expected a cemv-sheet-layout/1 JSON object)", source_name}});
  std::vector<LoadIssue> issues;
  auto parsed = parse_guarded_json(json_text, source_name, issues, kLayoutLimits);
  if (!parsed || !issues.empty()) throw LoadError(std::move(issues));
  LayoutParser parser;
  SheetLayout layout = parser.parse(*parsed);
  if (!parser.issues.empty()) throw_in_text_order(json_text, source_name, std::move(parser.issues));
  return layout;
}

std::string sheet_layout_json(const SheetLayout& layout, bool one_line) {
  ordered_json j;
  j["format"] = kSheetLayoutFormat;
  if (!layout.sheet.empty()) j["sheet"] = layout.sheet;
  j["orientation"] = to_string(layout.orientation);
  const bool causes_as_rows = layout.orientation != CsvOrientation::EffectsAsRows;
  if (!layout.causes.empty()) j["causes"] = places_json(layout.causes, causes_as_rows);
  if (!layout.effects.empty()) j["effects"] = places_json(layout.effects, !causes_as_rows);
  if (!layout.marks.empty()) {
    ordered_json& marks = j["marks"];
    for (const auto& [mark, meaning] : layout.marks) {
      ordered_json m;
      for (const auto& t : kTypes)
        if (t.type == meaning.type) m["type"] = t.name;
      if (!meaning.footnote.empty()) m["footnote"] = meaning.footnote;
      marks[mark] = m;
    }
  }
  if (!layout.footnotes.empty()) j["footnotes"] = layout.footnotes;
  if (!layout.remarks_sheet.empty()) j["remarks_sheet"] = layout.remarks_sheet;
  if (!layout.trip_sides.empty()) {
    ordered_json& sides = j["trip_sides"];
    for (const auto& [id, side] : layout.trip_sides) sides[id] = side == model::LimitType::High ? "high" : "low";
  }
  j["deleted"] = {{"strikethrough", layout.deleted.strikethrough}, {"words", layout.deleted.words}};
  // Texts come from sheets: bytes that are no UTF-8 are written as U+FFFD, never thrown on.
  const auto replace = nlohmann::ordered_json::error_handler_t::replace;
  return one_line ? j.dump(-1, ' ', false, replace) : j.dump(2, ' ', false, replace) + "\n";
}

}  // namespace cemv::formats
