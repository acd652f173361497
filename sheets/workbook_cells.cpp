#include "sheets/workbook_cells.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "sheets/workbook_rows.hpp"
#include "sheets/workbook_tags.hpp"
#include "model/matrix.hpp"
#include "model/text.hpp"

namespace cemv::formats::workbook {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::string trimmed(const std::string& s) {
  std::size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

Table CellReader::header(const Sheet& sheet, const std::vector<std::string>& headers, const std::string& info_only) {
  Table t{&sheet, {}};
  std::map<std::string, std::string> by_lower;
  for (const auto& h : headers) by_lower[lower(h)] = h;
  std::vector<std::string_view> known(headers.begin(), headers.end());
  for (const Cell* c : sheet.row(1)) {
    std::string h = trimmed(c->text);
    if (h.empty()) continue;
    auto it = by_lower.find(lower(h));
    if (it == by_lower.end()) {
      if (lower(h) != lower(info_only))
        error(sheet, 1, c->column, "", "unknown column " + model::in_quotes(h) + model::did_you_mean(h, known));
      continue;
    }
    if (!t.columns.emplace(it->second, c->column).second)
      error(sheet, 1, c->column, "", "column " + model::in_quotes(it->second) + " repeats the header of " +
                                         cell_address(1, t.columns[it->second]));
  }
  for (const auto& h : headers)
    if (!t.columns.count(h)) error(sheet, 1, 0, "", "column " + model::in_quotes(h) + " is missing from the header row");
  return t;
}

std::string CellReader::text(const Table& t, std::size_t row, const std::string& header, const std::string& path,
                             bool keep_blanks) {
  auto it = t.columns.find(header);
  if (it == t.columns.end()) return "";
  if (!path.empty()) remember(path, *t.sheet, row, it->second, header);
  const Cell* c = t.sheet->find(row, it->second);
  if (!c) return "";
  return keep_blanks ? c->text : trimmed(c->text);
}

bool CellReader::present(const Table& t, std::size_t row, const std::string& header) {
  return !text(t, row, header, "").empty();
}

void CellReader::error_at(const Table& t, std::size_t row, const std::string& header, std::string what) {
  auto it = t.columns.find(header);
  error(*t.sheet, row, it == t.columns.end() ? 0 : it->second, header, std::move(what));
}

long long CellReader::integer(const Table& t, std::size_t row, const std::string& header, const std::string& path,
                              long long min, long long max, long long fallback) {
  std::string s = text(t, row, header, path);
  if (s.empty()) return fallback;
  long long v = 0;
  if (!whole_number(s, min, max, v)) {
    error_at(t, row, header, model::in_quotes(s) + " is not a whole number " + std::to_string(min) + "-" + std::to_string(max));
    return fallback;
  }
  return v;
}

float CellReader::real(const Table& t, std::size_t row, const std::string& header, const std::string& path, float fallback) {
  std::string s = text(t, row, header, path);
  if (s.empty()) return fallback;
  // As the JSON loader reads a real: a double, then the nearest single; half
  // an ulp above FLT_MAX and beyond rounds to infinity and is refused.
  double d = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), d);
  constexpr double kFloatOverflow = 0x1.ffffffp+127;
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(d) || std::fabs(d) >= kFloatOverflow) {
    error_at(t, row, header, model::in_quotes(s) + " is not a number in the range of IEEE single precision (REAL, 6.3.1)");
    return fallback;
  }
  float v = static_cast<float>(d);
  return v == 0 ? 0.0f : v;  // -0 is 0, as in the JSON loader
}

bool CellReader::boolean(const Table& t, std::size_t row, const std::string& header, const std::string& path, bool fallback) {
  std::string s = lower(text(t, row, header, path));
  if (s.empty()) return fallback;
  if (s == "true" || s == "yes" || s == "1") return true;
  if (s == "false" || s == "no" || s == "0") return false;
  error_at(t, row, header, model::in_quotes(s) + " is not true or false");
  return fallback;
}

int CellReader::choice(const Table& t, std::size_t row, const std::string& header, const std::string& path,
                       const std::vector<std::string>& names, int fallback) {
  std::string s = text(t, row, header, path);
  if (s.empty()) return fallback;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (lower(s) == lower(names[i])) return static_cast<int>(i);
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + model::in_quotes(n);
  error_at(t, row, header, model::in_quotes(s) + " is not one of " + list + model::did_you_mean(s, names));
  return fallback;
}

std::optional<std::string> CellReader::tag(const Table& t, std::size_t row, const std::string& header, const std::string& path) {
  std::string s = text(t, row, header, path, true);
  if (trimmed(s).empty()) return std::nullopt;
  TagCell cell = read_tag_cell(s);
  auto column = t.columns.at(header);
  for (const auto& option : cell.ignored)
    warn(*t.sheet, row, column, header, "option " + option + " of tag " + model::in_quotes(cell.name) +
                                            " is an F-channel driver setting outside cemv-matrix/1; ignored (6.6.2)");
  if (!cell.normalized.empty())
    warn(*t.sheet, row, column, header, "read " + model::in_quotes(s) + " as the internal reference " +
                                            model::in_quotes(cell.normalized) + " (6.1.3)");
  return cell.name;
}

std::vector<int> CellReader::sif(const Table& t, std::size_t row, const std::string& header, const std::string& path) {
  std::string s = text(t, row, header, path);
  std::vector<int> out;
  std::string word;
  auto flush = [&] {
    if (word.empty()) return;
    long long v = 0;
    if (whole_number(word, 1, model::kMaxSifGroups, v))
      out.push_back(static_cast<int>(v));
    else
      error_at(t, row, header, "SIF group " + model::in_quotes(word) + " is not a whole number 1-64");
    word.clear();
  };
  for (char c : s) {
    if (c == ' ' || c == ';' || c == ',')
      flush();
    else
      word += c;
  }
  flush();
  return out;
}

void CellReader::error(const Sheet& sheet, std::size_t row, std::size_t column, const std::string& header, std::string what) {
  if (errors_.size() < kMaxIssues) errors_.push_back(place(file_, sheet, row, column, header, std::move(what)));
}

void CellReader::warn(const Sheet& sheet, std::size_t row, std::size_t column, const std::string& header, std::string what) {
  if (warnings_.size() < kMaxIssues) warnings_.push_back(place(file_, sheet, row, column, header, std::move(what)));
}

void CellReader::remember(const std::string& path, const Sheet& sheet, std::size_t row, std::size_t column,
                          const std::string& header) {
  places_[path] = {&sheet, row, column, header};
}

void CellReader::rename(const std::map<std::string, std::string>& prefixes) {
  std::map<std::string, Place> renamed;
  for (auto& [path, p] : places_) {
    std::string key = path;
    // The element prefix: "causes[12]" of "causes[12].tags[0].name".
    std::size_t end = path.find(']');
    if (end != std::string::npos) {
      auto it = prefixes.find(path.substr(0, end + 1));
      if (it != prefixes.end()) key = it->second + path.substr(end + 1);
    }
    renamed[key] = p;
  }
  places_ = std::move(renamed);
}

LoadIssue CellReader::locate(const LoadIssue& issue) const {
  std::string path = issue.where;
  while (!path.empty()) {
    auto it = places_.find(path);
    if (it != places_.end()) {
      const Place& p = it->second;
      LoadIssue out = place(file_, *p.sheet, p.row, p.column, p.header, issue.what);
      out.where += (out.where.empty() ? "" : " ") + std::string("[") + issue.where + "]";
      return out;
    }
    std::size_t cut = path.find_last_of(".[");
    if (cut == std::string::npos || cut == 0) break;
    path = path.substr(0, cut);
  }
  LoadIssue out = issue;
  out.file = file_;
  out.line = out.column = 0;
  return out;
}

}  // namespace cemv::formats::workbook
