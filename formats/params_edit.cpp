// The matrix's canonical JSON as a parameters file changes it
// (formats/params_edit.hpp, docs/params.md).
#include "formats/params_edit.hpp"

#include <filesystem>

#include "formats/matrix_json.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats::params {

using model::in_quotes;

std::string text_of(const Json& v) { return v.is_null() ? "null" : v.dump(); }

ParamsEdit::ParamsEdit(const model::Matrix& m, std::string_view text, const std::string& file)
    : text_(text), file_(file), doc_(Json::parse(to_canonical_json(m))) {}

void ParamsEdit::error(const std::string& path, std::string what) {
  if (errors_.size() < kMaxIssues) errors_.push_back({path, std::move(what), file_});
}

bool ParamsEdit::expect(bool ok, const std::string& path, const char* what) {
  if (!ok) error(path, std::string("expected ") + what);
  return ok;
}

void ParamsEdit::fail() {
  locate_issues(text_, file_, errors_);
  throw LoadError(errors_);
}

void ParamsEdit::warn(const std::string& path, std::string what) {
  warnings_.push_back({path, std::move(what), file_});
}

std::vector<LoadIssue> ParamsEdit::take_warnings() {
  locate_issues(text_, file_, warnings_);
  return std::move(warnings_);
}

std::string ParamsEdit::origin_of(const Json& entry, const std::string& path, const std::string& inherited) {
  auto it = entry.find("origin");
  if (it == entry.end()) return inherited;
  if (!it->is_string()) {
    error(member_path(path, "origin"), "expected a string saying where the values come from");
    return inherited;
  }
  return it->get<std::string>();
}

std::optional<std::size_t> ParamsEdit::element(const std::string& list, const std::string& key,
                                               const std::string& path) {
  const Json& items = doc_[list];
  const std::string want = model::tag_key(key);
  std::vector<std::size_t> by_sheet_id;
  std::vector<std::string> known;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string name = items[i]["name"].get<std::string>();
    if (model::tag_key(name) == want) return i;
    known.push_back(name);
    const std::string note = items[i]["note"].get<std::string>();
    static const std::string prefix = "sheet id: ";
    if (note.rfind(prefix, 0) == 0) {
      std::string sheet = note.substr(prefix.size(), note.find(';') - prefix.size());
      known.push_back(sheet);
      if (model::tag_key(sheet) == want) by_sheet_id.push_back(i);
    }
  }
  const char* kind = list == "causes" ? "cause" : "effect";
  if (by_sheet_id.size() == 1) return by_sheet_id.front();
  if (by_sheet_id.size() > 1) {
    std::string names;
    for (std::size_t i : by_sheet_id) names += (names.empty() ? "" : ", ") + items[i]["name"].get<std::string>();
    error(path, "sheet id " + in_quotes(key) + " names " + std::to_string(by_sheet_id.size()) + " " + kind +
                    "s (" + names + "); use the name of the one meant");
    return std::nullopt;
  }
  error(path, "the matrix has no " + std::string(kind) + " named " + in_quotes(key) + " (by name or sheet id)" +
                  model::did_you_mean(key, known));
  return std::nullopt;
}

std::string ParamsEdit::label(const std::string& list, std::size_t index) const {
  const Json& e = doc_[list][index];
  return std::string(list == "causes" ? "cause[" : "effect[") + std::to_string(e["id"].get<int>()) + "] " +
         e["name"].get<std::string>();
}

bool ParamsEdit::processed(const std::string& list, std::size_t index) const {
  return doc_[list][index]["function"] != "comment";
}

void ParamsEdit::set(Setting s, const Json& value) {
  std::string where = s.list.empty() ? member_path("", s.key)
                     : s.tag.empty()  ? member_path(element_path(s.list, s.index), s.key)
                                      : member_path(element_path(element_path(s.list, s.index) + ".tags", s.tag.front()),
                                                    "simulation_allowed");
  if (auto first = claim(where, s.params_path)) {
    error(s.params_path, s.label + " " + s.field + " is already set by " + *first);
    return;
  }
  Json& target = s.list.empty() ? doc_ : doc_[s.list][s.index];
  if (!s.tag.empty()) {
    Json& tag = target["tags"][s.tag.front()];
    s.previous = tag.contains("simulation_allowed") ? text_of(tag["simulation_allowed"]) : "true";
    tag["simulation_allowed"] = value;
  } else {
    s.previous = target.contains(s.key) ? text_of(target[s.key]) : "null";
    target[s.key] = value;
  }
  settings_.push_back(std::move(s));
}

std::optional<std::string> ParamsEdit::claim(const std::string& matrix_path, const std::string& params_path) {
  auto [it, fresh] = set_at_.emplace(matrix_path, params_path);
  if (fresh) return std::nullopt;
  return it->second;
}

void ParamsEdit::claim_for_policy(const std::string& matrix_path, const std::string& params_path) {
  set_at_[matrix_path] = params_path;
}

model::Matrix ParamsEdit::load_result() {
  const Json empty = Json::array();
  const Json& list = doc_.contains("tag_descriptions") ? doc_["tag_descriptions"] : empty;
  if (list.is_array())
    for (std::size_t i = 0; i < list.size(); ++i)
      if (auto at = description_at_.find(model::tag_key(list[i]["tag"].get<std::string>())); at != description_at_.end())
        set_at_[element_path("tag_descriptions", i)] = at->second;
  try {
    return parse_matrix(doc_.dump(), file_);
  } catch (const LoadError& e) {
    for (const auto& issue : e.issues()) {
      std::string at, key;
      for (const auto& [matrix_path, params_path] : set_at_)
        if ((issue.where == matrix_path || issue.where.rfind(matrix_path + ".", 0) == 0 ||
             issue.where.rfind(matrix_path + "[", 0) == 0) &&
            matrix_path.size() >= key.size()) {
          key = matrix_path;
          at = params_path;
        }
      error(at, (key.empty() ? "" : "sets " + issue.where + ": ") + issue.what);
    }
    fail();
  }
}

model::ParameterRecord ParamsEdit::record(const model::Matrix& result, const std::string& origin) {
  const Json c = Json::parse(to_canonical_json(result));
  model::ParameterRecord rec;
  rec.file = std::filesystem::path(file_).filename().string();
  rec.sha256 = sha256_hex(text_);
  rec.origin = origin;
  for (const auto& s : settings_) {
    std::string value = "null";
    if (s.key == "tag_descriptions") {
      for (const auto& d : c["tag_descriptions"])
        if (model::tag_key(d["tag"].get<std::string>()) == model::tag_key(s.label.substr(4))) value = d["description"].dump();
    } else if (s.key == "sif_groups") {
      value = text_of(c["sif_groups"][s.field.substr(std::string("sif_groups.").size())]);
    } else if (s.list.empty()) {
      value = c.contains(s.key) ? text_of(c[s.key]) : "null";
    } else if (!s.tag.empty()) {
      const Json& t = c[s.list][s.index]["tags"][s.tag.front()];
      value = t.contains("simulation_allowed") ? text_of(t["simulation_allowed"]) : "true";
    } else {
      const Json& e = c[s.list][s.index];
      value = e.contains(s.key) ? text_of(e[s.key]) : "null";
    }
    rec.values.push_back({s.label, s.field, value, s.previous, s.origin});
  }
  for (auto& v : policy_values_) rec.values.push_back(std::move(v));
  rec.footnotes = std::move(footnotes_);
  return rec;
}

}  // namespace cemv::formats::params
