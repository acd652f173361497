// Reading a C&E grid (docs/csv.md "The grid layout"): the elements of both axes,
// their numbers and names, and one intersection per marked cell. The sheet is
// imported as it is: its defects become warnings with line and column, and no
// safety parameter that the grid does not state is invented.
#include <algorithm>
#include <map>
#include <regex>
#include <set>
#include <utility>

#include "formats/csv_grid.hpp"
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


std::string upper(std::string s) {
  for (auto& c : s)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return s;
}

// A header row or label column is the tag row when its label says so ("Tag",
// "Tag name", "Output tag"); any other extra header text goes into the note.
bool is_tag_label(const std::string& label) {
  static const std::regex tag(R"(\btags?\b)", std::regex::icase);
  return std::regex_search(label, tag);
}

class GridImporter {
 public:
  GridImporter(const Sheet& sheet, const Shape& shape, OrientationDecision orientation,
               std::string source, std::string name)
      : sheet_(sheet), shape_(shape), orientation_(std::move(orientation)),
        source_(std::move(source)), name_(std::move(name)), warnings_(source_) {}

  CsvImportResult run() {
    if (orientation_.disagreement) {
      const auto& d = *orientation_.disagreement;
      warnings_.add(sheet_.rows[shape_.id_row].line, d);
    }
    read_legend();
    read_column_elements();
    read_row_elements();
    number_elements(effects(), "effect", "E", kMaxEffects, warnings_);
    number_elements(causes(), "cause", "C", kMaxCauses, warnings_);
    intersections_ = read_intersections(sheet_, shape_,
                                        GridAxes{row_elements_, element_rows_, column_elements_, causes_are_rows()},
                                        legend_, warnings_);
    report_missing_override();

    CsvImportResult result;
    result.layout = CsvLayoutKind::Grid;
    result.orientation = orientation_.orientation;
    result.matrix = parse_matrix(to_canonical_json(build_matrix()), source_);
    result.summary = summary(result.matrix);
    result.warnings = warnings_.in_file_order();
    return result;
  }

 private:
  bool causes_are_rows() const { return orientation_.orientation != CsvOrientation::EffectsAsRows; }
  const char* row_kind() const { return causes_are_rows() ? "cause" : "effect"; }
  const char* column_kind() const { return causes_are_rows() ? "effect" : "cause"; }
  static int limit_of(const std::string& kind) { return kind == "cause" ? kMaxCauses : kMaxEffects; }
  std::vector<SheetElement>& causes() { return causes_are_rows() ? row_elements_ : column_elements_; }
  std::vector<SheetElement>& effects() { return causes_are_rows() ? column_elements_ : row_elements_; }

  void warn(int line, int column, std::string what) { warnings_.at(line, column, std::move(what)); }

  Matrix build_matrix() {
    Matrix m;
    std::string stem = source_;
    if (auto slash = stem.find_last_of("/\\"); slash != std::string::npos) stem = stem.substr(slash + 1);
    if (auto dot = stem.rfind('.'); dot != std::string::npos && dot > 0) stem = stem.substr(0, dot);
    // 6.1.2: matrix names have at most 16 characters; 6.2.1: titles at most 60.
    m.name = name_.empty() ? sanitize_identifier(stem, kMaxMatrixNameLength) : name_;
    if (m.name.empty()) m.name = "IMPORTED_GRID";
    m.title = truncate_utf8(one_line(stem.empty() ? std::string("Imported C&E grid") : stem),
                            kMaxTitleLength);
    for (const auto& c : causes()) {
      Cause cause;
      cause.id = c.id;
      cause.name = c.name;
      cause.description = c.text;
      cause.note = c.note;
      cause.tags.push_back(CauseTag{c.tag, false, true});
      m.causes.push_back(std::move(cause));
    }
    for (const auto& e : effects()) {
      Effect effect;
      effect.id = e.id;
      effect.name = e.name;
      effect.description = e.text;
      effect.note = e.note;
      effect.tags.push_back(EffectTag{e.tag, false});
      m.effects.push_back(std::move(effect));
    }
    m.intersections = intersections_;
    m.sort_by_id();
    return m;
  }

  // "read 36 causes (rows 3-38, ids in column 2), 17 effects (columns 3-19, ids
  // in row 2), 102 intersections; orientation causes-as-rows from ...".
  std::string summary(const Matrix& m) {
    auto rows_part = [&](const std::vector<SheetElement>& els, const char* kind) {
      std::string s = std::to_string(els.size()) + " " + kind + (els.size() == 1 ? "" : "s") + " (rows " +
                      std::to_string(els.front().line) + "-" + std::to_string(els.back().line);
      s += shape_.id_column ? ", ids in column " + std::to_string(sheet_.column_of(*shape_.id_column))
                            : ", no id column";
      return s + ")";
    };
    auto columns_part = [&](const std::vector<SheetElement>& els, const char* kind) {
      return std::to_string(els.size()) + " " + kind + (els.size() == 1 ? "" : "s") + " (columns " +
             std::to_string(els.front().column) + "-" + std::to_string(els.back().column) +
             ", ids in row " + std::to_string(sheet_.rows[shape_.id_row].line) + ")";
    };
    std::string s = "read ";
    s += causes_are_rows() ? rows_part(row_elements_, "cause") : columns_part(column_elements_, "cause");
    s += ", ";
    s += causes_are_rows() ? columns_part(column_elements_, "effect") : rows_part(row_elements_, "effect");
    s += ", " + std::to_string(m.intersections.size()) + " intersections; orientation " +
         (causes_are_rows() ? "causes-as-rows " : "effects-as-rows ") + orientation_.evidence;
    for (const auto& extra : extras_) s += "; " + extra;
    if (sheet_.empty_rows_skipped || sheet_.empty_columns_skipped) {
      std::string skipped;
      if (sheet_.empty_rows_skipped)
        skipped = std::to_string(sheet_.empty_rows_skipped) + " empty row" +
                  (sheet_.empty_rows_skipped == 1 ? "" : "s") + " above";
      if (sheet_.empty_columns_skipped)
        join_to(skipped, " and ", std::to_string(sheet_.empty_columns_skipped) + " empty column" +
                                      (sheet_.empty_columns_skipped == 1 ? "" : "s") + " left of");
      s += "; skipped " + skipped + " the grid";
    }
    return s;
  }

  void read_legend() {
    static const std::regex legend_re(R"(^\(\s*(\d+)\s*\)$)");
    for (const auto& row : sheet_.legend) {
      std::smatch mt;
      const std::string first = cell_text(row, 0);
      std::regex_match(first, mt, legend_re);
      std::string text;
      for (std::size_t i = 1; i < row.fields.size(); ++i)
        if (auto t = cell_text(row, i); !t.empty()) join_to(text, " ", t);
      std::string key = "(" + mt[1].str() + ")";
      if (!legend_.emplace(key, one_line(text)).second)
        warn(row.line, sheet_.column_of(0), "footnote " + key + " defined twice in the legend; the first is kept");
    }
  }

  // Text of an extra header row or label column: the element's tag when the
  // label names the tag row, else a part of its note ("Action: close").
  void add_extra(SheetElement& e, const std::string& label, const std::string& value, int line,
                 int column, const char* kind) {
    if (value.empty()) return;
    if (is_tag_label(label)) {
      if (auto problem = tag_name_problem(value)) {
        warn(line, column,
             std::string(kind) + " tag " + in_quotes(value) + " is not a tag name (6.1.4: " + *problem +
                 "); the tag is named after the id");
        return;
      }
      e.tag_from_sheet = value;
      return;
    }
    join_to(e.note, "; ", (label.empty() ? "line " + std::to_string(line) : label) + ": " + value);
  }

  void note_extras(const std::vector<std::size_t>& extras, bool rows, const char* kind) {
    for (std::size_t x : extras) {
      const std::string label = rows ? row_label(sheet_, shape_, x) : column_label(sheet_, shape_, x);
      const std::string where = rows ? "header row " + std::to_string(sheet_.rows[x].line)
                                     : "label column " + std::to_string(sheet_.column_of(x));
      extras_.push_back(where + (label.empty() ? "" : " " + in_quotes(label)) +
                        (is_tag_label(label) ? " read as the " + std::string(kind) + " tags"
                                             : " kept in the " + std::string(kind) + " notes"));
    }
  }

  void read_column_elements() {
    const char* kind = column_kind();
    const CsvRecord& descriptions = sheet_.rows[shape_.description_row];
    const CsvRecord& ids = sheet_.rows[shape_.id_row];
    const std::size_t c0 = shape_.first_data_column;
    const std::size_t count = shape_.column_end - c0;
    if (count > static_cast<std::size_t>(limit_of(kind)))
      throw LoadError({{where_of(source_, ids.line),
                        "the grid has " + std::to_string(count) + " " + kind + " columns; a matrix holds at most " +
                            std::to_string(limit_of(kind)) + " " + kind + "s (3.4)"}});
    for (std::size_t i = c0; i < shape_.column_end; ++i) {
      SheetElement e;
      e.sheet_id = cell_text(ids, i);
      e.line = ids.line;
      e.column = sheet_.column_of(i);
      if (e.sheet_id.empty()) {
        e.unnamed = upper(kind) + "_COL_" + std::to_string(e.column);
        warn(ids.line, e.column,
             std::string(kind) + " column without an id; named after its column (" + e.unnamed + ")");
      }
      if (shape_.description_row != shape_.id_row)
        describe(e, cell_text(descriptions, i), descriptions.line, e.column, kind);
      for (std::size_t x : shape_.extra_rows)
        add_extra(e, row_label(sheet_, shape_, x), cell_text(sheet_.rows[x], i), sheet_.rows[x].line,
                  e.column, kind);
      column_elements_.push_back(std::move(e));
    }
    note_extras(shape_.extra_rows, true, kind);
  }

  // Description truncated to the 80 characters of 6.3/6.4; the full text kept in the note.
  void describe(SheetElement& e, const std::string& raw, int line, int column, const char* kind) {
    const std::string text = one_line(raw);
    e.text = text;
    if (utf8_length(text) > kMaxDescriptionLength) {
      e.text = truncate_utf8(text, kMaxDescriptionLength);
      join_to(e.note, "; ", "description: " + text);
      warn(line, column,
           std::string(kind) + " description of " + std::to_string(utf8_length(text)) +
               " characters truncated to " + std::to_string(kMaxDescriptionLength) +
               "; the full text is kept in the note");
    }
  }

  void read_row_elements() {
    const char* kind = row_kind();
    const std::size_t c0 = shape_.first_data_column;
    const bool has_description = shape_.description_column && shape_.description_column != shape_.id_column;
    for (std::size_t r = shape_.first_data_row; r < sheet_.rows.size(); ++r) {
      const CsvRecord& row = sheet_.rows[r];
      std::string label;
      for (std::size_t i = 0; i < c0; ++i)
        if (auto t = cell_text(row, i); !t.empty()) join_to(label, " ", t);
      bool marks = false;
      for (std::size_t i = c0; i < row.fields.size(); ++i) marks = marks || !cell_text(row, i).empty();
      if (label.empty() && !marks) continue;
      SheetElement c;
      c.sheet_id = shape_.id_column ? cell_text(row, *shape_.id_column) : "";
      c.line = row.line;
      c.column = sheet_.column_of(shape_.id_column ? *shape_.id_column : c0 - 1);
      if (c.sheet_id.empty()) {
        if (!marks) {
          warn(row.line, sheet_.column_of(0),
               "text row without " + std::string(kind == std::string("cause") ? "a cause" : "an effect") +
                   " id or intersections ignored: " + in_quotes(label));
          continue;
        }
        c.unnamed = upper(kind) + "_LINE_" + std::to_string(row.line);
        warn(row.line, c.column,
             std::string(kind) + " row without an id; imported, named after its line (" + c.unnamed + ")");
      }
      if (row_elements_.size() == static_cast<std::size_t>(limit_of(kind)))
        throw LoadError({{where_of(source_, row.line),
                          "more than " + std::to_string(limit_of(kind)) + " " + kind + " rows; a matrix holds at most " +
                              std::to_string(limit_of(kind)) + " " + kind + "s (3.4)"}});
      if (has_description)
        describe(c, cell_text(row, *shape_.description_column), row.line,
                 sheet_.column_of(*shape_.description_column), kind);
      for (std::size_t x : shape_.extra_columns)
        add_extra(c, column_label(sheet_, shape_, x), cell_text(row, x), row.line, sheet_.column_of(x), kind);
      element_rows_.push_back(r);
      row_elements_.push_back(std::move(c));
    }
    if (row_elements_.empty())
      throw LoadError({{where_of(source_, sheet_.rows.back().line),
                        std::string("not a C&E grid: no ") + kind + " rows after the header rows (docs/csv.md)"}});
    note_extras(shape_.extra_columns, false, kind);
  }

  // 6.5.2: V and R need a maximum override time, which a grid never states.
  void report_missing_override() {
    std::set<int> need;
    for (const auto& x : intersections_)
      if (x.type == IntersectionType::V || x.type == IntersectionType::R) need.insert(x.effect);
    if (need.empty()) return;
    std::string list;
    for (const auto& e : effects())
      if (need.count(e.id)) join_to(list, ", ", e.name);
    warn(effects().front().line, 0,
         "the grid states no maximum override time (6.5.2) for the effects with V/R "
         "intersections (" + list + "); none was invented: cemv validate reports each");
  }

  const Sheet& sheet_;
  const Shape& shape_;
  OrientationDecision orientation_;
  std::string source_;
  std::string name_;  // the matrix name asked for; empty: from the file name
  std::vector<SheetElement> column_elements_;  // one per column of the grid
  std::vector<SheetElement> row_elements_;     // one per row of the grid
  std::vector<std::size_t> element_rows_;      // the sheet row of each row element
  std::vector<std::string> extras_;            // what the extra header rows/columns became
  std::map<std::string, std::string> legend_;
  std::vector<Intersection> intersections_;
  GridWarnings warnings_;
};

}  // namespace

CsvImportResult import_grid(std::string_view text, const std::string& source,
                            const CsvImportOptions& options) {
  const Sheet sheet = read_sheet(text, options.separator, source);
  const Shape shape = find_shape(sheet, source);
  OrientationDecision orientation = decide_orientation(sheet, shape, options.orientation, source);
  return GridImporter(sheet, shape, std::move(orientation), source, options.matrix_name).run();
}

}  // namespace cemv::formats::grid
