// Reading a C&E grid (docs/csv.md "The grid layout"): the elements of both
// axes, their numbers and names, one intersection per marked cell, then the
// matrix, the summary and the layout it was read with. The sheet is imported
// as it is: its defects become warnings with line and column, what cannot be
// read right is refused with every cell named, and no safety parameter that
// the grid does not state is invented.
#include <algorithm>
#include <map>
#include <regex>
#include <set>
#include <utility>

#include "sheets/csv_grid.hpp"
#include "formats/csv_text.hpp"
#include "formats/matrix_json.hpp"
#include "model/names.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats::grid {

using namespace csv_text;
using namespace cemv::model;

namespace {

constexpr std::size_t kMaxMatrixNameLength = 16;  // 6.1.2
constexpr std::size_t kMaxTitleLength = 60;       // 6.2.1

bool cause_only(SheetAttribute a) {
  return a == SheetAttribute::Setpoint || a == SheetAttribute::Unit || a == SheetAttribute::Voting ||
         a == SheetAttribute::TripSide;
}

// What the summary says a slot was read as ("read as the effect tags").
std::string read_as(SheetAttribute a, const std::string& kind) {
  switch (a) {
    case SheetAttribute::Tag: return "read as the " + kind + " tags";
    case SheetAttribute::Setpoint: return "read as the " + kind + " setpoints";
    case SheetAttribute::Unit: return "read as the units of the setpoints";
    case SheetAttribute::Voting: return "read as the " + kind + " voting";
    case SheetAttribute::Sil: return "read as the " + kind + " SIL";
    case SheetAttribute::TripSide: return "read as the trip sides of the setpoints";
    case SheetAttribute::Id: return "read as the " + kind + " ids";
    case SheetAttribute::Description: return "read as the " + kind + " descriptions";
    default: return "kept in the " + kind + " notes";
  }
}

std::string plural(std::size_t n, const std::string& word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

class GridImporter {
 public:
  GridImporter(const Sheet& sheet, const Shape& shape, OrientationDecision orientation, std::string source,
               std::string name, const SheetLayout& layout,
               const std::map<std::string, model::LimitType>& parameter_trip_sides)
      : sheet_(sheet), shape_(shape), orientation_(std::move(orientation)), source_(std::move(source)),
        name_(std::move(name)), layout_(layout), parameter_trip_sides_(parameter_trip_sides), warnings_(source_),
        errors_(source_) {}

  CsvImportResult run() {
    if (orientation_.disagreement) warnings_.add(sheet_.rows[shape_.id_row].line, *orientation_.disagreement);
    check_slot_kinds();
    read_legend();
    const MarkTable marks(layout_.marks);
    columns_ = read_column_elements(sheet_, shape_, context(causes_are_rows() ? ElementKind::Effect : ElementKind::Cause));
    rows_ = read_row_elements(sheet_, shape_, context(causes_are_rows() ? ElementKind::Cause : ElementKind::Effect));
    number_elements(effects().elements, "effect", "E", kMaxEffects, warnings_);
    number_elements(causes().elements, "cause", "C", kMaxCauses, warnings_);
    intersections_ = read_intersections(sheet_, shape_, GridAxes{rows_, columns_, causes_are_rows()}, marks, legend_,
                                        warnings_, errors_);
    if (!errors_.empty()) {
      std::vector<LoadIssue> issues = errors_.in_file_order();
      if (issues.size() > kMaxIssues) issues.resize(kMaxIssues);
      throw LoadError(std::move(issues));
    }
    report_missing_override();

    CsvImportResult result;
    result.layout = CsvLayoutKind::Grid;
    result.orientation = orientation_.orientation;
    result.matrix = parse_matrix(to_canonical_json(build_matrix()), source_);
    result.summary = summary(result.matrix);
    result.warnings = warnings_.in_file_order();
    result.layout_used = layout_used();
    return result;
  }

 private:
  bool causes_are_rows() const { return orientation_.orientation != CsvOrientation::EffectsAsRows; }
  AxisElements& causes() { return causes_are_rows() ? rows_ : columns_; }
  AxisElements& effects() { return causes_are_rows() ? columns_ : rows_; }
  AxisContext context(ElementKind kind) { return {kind, layout_, source_, warnings_, errors_, parameter_trip_sides_}; }

  // A cause's attribute (setpoint, unit, voting, trip side) on the effects'
  // axis: the orientation or the layout is wrong.
  void check_slot_kinds() {
    const auto& effect_slots = causes_are_rows() ? shape_.column_slots : shape_.row_slots;
    for (const Slot& s : effect_slots) {
      if (!cause_only(s.attribute)) continue;
      const bool row = causes_are_rows();
      const int line = row ? sheet_.rows[s.index].line : sheet_.rows[shape_.id_row].line;
      const int column = row ? sheet_.column_of(0) : sheet_.column_of(s.index);
      errors_.at(line, column, std::string(row ? "header row " : "label column ") +
                                   std::to_string(row ? line : column) + " " +
                                   in_quotes(s.label.empty() ? to_string(s.attribute) : s.label) + " holds the " +
                                   to_string(s.attribute) + " of causes, but the " + (row ? "columns" : "rows") +
                                   " are the effects (orientation " + to_string(orientation_.orientation) + ")");
    }
  }

  // The footnotes' texts: the legend rows of the sheet, the layout's
  // footnotes and a workbook's remarks sheet; two texts for one key are an
  // error (never one picked in silence).
  void read_legend() {
    static const std::regex legend_re(R"(^(\(\s*(\d+)\s*\)|\*{1,3})$)");
    for (const auto& row : sheet_.legend) {
      std::smatch mt;
      const std::string first = cell_text(row, 0);
      std::regex_match(first, mt, legend_re);
      std::string text;
      for (std::size_t i = 1; i < row.fields.size(); ++i)
        if (auto t = cell_text(row, i); !t.empty()) join_to(text, " ", t);
      const std::string key = mt[2].matched ? "(" + mt[2].str() + ")" : mt[1].str();
      if (!legend_.emplace(key, one_line(text)).second)
        warnings_.at(row.line, sheet_.column_of(0), "footnote " + key + " defined twice in the legend; the first is kept");
      legend_line_[key] = row.line;
    }
    auto merge = [&](const std::map<std::string, std::string>& texts, const std::string& from) {
      for (const auto& [key, text] : texts) {
        auto [it, fresh] = legend_.emplace(key, text);
        if (!fresh && it->second != text)
          errors_.at(legend_line_.count(key) ? legend_line_[key] : sheet_.rows[shape_.id_row].line, 0,
                     "footnote " + key + " reads " + in_quotes(it->second) + " here and " + in_quotes(text) + " in " +
                         from + ": give it one text");
        kept_footnotes_[key] = text;
      }
    };
    merge(layout_.footnotes, "the layout");
    merge(sheet_.extras.remarks, sheet_.extras.remarks_place);
  }

  Matrix build_matrix() {
    Matrix m;
    std::string stem = source_;
    if (auto slash = stem.find_last_of("/\\"); slash != std::string::npos) stem = stem.substr(slash + 1);
    if (auto dot = stem.rfind('.'); dot != std::string::npos && dot > 0) stem = stem.substr(0, dot);
    // 6.1.2: matrix names have at most 16 characters; 6.2.1: titles at most 60.
    m.name = name_.empty() ? sanitize_identifier(stem, kMaxMatrixNameLength) : name_;
    if (m.name.empty()) m.name = "IMPORTED_GRID";
    m.title = truncate_utf8(one_line(stem.empty() ? std::string("Imported C&E grid") : stem), kMaxTitleLength);
    for (const auto& c : causes().elements) {
      Cause cause;
      cause.id = c.id;
      cause.name = c.name;
      cause.description = c.text;
      cause.note = c.note;
      cause.sil = c.sil;
      cause.function = c.function.value_or(CauseFunction::Normal);
      for (const auto& t : c.tags) cause.tags.push_back(CauseTag{t, false, true});
      if (c.analog) {
        cause.input = InputKind::Analog;
        cause.analog = c.analog;
      }
      m.causes.push_back(std::move(cause));
    }
    for (const auto& e : effects().elements) {
      Effect effect;
      effect.id = e.id;
      effect.name = e.name;
      effect.description = e.text;
      effect.note = e.note;
      effect.sil = e.sil;
      for (const auto& t : e.tags) effect.tags.push_back(EffectTag{t, false});
      m.effects.push_back(std::move(effect));
    }
    m.intersections = intersections_;
    m.sort_by_id();
    return m;
  }

  std::string summary(const Matrix& m) {
    auto rows_part = [&](const std::vector<SheetElement>& els, const char* kind) {
      std::string s = plural(els.size(), kind) + " (rows " + std::to_string(els.front().line) + "-" +
                      std::to_string(els.back().last_line);
      s += shape_.id_column ? ", ids in column " + std::to_string(sheet_.column_of(*shape_.id_column))
                            : ", no id column";
      return s + ")";
    };
    auto columns_part = [&](const std::vector<SheetElement>& els, const char* kind) {
      return plural(els.size(), kind) + " (columns " + std::to_string(els.front().column) + "-" +
             std::to_string(els.back().last_line) + ", ids in row " +
             std::to_string(sheet_.rows[shape_.id_row].line) + ")";
    };
    std::string s = "read ";
    s += causes_are_rows() ? rows_part(rows_.elements, "cause") : columns_part(columns_.elements, "cause");
    s += ", ";
    s += causes_are_rows() ? columns_part(columns_.elements, "effect") : rows_part(rows_.elements, "effect");
    s += ", " + std::to_string(m.intersections.size()) + " intersections; orientation " +
         (causes_are_rows() ? "causes-as-rows " : "effects-as-rows ") + orientation_.evidence;
    for (const auto& slot_text : slot_summary()) s += "; " + slot_text;
    if (!causes().groups.empty()) {
      std::string list;
      for (const auto& g : causes().groups) join_to(list, ", ", g);
      s += "; voting groups: " + list;
    }
    if (causes().analog > 0) s += "; " + plural(static_cast<std::size_t>(causes().analog), "setpoint") + " read as analog limits";
    for (AxisElements* axis : {&causes(), &effects()}) {
      if (axis->deleted.empty()) continue;
      std::string list;
      for (const auto& d : axis->deleted) join_to(list, ", ", d);
      s += "; left out " + plural(axis->deleted.size(), std::string("deleted ") + (axis == &causes() ? "cause" : "effect")) +
           ": " + list;
    }
    if (sheet_.empty_rows_skipped || sheet_.empty_columns_skipped) {
      std::string skipped;
      if (sheet_.empty_rows_skipped) skipped = plural(sheet_.empty_rows_skipped, "empty row") + " above";
      if (sheet_.empty_columns_skipped)
        join_to(skipped, " and ", plural(sheet_.empty_columns_skipped, "empty column") + " left of");
      s += "; skipped " + skipped + " the grid";
    }
    return s;
  }

  // What the label columns and header rows other than ids and descriptions became.
  std::vector<std::string> slot_summary() const {
    std::vector<std::string> out;
    auto describe = [&](const std::vector<Slot>& slots, bool rows, const std::string& kind) {
      for (const Slot& s : slots) {
        const bool named = s.attribute == SheetAttribute::Id || s.attribute == SheetAttribute::Description;
        if (named && s.evidence.empty()) continue;
        const std::string where = rows ? "label column " + std::to_string(sheet_.column_of(s.index))
                                       : "header row " + std::to_string(sheet_.rows[s.index].line);
        out.push_back(where + (s.label.empty() ? "" : " " + in_quotes(s.label)) + " " + read_as(s.attribute, kind) +
                      (s.evidence.empty() ? "" : " (" + s.evidence + ")"));
      }
    };
    describe(shape_.column_slots, false, causes_are_rows() ? "effect" : "cause");
    describe(shape_.row_slots, true, causes_are_rows() ? "cause" : "effect");
    return out;
  }

  // The layout the sheet was read with, complete: the given one, the
  // orientation and the places found, and every footnote text not in the
  // sheet itself (layout, remarks sheet), so that it reads a CSV of the same
  // sheet the same.
  SheetLayout layout_used() const {
    SheetLayout u = layout_;
    u.orientation = orientation_.orientation;
    std::vector<AttributePlace> row_places, column_places;
    for (const Slot& s : shape_.row_slots) row_places.push_back({s.attribute, sheet_.column_of(s.index)});
    for (const Slot& s : shape_.column_slots) column_places.push_back({s.attribute, sheet_.rows[s.index].line});
    u.causes = causes_are_rows() ? row_places : column_places;
    u.effects = causes_are_rows() ? column_places : row_places;
    u.footnotes = kept_footnotes_;
    return u;
  }

  // 6.5.2: V and R need a maximum override time, which a grid never states.
  void report_missing_override() {
    std::set<int> need;
    for (const auto& x : intersections_)
      if (x.type == IntersectionType::V || x.type == IntersectionType::R) need.insert(x.effect);
    if (need.empty()) return;
    std::string list;
    for (const auto& e : effects().elements)
      if (need.count(e.id)) join_to(list, ", ", e.name);
    warnings_.at(effects().elements.front().line, 0,
                 "the grid states no maximum override time (6.5.2) for the effects with V/R "
                 "intersections (" + list + "); none was invented: cemv validate reports each");
  }

  const Sheet& sheet_;
  const Shape& shape_;
  OrientationDecision orientation_;
  std::string source_;
  std::string name_;  // the matrix name asked for; empty: from the file name
  const SheetLayout& layout_;
  const std::map<std::string, model::LimitType>& parameter_trip_sides_;
  AxisElements columns_;  // one per column (a voting group: several) of the grid
  AxisElements rows_;
  std::map<std::string, std::string> legend_;
  std::map<std::string, int> legend_line_;
  std::map<std::string, std::string> kept_footnotes_;  // from the layout and a remarks sheet
  std::vector<Intersection> intersections_;
  GridWarnings warnings_;
  GridErrors errors_;
};

}  // namespace

CsvImportResult import_grid(std::string_view text, const std::string& source, const CsvImportOptions& options,
                            const SheetExtras& extras) {
  const SheetLayout layout = options.sheet_layout.value_or(SheetLayout{});
  CsvOrientation requested = options.orientation;
  std::string given_by = "--orientation";
  if (layout.orientation != CsvOrientation::Auto) {
    if (requested != CsvOrientation::Auto && requested != layout.orientation)
      throw LoadError({{source, std::string("--orientation ") + to_string(requested) + " and the layout's " +
                                    to_string(layout.orientation) + " disagree; give one"}});
    requested = layout.orientation;
    given_by = "the layout's orientation";
  }
  Sheet sheet = read_sheet(text, options.separator, source);
  sheet.extras = extras;
  const Shape shape = find_shape(sheet, source, layout);
  OrientationDecision orientation =
      decide_orientation(sheet, shape, requested, source, given_by, layout.orientation != CsvOrientation::Auto);
  return GridImporter(sheet, shape, std::move(orientation), source, options.matrix_name, layout,
                      options.parameter_trip_sides).run();
}

}  // namespace cemv::formats::grid
