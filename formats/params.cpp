// cemv-params/1 (docs/params.md): read a parameters file, set its values in
// the matrix's canonical JSON, pass the result through the matrix loader (so
// every value obeys docs/format.md), and record each value with its origin.
#include "formats/params.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include <nlohmann/json.hpp>

#include "formats/matrix_json.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats {

namespace {

using Json = nlohmann::ordered_json;
using model::in_quotes;

// Keys of a cause or an effect the file may not set: they name the element.
const std::set<std::string> kIdentity = {"id", "name"};
const std::vector<std::string> kMatrixKeys = {"name", "title", "cycle_ms", "watchdog_ms", "secure_write",
                                              "group_deactivation"};
const std::vector<std::string> kTopKeys = {"format",  "origin", "matrix", "sif_groups", "soft_bypass", "simulation",
                                           "causes",  "effects", "tags", "footnotes", "limitations"};

std::string text_of(const Json& v) { return v.is_null() ? "null" : v.dump(); }

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

class Applier {
 public:
  Applier(const model::Matrix& m, std::string_view text, const std::string& file)
      : m_(m), text_(text), file_(file), doc_(Json::parse(to_canonical_json(m))) {}

  ParamsApplication run();

 private:
  [[noreturn]] void fail() {
    locate_issues(text_, file_, errors_);
    throw LoadError(errors_);
  }
  void error(const std::string& path, std::string what) {
    if (errors_.size() < kMaxIssues) errors_.push_back({path, std::move(what), file_});
  }
  bool expect(const Json&, bool ok, const std::string& path, const char* what) {
    if (!ok) error(path, std::string("expected ") + what);
    return ok;
  }
  std::string origin_of(const Json& entry, const std::string& path, const std::string& inherited) {
    auto it = entry.find("origin");
    if (it == entry.end()) return inherited;
    if (!it->is_string()) {
      error(member_path(path, "origin"), "expected a string saying where the values come from");
      return inherited;
    }
    return it->get<std::string>();
  }

  // Elements by the keys the file may use: the name (case-insensitive) or
  // the sheet id the grid import recorded in the note.
  std::optional<std::size_t> element(const std::string& list, const std::string& key, const std::string& path);
  std::string label(const std::string& list, std::size_t index) const {
    const Json& e = doc_[list][index];
    return std::string(list == "causes" ? "cause[" : "effect[") + std::to_string(e["id"].get<int>()) + "] " +
           e["name"].get<std::string>();
  }
  bool processed(const std::string& list, std::size_t index) const {
    return doc_[list][index]["function"] != "comment";
  }

  void set(Setting s, const Json& value);
  void read_matrix(const Json& j, const std::string& origin);
  void read_sif_groups(const Json& j, const std::string& origin);
  void read_elements(const std::string& list, const Json& j, const std::string& path, const std::string& origin);
  void read_policies(const std::string& origin);
  void read_tags(const Json& j, const std::string& origin);
  void read_footnotes(const Json& j, const std::string& origin);

  model::Matrix load_result();
  void record(model::Matrix& result, const std::string& origin);

  const model::Matrix& m_;
  std::string_view text_;
  std::string file_;
  Json doc_;     // the matrix being changed, canonical JSON
  Json params_;
  std::vector<LoadIssue> errors_;
  std::vector<Setting> settings_;
  std::map<std::string, std::string> set_at_;  // "causes[3].soft_bypass" -> params path that set it
  std::set<std::string> explicit_soft_bypass_;  // "causes[3]"
  std::set<std::string> explicit_simulation_;   // tag keys given in "tags"
  std::map<std::string, std::string> description_at_;  // tag key -> params path
  std::vector<model::ParameterValue> policy_values_;    // recorded once for many elements
  std::vector<model::FootnoteRecord> footnotes_;
  std::vector<std::string> notes_;
  std::vector<LoadIssue> warnings_;
};

std::optional<std::size_t> Applier::element(const std::string& list, const std::string& key, const std::string& path) {
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

// Sets one key of the matrix or of an element, once.
void Applier::set(Setting s, const Json& value) {
  std::string where = s.list.empty() ? member_path("", s.key)
                     : s.tag.empty()  ? member_path(element_path(s.list, s.index), s.key)
                                      : member_path(element_path(element_path(s.list, s.index) + ".tags", s.tag.front()),
                                                    "simulation_allowed");
  auto [it, fresh] = set_at_.emplace(where, s.params_path);
  if (!fresh) {
    error(s.params_path, s.label + " " + s.field + " is already set by " + it->second);
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

void Applier::read_matrix(const Json& j, const std::string& origin) {
  if (!expect(j, j.is_object(), "matrix", "an object of matrix properties")) return;
  std::string o = origin_of(j, "matrix", origin);
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (it.key() == "origin") continue;
    std::string path = member_path("matrix", it.key());
    if (std::find(kMatrixKeys.begin(), kMatrixKeys.end(), it.key()) == kMatrixKeys.end()) {
      error(path, "not a matrix property the parameters may set (name, title, cycle_ms, watchdog_ms, "
                  "secure_write, group_deactivation)" + model::did_you_mean(it.key(), kMatrixKeys));
      continue;
    }
    set({"", 0, it.key(), it.key(), "matrix", path, o, "", {}}, it.value());
  }
}

void Applier::read_sif_groups(const Json& j, const std::string& origin) {
  if (!expect(j, j.is_object(), "sif_groups", "an object of SIF groups by number")) return;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string path = member_path("sif_groups", it.key());
    const Json& g = it.value();
    if (!expect(g, g.is_object() && g.contains("name"), path, "an object with the group's name")) continue;
    std::string o = origin_of(g, path, origin);
    Json entry = Json::object();
    entry["name"] = g["name"];
    if (g.contains("process_safety_time_ms")) entry["process_safety_time_ms"] = g["process_safety_time_ms"];
    for (auto k = g.begin(); k != g.end(); ++k)
      if (k.key() != "name" && k.key() != "process_safety_time_ms" && k.key() != "causes" && k.key() != "effects" &&
          k.key() != "origin")
        error(member_path(path, k.key()), "unknown key (a group has name, process_safety_time_ms, causes, effects, origin)");
    Json& groups = doc_["sif_groups"];
    std::string previous = groups.contains(it.key()) ? text_of(groups[it.key()]) : "null";
    std::string where = member_path("sif_groups", it.key());
    if (auto [at, fresh] = set_at_.emplace(where, path); !fresh) {
      error(path, "SIF group " + it.key() + " is already set by " + at->second);
      continue;
    }
    groups[it.key()] = entry;
    settings_.push_back({"", 0, "sif_groups", "sif_groups." + it.key(), "matrix", path, o, previous, {}});
    int number = 0;
    try {
      number = std::stoi(it.key());
    } catch (...) {
      number = 0;  // the loader names the bad key
    }
    for (const char* list : {"causes", "effects"}) {
      if (!g.contains(list)) continue;
      const std::string lp = member_path(path, list);
      if (!expect(g[list], g[list].is_array(), lp, "an array of element names or sheet ids")) continue;
      for (std::size_t i = 0; i < g[list].size(); ++i) {
        const std::string ep = element_path(lp, i);
        if (!expect(g[list][i], g[list][i].is_string(), ep, "a name or sheet id")) continue;
        auto index = element(list, g[list][i].get<std::string>(), ep);
        if (!index) continue;
        Json& sif = doc_[list][*index]["sif"];
        std::string before = text_of(sif);
        if (std::find(sif.begin(), sif.end(), Json(number)) == sif.end()) sif.push_back(number);
        std::string key = member_path(element_path(list, *index), "sif");
        if (!set_at_.count(key)) {
          set_at_[key] = ep;
          settings_.push_back({list, *index, "sif", "sif", label(list, *index), ep, o, before, {}});
        }
      }
    }
  }
}

void Applier::read_elements(const std::string& list, const Json& j, const std::string& path, const std::string& origin) {
  if (!expect(j, j.is_object(), path, "an object of elements by name or sheet id")) return;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string ep = member_path(path, it.key());
    auto index = element(list, it.key(), ep);
    if (!index || !expect(it.value(), it.value().is_object(), ep, "an object of fields")) continue;
    std::string o = origin_of(it.value(), ep, origin);
    for (auto f = it.value().begin(); f != it.value().end(); ++f) {
      if (f.key() == "origin") continue;
      const std::string fp = member_path(ep, f.key());
      if (kIdentity.count(f.key())) {
        error(fp, in_quotes(f.key()) + " identifies the element; the parameters cannot change it");
        continue;
      }
      if (list == "causes" && f.key() == "soft_bypass") explicit_soft_bypass_.insert(std::to_string(*index));
      set({list, *index, f.key(), f.key(), label(list, *index), fp, o, "", {}}, f.value());
    }
  }
}

// The policies of the file: for every processed cause the soft bypass, for
// every cause input tag and output tag whether it may be simulated, unless an
// entry of its own says otherwise. Recorded once each.
void Applier::read_policies(const std::string& origin) {
  if (params_.contains("soft_bypass")) {
    const Json& p = params_["soft_bypass"];
    if (expect(p, p.is_object(), "soft_bypass", "an object like a cause's soft_bypass (allowed, max_s, prealarm_s)")) {
      std::string o = origin_of(p, "soft_bypass", origin);
      Json value = p;
      value.erase("origin");
      // "tags": whether the operator may soft-bypass single tags (6.3.4), for
      // every tag of the causes the policy covers.
      std::optional<bool> tags;
      if (value.contains("tags")) {
        if (value["tags"].is_boolean()) tags = value["tags"].get<bool>();
        else error(member_path("soft_bypass", "tags"), "expected true or false (may single tags be soft-bypassed)");
        value.erase("tags");
      }
      std::set<std::string> before;
      int n = 0;
      for (std::size_t i = 0; i < doc_["causes"].size(); ++i) {
        if (!processed("causes", i) || explicit_soft_bypass_.count(std::to_string(i))) continue;
        before.insert(text_of(doc_["causes"][i]["soft_bypass"]));
        doc_["causes"][i]["soft_bypass"] = value;
        if (tags)
          for (auto& t : doc_["causes"][i]["tags"]) t["soft_bypass_allowed"] = *tags;
        set_at_[member_path(element_path("causes", i), "soft_bypass")] = "soft_bypass";
        ++n;
      }
      std::string previous;
      for (const auto& b : before) previous += (previous.empty() ? "" : " or ") + b;
      if (n) policy_values_.push_back({"every cause without its own soft_bypass (" + std::to_string(n) + ")",
                                        "soft_bypass", value.dump(), previous, o});
      if (n && tags)
        policy_values_.push_back({"every tag of those causes", "tags[].soft_bypass_allowed", *tags ? "true" : "false",
                                  "true", o});
    }
  }
  if (params_.contains("simulation")) {
    const Json& p = params_["simulation"];
    if (expect(p, p.is_object() && p.contains("allowed") && p["allowed"].is_boolean(), "simulation",
               "an object {\"allowed\": true|false}")) {
      std::string o = origin_of(p, "simulation", origin);
      for (auto k = p.begin(); k != p.end(); ++k)
        if (k.key() != "allowed" && k.key() != "origin")
          error(member_path("simulation", k.key()), "unknown key (simulation has allowed and origin)");
      const bool allowed = p["allowed"].get<bool>();
      int n = 0;
      for (const char* list : {"causes", "effects"})
        for (std::size_t i = 0; i < doc_[list].size(); ++i) {
          if (!processed(list, i)) continue;
          for (auto& t : doc_[list][i]["tags"]) {
            const std::string name = t["name"].get<std::string>();
            if (model::parse_internal_ref(name) || explicit_simulation_.count(model::tag_key(name))) continue;
            if (allowed) t.erase("simulation_allowed");
            else t["simulation_allowed"] = false;
            ++n;
          }
        }
      if (n) policy_values_.push_back({"every cause input tag and output tag without an entry in tags (" +
                                           std::to_string(n) + ")",
                                       "simulation_allowed", allowed ? "true" : "false", "true", o});
    }
  }
}

void Applier::read_tags(const Json& j, const std::string& origin) {
  if (!expect(j, j.is_object(), "tags", "an object of tags by name")) return;
  // Every tag the matrix names in any role, as the file has changed it (a
  // footnote may add a reset tag), internal references aside.
  std::vector<std::string> known;
  std::set<std::string> keys;
  auto add = [&](const Json& v) {
    if (!v.is_string() || model::parse_internal_ref(v.get<std::string>())) return;
    if (keys.insert(model::tag_key(v.get<std::string>())).second) known.push_back(v.get<std::string>());
  };
  for (const char* list : {"causes", "effects"})
    for (const auto& e : doc_[list]) {
      for (const auto& t : e["tags"]) add(t["name"]);
      for (const char* k : {"bypass_tag", "inhibit_tag", "reset_tag"})
        if (e.contains(k)) add(e[k]);
      if (e.contains("process_data") && e["process_data"].is_object())
        for (const char* k : {"tag", "mask_tag"})
          if (e["process_data"].contains(k)) add(e["process_data"][k]);
    }
  for (const char* k : {"secure_write", "group_deactivation"})
    if (doc_.contains(k) && doc_[k].is_object())
      for (const auto& [name, tag] : doc_[k].items()) add(tag);
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string tp = member_path("tags", it.key());
    const std::string key = model::tag_key(it.key());
    if (!keys.count(key)) {
      error(tp, "the matrix reads or writes no tag " + in_quotes(it.key()) + model::did_you_mean(it.key(), known));
      continue;
    }
    if (!expect(it.value(), it.value().is_object(), tp, "an object with description and/or simulation_allowed")) continue;
    std::string o = origin_of(it.value(), tp, origin);
    for (auto f = it.value().begin(); f != it.value().end(); ++f) {
      const std::string fp = member_path(tp, f.key());
      if (f.key() == "origin") continue;
      if (f.key() == "description") {
        Json& list = doc_["tag_descriptions"];
        if (!list.is_array()) list = Json::array();
        std::string previous = "null";
        for (auto d = list.begin(); d != list.end(); ++d)
          if (model::tag_key((*d)["tag"].get<std::string>()) == key) {
            previous = text_of((*d)["description"]);
            list.erase(d);
            break;
          }
        list.push_back(Json{{"tag", it.key()}, {"description", f.value()}});
        description_at_[key] = fp;
        settings_.push_back({"", 0, "tag_descriptions", "description", "tag " + it.key(), fp, o, previous, {}});
      } else if (f.key() == "simulation_allowed") {
        explicit_simulation_.insert(key);
        int n = 0;
        for (const char* list : {"causes", "effects"})
          for (std::size_t i = 0; i < doc_[list].size(); ++i)
            for (std::size_t k = 0; k < doc_[list][i]["tags"].size(); ++k)
              if (model::tag_key(doc_[list][i]["tags"][k]["name"].get<std::string>()) == key) {
                set({list, i, "tags", "tags[" + std::to_string(k + 1) + "].simulation_allowed", label(list, i), fp, o,
                     "", {k}},
                    f.value());
                ++n;
              }
        if (n == 0) error(fp, "tag " + in_quotes(it.key()) + " is neither a cause input tag nor an output tag, the "
                                                             "tags an operator can simulate (O.8)");
      } else {
        error(fp, "unknown key (a tag has description, simulation_allowed, origin)");
      }
    }
  }
}

void Applier::read_footnotes(const Json& j, const std::string& origin) {
  if (!expect(j, j.is_object(), "footnotes", "an object of footnotes by mark, e.g. \"(1)\"")) return;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string fp = member_path("footnotes", it.key());
    const Json& f = it.value();
    if (!expect(f, f.is_object() && f.contains("text") && f["text"].is_string(), fp,
                "an object with the legend's text")) continue;
    model::FootnoteRecord rec;
    rec.mark = it.key();
    rec.text = f["text"].get<std::string>();
    const std::string own = origin_of(f, fp, origin);
    const std::string o = "footnote " + rec.mark + " \"" + rec.text + "\"" + (own.empty() ? "" : "; " + own);
    bool expressed = false;
    for (auto k = f.begin(); k != f.end(); ++k) {
      const std::string kp = member_path(fp, k.key());
      if (k.key() == "causes" || k.key() == "effects") {
        read_elements(k.key(), k.value(), kp, o);
        expressed = true;
      } else if (k.key() == "modelled" || k.key() == "not_modelled") {
        if (!expect(k.value(), k.value().is_string(), kp, "a string")) continue;
        (k.key() == "modelled" ? rec.modelled : rec.not_modelled) = k.value().get<std::string>();
      } else if (k.key() != "text" && k.key() != "origin") {
        error(kp, "unknown key (a footnote has text, causes, effects, modelled, not_modelled, origin)");
      }
    }
    if (!expressed && rec.not_modelled.empty())
      error(fp, "footnote " + rec.mark + ": say how the matrix expresses it (causes, effects) or why it cannot "
                "(not_modelled)");
    // The legend's text in the notes of the intersections that cite it.
    int cited = 0;
    for (auto& x : doc_["intersections"]) {
      std::string note = x["note"].get<std::string>();
      std::string out;
      bool changed = false;
      std::size_t start = 0;
      while (start <= note.size()) {
        std::size_t end = note.find("; ", start);
        std::string piece = note.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (piece == rec.mark || piece.rfind(rec.mark + " ", 0) == 0) {
          piece = rec.mark + " " + rec.text;
          changed = true;
        }
        out += (out.empty() ? "" : "; ") + piece;
        if (end == std::string::npos) break;
        start = end + 2;
      }
      if (changed) {
        x["note"] = out;
        ++cited;
      }
    }
    if (cited == 0)
      warnings_.push_back({fp, "footnote " + rec.mark + " is cited by no intersection of the matrix", file_});
    else
      policy_values_.push_back({"footnote " + rec.mark + " (" + std::to_string(cited) +
                                    (cited == 1 ? " intersection)" : " intersections)"),
                                "note",
                                Json(rec.mark + " " + rec.text).dump(), Json(rec.mark).dump(), o});
    footnotes_.push_back(std::move(rec));
  }
}

// The matrix as changed, through the loader: a value the format refuses is
// reported at the place of the parameters file that set it.
model::Matrix Applier::load_result() {
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

// Each value as the canonical form writes it, in the record of this file.
void Applier::record(model::Matrix& result, const std::string& origin) {
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
  if (params_.contains("limitations")) {
    const Json& l = params_["limitations"];
    if (l.is_array())
      for (const auto& t : l)
        if (t.is_string()) rec.limitations.push_back(t.get<std::string>());
  }
  notes_.push_back("parameters " + rec.file + " (sha256 " + rec.sha256.substr(0, 12) + "...): set " +
                   std::to_string(rec.values.size()) + (rec.values.size() == 1 ? " value" : " values") + ", " +
                   std::to_string(rec.footnotes.size()) + (rec.footnotes.size() == 1 ? " footnote" : " footnotes") +
                   " explained, " + std::to_string(rec.limitations.size()) +
                   (rec.limitations.size() == 1 ? " limitation" : " limitations") + " stated");
  result.provenance.parameters.push_back(std::move(rec));
}

ParamsApplication Applier::run() {
  std::vector<LoadIssue> issues;
  auto parsed = parse_guarded_json(text_, file_, issues, {4096, "parameters file", 8});
  if (!parsed) throw LoadError(issues);
  params_ = std::move(*parsed);
  if (!params_.is_object()) {
    error("", "expected a JSON object (" + std::string(kParamsFormat) + ")");
    fail();
  }
  if (!params_.contains("format") || params_["format"] != kParamsFormat) {
    error("format", std::string(params_.contains("format") ? "is " + text_of(params_["format"]) + ", expected '"
                                                           : "required key is missing (expected '") +
                        kParamsFormat + "'" + (params_.contains("format") ? "" : ")"));
    fail();
  }
  for (auto it = params_.begin(); it != params_.end(); ++it)
    if (std::find(kTopKeys.begin(), kTopKeys.end(), it.key()) == kTopKeys.end())
      error(it.key(), "unknown key" + model::did_you_mean(it.key(), kTopKeys));
  const std::string sha = sha256_hex(text_);
  for (const auto& r : m_.provenance.parameters)
    if (r.sha256 == sha) error("", "this parameters file (" + r.file + ", sha256 " + sha.substr(0, 12) +
                                       "...) is already applied to the matrix");
  std::string origin;
  if (params_.contains("origin")) origin = origin_of(params_, "", "");
  if (params_.contains("limitations")) {
    const Json& l = params_["limitations"];
    if (expect(l, l.is_array(), "limitations", "an array of texts"))
      for (std::size_t i = 0; i < l.size(); ++i) expect(l[i], l[i].is_string(), element_path("limitations", i), "a text");
  }
  if (!doc_.contains("tag_descriptions")) doc_["tag_descriptions"] = Json::array();
  if (params_.contains("matrix")) read_matrix(params_["matrix"], origin);
  if (params_.contains("sif_groups")) read_sif_groups(params_["sif_groups"], origin);
  if (params_.contains("causes")) read_elements("causes", params_["causes"], "causes", origin);
  if (params_.contains("effects")) read_elements("effects", params_["effects"], "effects", origin);
  if (params_.contains("footnotes")) read_footnotes(params_["footnotes"], origin);
  if (params_.contains("tags")) read_tags(params_["tags"], origin);
  read_policies(origin);
  if (doc_["tag_descriptions"].empty()) doc_.erase("tag_descriptions");
  if (!errors_.empty()) fail();

  // Footnotes the sheet cites that the file leaves unexplained.
  std::set<std::string> explained;
  for (const auto& f : footnotes_) explained.insert(f.mark);
  std::map<std::string, int> unexplained;
  for (const auto& x : m_.intersections) {
    for (std::size_t at = x.note.find('('); at != std::string::npos; at = x.note.find('(', at + 1)) {
      std::size_t end = x.note.find(')', at);
      if (end == std::string::npos || end - at < 2 || end - at > 4) continue;
      std::string mark = x.note.substr(at, end - at + 1);
      if (mark.find_first_not_of("0123456789", 1) != mark.size() - 1) continue;
      if (!explained.count(mark)) ++unexplained[mark];
    }
  }
  for (const auto& [mark, n] : unexplained)
    warnings_.push_back({"footnotes", "the sheet's footnote " + mark + " (" + std::to_string(n) +
                                          (n == 1 ? " intersection" : " intersections") +
                                          ") is not explained: say what it means, or why the matrix cannot express it",
                         file_});

  model::Matrix result = load_result();
  record(result, origin);
  locate_issues(text_, file_, warnings_);
  return {std::move(result), std::move(notes_), std::move(warnings_)};
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
  return Applier(m, text, file_name).run();
}

}  // namespace cemv::formats
