// cemv-params/1 (docs/params.md): read a parameters file, set its values in
// the matrix's canonical JSON, pass the result through the matrix loader (so
// every value obeys docs/format.md), and record each value with its origin.
// The edit and its record are params_edit.cpp; the sections params_sections.cpp.
#include "formats/params.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "formats/params_edit.hpp"
#include "formats/matrix_json.hpp"
#include "model/text.hpp"

namespace cemv::formats {

namespace {

using params::Json;
using params::text_of;

const std::vector<std::string> kTopKeys = {"format",  "origin", "matrix", "sif_groups", "soft_bypass", "simulation",
                                           "causes",  "effects", "tags", "footnotes", "limitations"};

// The file's own keys: its format, no key it does not know, not applied
// before, its limitations texts.
void check_file(params::ParamsEdit& edit, const Json& p, const model::Matrix& m, std::string_view text) {
  if (!p.is_object()) {
    edit.error("", "expected a JSON object (" + std::string(kParamsFormat) + ")");
    edit.fail();
  }
  if (!p.contains("format") || p["format"] != kParamsFormat) {
    edit.error("format", std::string(p.contains("format") ? "is " + text_of(p["format"]) + ", expected '"
                                                          : "required key is missing (expected '") +
                             kParamsFormat + "'" + (p.contains("format") ? "" : ")"));
    edit.fail();
  }
  for (auto it = p.begin(); it != p.end(); ++it)
    if (std::find(kTopKeys.begin(), kTopKeys.end(), it.key()) == kTopKeys.end())
      edit.error(it.key(), "unknown key" + model::did_you_mean(it.key(), kTopKeys));
  const std::string sha = sha256_hex(text);
  for (const auto& r : m.provenance.parameters)
    if (r.sha256 == sha)
      edit.error("", "this parameters file (" + r.file + ", sha256 " + sha.substr(0, 12) +
                         "...) is already applied to the matrix");
  if (p.contains("limitations")) {
    const Json& l = p["limitations"];
    if (edit.expect(l.is_array(), "limitations", "an array of texts"))
      for (std::size_t i = 0; i < l.size(); ++i) edit.expect(l[i].is_string(), element_path("limitations", i), "a text");
  }
}

// Footnotes the sheet cites that the file leaves unexplained.
void warn_unexplained_footnotes(params::ParamsEdit& edit, const model::Matrix& m) {
  std::set<std::string> explained;
  for (const auto& f : edit.footnotes()) explained.insert(f.mark);
  std::map<std::string, int> unexplained;
  for (const auto& x : m.intersections) {
    for (std::size_t at = x.note.find('('); at != std::string::npos; at = x.note.find('(', at + 1)) {
      std::size_t end = x.note.find(')', at);
      if (end == std::string::npos || end - at < 2 || end - at > 4) continue;
      std::string mark = x.note.substr(at, end - at + 1);
      if (mark.find_first_not_of("0123456789", 1) != mark.size() - 1) continue;
      if (!explained.count(mark)) ++unexplained[mark];
    }
  }
  for (const auto& [mark, n] : unexplained)
    edit.warn("footnotes", "the sheet's footnote " + mark + " (" + std::to_string(n) +
                               (n == 1 ? " intersection" : " intersections") +
                               ") is not explained: say what it means, or why the matrix cannot express it");
}

std::string summary(const model::ParameterRecord& rec) {
  return "parameters " + rec.file + " (sha256 " + rec.sha256.substr(0, 12) + "...): set " +
         std::to_string(rec.values.size()) + (rec.values.size() == 1 ? " value" : " values") + ", " +
         std::to_string(rec.footnotes.size()) + (rec.footnotes.size() == 1 ? " footnote" : " footnotes") +
         " explained, " + std::to_string(rec.limitations.size()) +
         (rec.limitations.size() == 1 ? " limitation" : " limitations") + " stated";
}

ParamsApplication apply(const model::Matrix& m, std::string_view text, const std::string& file) {
  std::vector<LoadIssue> issues;
  auto parsed = parse_guarded_json(text, file, issues, {4096, "parameters file", 8});
  if (!parsed) throw LoadError(issues);
  const Json p = std::move(*parsed);
  params::ParamsEdit edit(m, text, file);
  check_file(edit, p, m, text);
  std::string origin;
  if (p.contains("origin")) origin = edit.origin_of(p, "", "");

  Json& doc = edit.doc();
  if (!doc.contains("tag_descriptions")) doc["tag_descriptions"] = Json::array();
  params::ParamsSections sections(edit, p);
  if (p.contains("matrix")) sections.read_matrix(p["matrix"], origin);
  if (p.contains("sif_groups")) sections.read_sif_groups(p["sif_groups"], origin);
  if (p.contains("causes")) sections.read_elements("causes", p["causes"], "causes", origin);
  if (p.contains("effects")) sections.read_elements("effects", p["effects"], "effects", origin);
  if (p.contains("footnotes")) sections.read_footnotes(p["footnotes"], origin);
  if (p.contains("tags")) sections.read_tags(p["tags"], origin);
  sections.read_policies(origin);
  if (doc["tag_descriptions"].empty()) doc.erase("tag_descriptions");
  if (edit.has_errors()) edit.fail();
  warn_unexplained_footnotes(edit, m);

  model::Matrix result = edit.load_result();
  model::ParameterRecord rec = edit.record(result, origin);
  if (p.contains("limitations") && p["limitations"].is_array())
    for (const auto& t : p["limitations"])
      if (t.is_string()) rec.limitations.push_back(t.get<std::string>());
  std::vector<std::string> notes{summary(rec)};
  result.provenance.parameters.push_back(std::move(rec));
  return {std::move(result), std::move(notes), edit.take_warnings()};
}

}  // namespace

std::map<std::string, model::LimitType> params_trip_sides(std::string_view text, const std::string& file_name) {
  if (text.size() > kMaxFileBytes)
    throw LoadError({{"", "file larger than " + std::to_string(kMaxFileBytes) + " bytes", file_name}});
  std::vector<LoadIssue> issues;
  auto parsed = parse_guarded_json(text, file_name, issues, {4096, "parameters file", 8});
  if (!parsed) throw LoadError(issues);
  std::map<std::string, model::LimitType> sides;
  if (!parsed->is_object() || !parsed->contains("causes") || !(*parsed)["causes"].is_object()) return sides;
  for (const auto& [key, cause] : (*parsed)["causes"].items()) {
    if (!cause.is_object() || !cause.contains("analog") || !cause["analog"].is_object()) continue;
    const Json& analog = cause["analog"];
    const Json type = analog.contains("limit_type") ? analog["limit_type"] : Json();
    if (type == "high") sides[key] = model::LimitType::High;
    else if (type == "low") sides[key] = model::LimitType::Low;
  }
  return sides;
}

ParamsApplication apply_params(const model::Matrix& m, std::string_view text, const std::string& file_name) {
  if (text.size() > kMaxFileBytes)
    throw LoadError({{"", "file larger than " + std::to_string(kMaxFileBytes) + " bytes", file_name}});
  return apply(m, text, file_name);
}

}  // namespace cemv::formats
