// Inside cemv-params/1 (params.cpp, params_sections.cpp): the matrix's
// canonical JSON as a parameters file changes it, each value set once and
// recorded with the place of the file that set it, every problem at that place.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "formats/diagnostics.hpp"
#include "model/matrix.hpp"

namespace cemv::formats::params {

using Json = nlohmann::ordered_json;

std::string text_of(const Json& v);

// One value the file sets: where in the matrix's JSON and where in the file.
struct Setting {
  std::string list;        // "", "causes", "effects"
  std::size_t index = 0;   // into the list
  std::string key;         // top-level key of the element (or of the matrix)
  std::string field;       // as recorded: "override", "tags[1].simulation_allowed"
  std::string label;       // "effect[1] TMA_A_1"
  std::string params_path; // where the file sets it
  std::string origin;
  std::string previous;    // JSON text before
  std::vector<std::size_t> tag;  // for tags[k].simulation_allowed: k (0-based)
};

class ParamsEdit {
 public:
  ParamsEdit(const model::Matrix& m, std::string_view text, const std::string& file);

  Json& doc() { return doc_; }

  void error(const std::string& path, std::string what);
  bool expect(bool ok, const std::string& path, const char* what);
  bool has_errors() const { return !errors_.empty(); }
  [[noreturn]] void fail();
  void warn(const std::string& path, std::string what);
  // The entry's own "origin", else the one it inherits.
  std::string origin_of(const Json& entry, const std::string& path, const std::string& inherited);

  // Elements by the keys the file may use: the name (case-insensitive) or
  // the sheet id the grid import recorded in the note.
  std::optional<std::size_t> element(const std::string& list, const std::string& key, const std::string& path);
  std::string label(const std::string& list, std::size_t index) const;
  bool processed(const std::string& list, std::size_t index) const;

  // Sets one key of the matrix or of an element, once.
  void set(Setting s, const Json& value);
  // Claims a path of the matrix's JSON for the place of the file that sets
  // it; the place that claimed it first, if another did.
  std::optional<std::string> claim(const std::string& matrix_path, const std::string& params_path);
  // A path a policy of the file sets, unless an entry of its own did.
  void claim_for_policy(const std::string& matrix_path, const std::string& params_path);
  void record_setting(Setting s) { settings_.push_back(std::move(s)); }
  void record_policy(model::ParameterValue v) { policy_values_.push_back(std::move(v)); }
  void record_footnote(model::FootnoteRecord f) { footnotes_.push_back(std::move(f)); }
  const std::vector<model::FootnoteRecord>& footnotes() const { return footnotes_; }
  void describe_tag(const std::string& tag_key, const std::string& params_path) { description_at_[tag_key] = params_path; }

  // The matrix as changed, through the loader: a value the format refuses is
  // reported at the place of the parameters file that set it.
  model::Matrix load_result();
  // Each value as the canonical form of `result` writes it, the record of this file.
  model::ParameterRecord record(const model::Matrix& result, const std::string& origin);
  std::vector<LoadIssue> take_warnings();

 private:
  std::string_view text_;
  std::string file_;
  Json doc_;  // the matrix being changed, canonical JSON
  std::vector<LoadIssue> errors_;
  std::vector<LoadIssue> warnings_;
  std::vector<Setting> settings_;
  std::map<std::string, std::string> set_at_;  // "causes[3].soft_bypass" -> params path that set it
  std::map<std::string, std::string> description_at_;  // tag key -> params path
  std::vector<model::ParameterValue> policy_values_;    // recorded once for many elements
  std::vector<model::FootnoteRecord> footnotes_;
};

// The sections of the file, each read into the edit.
class ParamsSections {
 public:
  ParamsSections(ParamsEdit& edit, const Json& params) : edit_(edit), params_(params) {}

  void read_matrix(const Json& j, const std::string& origin);
  void read_sif_groups(const Json& j, const std::string& origin);
  void read_elements(const std::string& list, const Json& j, const std::string& path, const std::string& origin);
  void read_footnotes(const Json& j, const std::string& origin);
  void read_tags(const Json& j, const std::string& origin);
  // The file's policies, for every element without an entry of its own: read last.
  void read_policies(const std::string& origin);

 private:
  void read_soft_bypass_policy(const std::string& origin);
  void read_simulation_policy(const std::string& origin);
  void read_sif_group_members(const Json& group, int number, const std::string& path, const std::string& origin);
  void read_tag_description(const std::string& tag, const Json& value, const std::string& path,
                            const std::string& origin);
  void read_tag_simulation(const std::string& tag, const Json& value, const std::string& path,
                           const std::string& origin);
  void cite_footnote(const model::FootnoteRecord& rec, const std::string& path, const std::string& origin);

  ParamsEdit& edit_;
  const Json& params_;
  std::set<std::string> explicit_soft_bypass_;  // "3" for causes[3]
  std::set<std::string> explicit_simulation_;   // tag keys given in "tags"
};

}  // namespace cemv::formats::params
