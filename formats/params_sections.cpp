// The sections of a cemv-params/1 file read into the matrix being changed
// (formats/params_edit.hpp, docs/params.md).
#include <algorithm>

#include "formats/params_edit.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats::params {

using model::in_quotes;

namespace {

// Keys of a cause or an effect the file may not set: they name the element.
const std::set<std::string> kIdentity = {"id", "name"};
const std::vector<std::string> kMatrixKeys = {"name", "title", "cycle_ms", "watchdog_ms", "secure_write",
                                              "group_deactivation"};

}  // namespace

void ParamsSections::read_matrix(const Json& j, const std::string& origin) {
  if (!edit_.expect(j.is_object(), "matrix", "an object of matrix properties")) return;
  std::string o = edit_.origin_of(j, "matrix", origin);
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (it.key() == "origin") continue;
    std::string path = member_path("matrix", it.key());
    if (std::find(kMatrixKeys.begin(), kMatrixKeys.end(), it.key()) == kMatrixKeys.end()) {
      edit_.error(path, "not a matrix property the parameters may set (name, title, cycle_ms, watchdog_ms, "
                        "secure_write, group_deactivation)" + model::did_you_mean(it.key(), kMatrixKeys));
      continue;
    }
    edit_.set({"", 0, it.key(), it.key(), "matrix", path, o, "", {}}, it.value());
  }
}

void ParamsSections::read_sif_groups(const Json& j, const std::string& origin) {
  if (!edit_.expect(j.is_object(), "sif_groups", "an object of SIF groups by number")) return;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string path = member_path("sif_groups", it.key());
    const Json& g = it.value();
    if (!edit_.expect(g.is_object() && g.contains("name"), path, "an object with the group's name")) continue;
    std::string o = edit_.origin_of(g, path, origin);
    Json entry = Json::object();
    entry["name"] = g["name"];
    if (g.contains("process_safety_time_ms")) entry["process_safety_time_ms"] = g["process_safety_time_ms"];
    for (auto k = g.begin(); k != g.end(); ++k)
      if (k.key() != "name" && k.key() != "process_safety_time_ms" && k.key() != "causes" && k.key() != "effects" &&
          k.key() != "origin")
        edit_.error(member_path(path, k.key()),
                    "unknown key (a group has name, process_safety_time_ms, causes, effects, origin)");
    Json& groups = edit_.doc()["sif_groups"];
    std::string previous = groups.contains(it.key()) ? text_of(groups[it.key()]) : "null";
    if (auto first = edit_.claim(member_path("sif_groups", it.key()), path)) {
      edit_.error(path, "SIF group " + it.key() + " is already set by " + *first);
      continue;
    }
    groups[it.key()] = entry;
    edit_.record_setting({"", 0, "sif_groups", "sif_groups." + it.key(), "matrix", path, o, previous, {}});
    int number = 0;
    try {
      number = std::stoi(it.key());
    } catch (...) {
      number = 0;  // the loader names the bad key
    }
    read_sif_group_members(g, number, path, o);
  }
}

// The causes and effects a group's entry names join the group.
void ParamsSections::read_sif_group_members(const Json& group, int number, const std::string& path,
                                            const std::string& origin) {
  for (const char* list : {"causes", "effects"}) {
    if (!group.contains(list)) continue;
    const std::string lp = member_path(path, list);
    const Json& names = group[list];
    if (!edit_.expect(names.is_array(), lp, "an array of element names or sheet ids")) continue;
    for (std::size_t i = 0; i < names.size(); ++i) {
      const std::string ep = element_path(lp, i);
      if (!edit_.expect(names[i].is_string(), ep, "a name or sheet id")) continue;
      auto index = edit_.element(list, names[i].get<std::string>(), ep);
      if (!index) continue;
      Json& sif = edit_.doc()[list][*index]["sif"];
      std::string before = text_of(sif);
      if (std::find(sif.begin(), sif.end(), Json(number)) == sif.end()) sif.push_back(number);
      if (!edit_.claim(member_path(element_path(list, *index), "sif"), ep))
        edit_.record_setting({list, *index, "sif", "sif", edit_.label(list, *index), ep, origin, before, {}});
    }
  }
}

void ParamsSections::read_elements(const std::string& list, const Json& j, const std::string& path,
                                   const std::string& origin) {
  if (!edit_.expect(j.is_object(), path, "an object of elements by name or sheet id")) return;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string ep = member_path(path, it.key());
    auto index = edit_.element(list, it.key(), ep);
    if (!index || !edit_.expect(it.value().is_object(), ep, "an object of fields")) continue;
    std::string o = edit_.origin_of(it.value(), ep, origin);
    for (auto f = it.value().begin(); f != it.value().end(); ++f) {
      if (f.key() == "origin") continue;
      const std::string fp = member_path(ep, f.key());
      if (kIdentity.count(f.key())) {
        edit_.error(fp, in_quotes(f.key()) + " identifies the element; the parameters cannot change it");
        continue;
      }
      if (list == "causes" && f.key() == "soft_bypass") explicit_soft_bypass_.insert(std::to_string(*index));
      edit_.set({list, *index, f.key(), f.key(), edit_.label(list, *index), fp, o, "", {}}, f.value());
    }
  }
}

// The policies of the file: for every processed cause the soft bypass, for
// every cause input tag and output tag whether it may be simulated, unless an
// entry of its own says otherwise. Recorded once each.
void ParamsSections::read_policies(const std::string& origin) {
  if (params_.contains("soft_bypass")) read_soft_bypass_policy(origin);
  if (params_.contains("simulation")) read_simulation_policy(origin);
}

void ParamsSections::read_soft_bypass_policy(const std::string& origin) {
  const Json& p = params_["soft_bypass"];
  if (!edit_.expect(p.is_object(), "soft_bypass", "an object like a cause's soft_bypass (allowed, max_s, prealarm_s)"))
    return;
  std::string o = edit_.origin_of(p, "soft_bypass", origin);
  Json value = p;
  value.erase("origin");
  // "tags": whether the operator may soft-bypass single tags (6.3.4), for
  // every tag of the causes the policy covers.
  std::optional<bool> tags;
  if (value.contains("tags")) {
    if (value["tags"].is_boolean()) tags = value["tags"].get<bool>();
    else edit_.error(member_path("soft_bypass", "tags"), "expected true or false (may single tags be soft-bypassed)");
    value.erase("tags");
  }
  std::set<std::string> before;
  int n = 0;
  Json& causes = edit_.doc()["causes"];
  for (std::size_t i = 0; i < causes.size(); ++i) {
    if (!edit_.processed("causes", i) || explicit_soft_bypass_.count(std::to_string(i))) continue;
    before.insert(text_of(causes[i]["soft_bypass"]));
    causes[i]["soft_bypass"] = value;
    if (tags)
      for (auto& t : causes[i]["tags"]) t["soft_bypass_allowed"] = *tags;
    edit_.claim_for_policy(member_path(element_path("causes", i), "soft_bypass"), "soft_bypass");
    ++n;
  }
  std::string previous;
  for (const auto& b : before) previous += (previous.empty() ? "" : " or ") + b;
  if (n)
    edit_.record_policy({"every cause without its own soft_bypass (" + std::to_string(n) + ")", "soft_bypass",
                         value.dump(), previous, o});
  if (n && tags)
    edit_.record_policy({"every tag of those causes", "tags[].soft_bypass_allowed", *tags ? "true" : "false", "true", o});
}

void ParamsSections::read_simulation_policy(const std::string& origin) {
  const Json& p = params_["simulation"];
  if (!edit_.expect(p.is_object() && p.contains("allowed") && p["allowed"].is_boolean(), "simulation",
                    "an object {\"allowed\": true|false}"))
    return;
  std::string o = edit_.origin_of(p, "simulation", origin);
  for (auto k = p.begin(); k != p.end(); ++k)
    if (k.key() != "allowed" && k.key() != "origin")
      edit_.error(member_path("simulation", k.key()), "unknown key (simulation has allowed and origin)");
  const bool allowed = p["allowed"].get<bool>();
  int n = 0;
  for (const char* list : {"causes", "effects"})
    for (std::size_t i = 0; i < edit_.doc()[list].size(); ++i) {
      if (!edit_.processed(list, i)) continue;
      for (auto& t : edit_.doc()[list][i]["tags"]) {
        const std::string name = t["name"].get<std::string>();
        if (model::parse_internal_ref(name) || explicit_simulation_.count(model::tag_key(name))) continue;
        if (allowed) t.erase("simulation_allowed");
        else t["simulation_allowed"] = false;
        ++n;
      }
    }
  if (n)
    edit_.record_policy({"every cause input tag and output tag without an entry in tags (" + std::to_string(n) + ")",
                         "simulation_allowed", allowed ? "true" : "false", "true", o});
}

void ParamsSections::read_tags(const Json& j, const std::string& origin) {
  if (!edit_.expect(j.is_object(), "tags", "an object of tags by name")) return;
  // Every tag the matrix names in any role, as the file has changed it (a
  // footnote may add a reset tag), internal references aside.
  std::vector<std::string> known;
  std::set<std::string> keys;
  auto add = [&](const Json& v) {
    if (!v.is_string() || model::parse_internal_ref(v.get<std::string>())) return;
    if (keys.insert(model::tag_key(v.get<std::string>())).second) known.push_back(v.get<std::string>());
  };
  const Json& doc = edit_.doc();
  for (const char* list : {"causes", "effects"})
    for (const auto& e : doc[list]) {
      for (const auto& t : e["tags"]) add(t["name"]);
      for (const char* k : {"bypass_tag", "inhibit_tag", "reset_tag"})
        if (e.contains(k)) add(e[k]);
      if (e.contains("process_data") && e["process_data"].is_object())
        for (const char* k : {"tag", "mask_tag"})
          if (e["process_data"].contains(k)) add(e["process_data"][k]);
    }
  for (const char* k : {"secure_write", "group_deactivation"})
    if (doc.contains(k) && doc[k].is_object())
      for (const auto& [name, tag] : doc[k].items()) add(tag);
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string tp = member_path("tags", it.key());
    if (!keys.count(model::tag_key(it.key()))) {
      edit_.error(tp, "the matrix reads or writes no tag " + in_quotes(it.key()) + model::did_you_mean(it.key(), known));
      continue;
    }
    if (!edit_.expect(it.value().is_object(), tp, "an object with description and/or simulation_allowed")) continue;
    std::string o = edit_.origin_of(it.value(), tp, origin);
    for (auto f = it.value().begin(); f != it.value().end(); ++f) {
      const std::string fp = member_path(tp, f.key());
      if (f.key() == "origin") continue;
      if (f.key() == "description") read_tag_description(it.key(), f.value(), fp, o);
      else if (f.key() == "simulation_allowed") read_tag_simulation(it.key(), f.value(), fp, o);
      else edit_.error(fp, "unknown key (a tag has description, simulation_allowed, origin)");
    }
  }
}

void ParamsSections::read_tag_description(const std::string& tag, const Json& value, const std::string& path,
                                          const std::string& origin) {
  const std::string key = model::tag_key(tag);
  Json& list = edit_.doc()["tag_descriptions"];
  if (!list.is_array()) list = Json::array();
  std::string previous = "null";
  for (auto d = list.begin(); d != list.end(); ++d)
    if (model::tag_key((*d)["tag"].get<std::string>()) == key) {
      previous = text_of((*d)["description"]);
      list.erase(d);
      break;
    }
  list.push_back(Json{{"tag", tag}, {"description", value}});
  edit_.describe_tag(key, path);
  edit_.record_setting({"", 0, "tag_descriptions", "description", "tag " + tag, path, origin, previous, {}});
}

void ParamsSections::read_tag_simulation(const std::string& tag, const Json& value, const std::string& path,
                                         const std::string& origin) {
  const std::string key = model::tag_key(tag);
  explicit_simulation_.insert(key);
  int n = 0;
  for (const char* list : {"causes", "effects"})
    for (std::size_t i = 0; i < edit_.doc()[list].size(); ++i)
      for (std::size_t k = 0; k < edit_.doc()[list][i]["tags"].size(); ++k)
        if (model::tag_key(edit_.doc()[list][i]["tags"][k]["name"].get<std::string>()) == key) {
          edit_.set({list, i, "tags", "tags[" + std::to_string(k + 1) + "].simulation_allowed", edit_.label(list, i),
                     path, origin, "", {k}},
                    value);
          ++n;
        }
  if (n == 0)
    edit_.error(path, "tag " + in_quotes(tag) +
                          " is neither a cause input tag nor an output tag, the tags an operator can simulate (O.8)");
}

void ParamsSections::read_footnotes(const Json& j, const std::string& origin) {
  if (!edit_.expect(j.is_object(), "footnotes", "an object of footnotes by mark, e.g. \"(1)\"")) return;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string fp = member_path("footnotes", it.key());
    const Json& f = it.value();
    if (!edit_.expect(f.is_object() && f.contains("text") && f["text"].is_string(), fp,
                      "an object with the legend's text"))
      continue;
    model::FootnoteRecord rec;
    rec.mark = it.key();
    rec.text = f["text"].get<std::string>();
    const std::string own = edit_.origin_of(f, fp, origin);
    const std::string o = "footnote " + rec.mark + " \"" + rec.text + "\"" + (own.empty() ? "" : "; " + own);
    bool expressed = false;
    for (auto k = f.begin(); k != f.end(); ++k) {
      const std::string kp = member_path(fp, k.key());
      if (k.key() == "causes" || k.key() == "effects") {
        read_elements(k.key(), k.value(), kp, o);
        expressed = true;
      } else if (k.key() == "modelled" || k.key() == "not_modelled") {
        if (!edit_.expect(k.value().is_string(), kp, "a string")) continue;
        (k.key() == "modelled" ? rec.modelled : rec.not_modelled) = k.value().get<std::string>();
      } else if (k.key() != "text" && k.key() != "origin") {
        edit_.error(kp, "unknown key (a footnote has text, causes, effects, modelled, not_modelled, origin)");
      }
    }
    if (!expressed && rec.not_modelled.empty())
      edit_.error(fp, "footnote " + rec.mark + ": say how the matrix expresses it (causes, effects) or why it cannot "
                      "(not_modelled)");
    cite_footnote(rec, fp, o);
    edit_.record_footnote(std::move(rec));
  }
}

// The legend's text in the notes of the intersections that cite the footnote.
void ParamsSections::cite_footnote(const model::FootnoteRecord& rec, const std::string& path,
                                   const std::string& origin) {
  int cited = 0;
  for (auto& x : edit_.doc()["intersections"]) {
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
    edit_.warn(path, "footnote " + rec.mark + " is cited by no intersection of the matrix");
  else
    edit_.record_policy({"footnote " + rec.mark + " (" + std::to_string(cited) +
                             (cited == 1 ? " intersection)" : " intersections)"),
                         "note", Json(rec.mark + " " + rec.text).dump(), Json(rec.mark).dump(), origin});
}

}  // namespace cemv::formats::params
