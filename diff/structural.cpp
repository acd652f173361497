#include "diff/structural.hpp"

#include <algorithm>
#include <functional>
#include <set>

#include <nlohmann/json.hpp>

#include "formats/matrix_json.hpp"
#include "model/vocabulary.hpp"

namespace cemv::diff {

namespace {

using json = nlohmann::ordered_json;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Fields that no semantics reads (6.2.3 "formal changes, e.g. to user notes
// or display functions"): texts, SIL and SIF assignment, units.
bool non_critical(const std::string& element_kind, const std::string& path) {
  static const std::set<std::string> element{"name", "description", "note", "sil", "sif", "analog.unit"};
  static const std::set<std::string> matrix{"name", "title", "sif_groups", "tag_descriptions", "provenance"};
  if (element_kind == "matrix") {
    for (const auto& f : matrix)
      if (path == f || path.rfind(f + ".", 0) == 0) return true;
    return false;
  }
  return element.count(path) > 0;
}

// A provenance list as a reader compares it: the files it names, with the
// start of their SHA-256 (the records themselves are in the matrix).
std::string provenance_text(const json& records) {
  std::string out;
  if (!records.is_array()) return out;
  for (const auto& r : records) {
    std::string sha = r.value("sha256", "");
    out += (out.empty() ? "" : ", ") + r.value("file", std::string("?")) +
           (sha.empty() ? "" : " (sha256 " + sha.substr(0, 12) + "...)");
  }
  return out;
}

// Recursive field comparison of two canonical JSON objects.
void compare_json(const json& o, const json& n, const std::string& path, const std::string& kind,
                  std::vector<FieldChange>& out) {
  if (o == n) return;
  if (path == "provenance" && (o.is_null() || n.is_null())) {
    compare_json(o.is_null() ? json::object() : o, n.is_null() ? json::object() : n, path, kind, out);
    return;
  }
  if (path == "provenance.imports" || path == "provenance.parameters") {
    std::string a = provenance_text(o), b = provenance_text(n);
    if (a == b) b += " (the same files; what they record differs: values they replaced, warnings)";
    // Values are JSON text, as for every other field (cemv-diff/1 parses them).
    out.push_back({path, a.empty() ? "" : json(a).dump(), b.empty() ? "" : json(b).dump(), false});
    return;
  }
  if (o.is_object() && n.is_object() && path != "sif_groups") {
    std::set<std::string> keys;
    for (auto it = o.begin(); it != o.end(); ++it) keys.insert(it.key());
    for (auto it = n.begin(); it != n.end(); ++it) keys.insert(it.key());
    for (const auto& k : keys) {
      if (path.empty() && k == "id") continue;
      const std::string p = path.empty() ? k : path + "." + k;
      json a = o.contains(k) ? o[k] : json(), b = n.contains(k) ? n[k] : json();
      compare_json(a, b, p, kind, out);
    }
    return;
  }
  if (o.is_array() && n.is_array() && path == "tags") {
    for (std::size_t i = 0; i < std::max(o.size(), n.size()); ++i)
      compare_json(i < o.size() ? o[i] : json(), i < n.size() ? n[i] : json(),
                   path + "[" + std::to_string(i + 1) + "]", kind, out);
    return;
  }
  FieldChange f;
  f.field = path;
  f.old_value = o.is_null() ? "" : o.dump();
  f.new_value = n.is_null() ? "" : n.dump();
  std::string base = path.substr(0, path.find('['));
  f.critical = !non_critical(kind, base);
  out.push_back(std::move(f));
}

// A tag name with its internal reference renumbered by the maps.
std::string renumber_ref(const std::string& name, const std::map<int, int>& causes, const std::map<int, int>& effects) {
  auto r = model::parse_internal_ref(name);
  if (!r) return name;
  auto map = [](const std::map<int, int>& m, int id) {
    auto it = m.find(id);
    return it == m.end() ? id : it->second;
  };
  switch (r->kind) {
    case model::InternalRef::Kind::Cause: return "Cause[" + std::to_string(map(causes, r->id)) + "]";
    case model::InternalRef::Kind::Effect: return "Effect[" + std::to_string(map(effects, r->id)) + "]";
    case model::InternalRef::Kind::EffectTag:
      return "Effect[" + std::to_string(map(effects, r->id)) + "][" + std::to_string(r->tag) + "]";
  }
  return name;
}

void renumber_refs(model::Matrix& m, const std::map<int, int>& causes, const std::map<int, int>& effects) {
  auto fix = [&](std::string& s) { s = renumber_ref(s, causes, effects); };
  auto fix_opt = [&](std::optional<std::string>& s) {
    if (s) fix(*s);
  };
  for (auto& c : m.causes) {
    for (auto& t : c.tags) fix(t.name);
    fix_opt(c.bypass_tag);
    fix_opt(c.inhibit_tag);
  }
  for (auto& e : m.effects) {
    for (auto& t : e.tags) fix(t.name);
    fix_opt(e.bypass_tag);
    fix_opt(e.reset_tag);
    if (e.process_data) {
      fix_opt(e.process_data->tag);
      fix_opt(e.process_data->mask_tag);
    }
  }
  if (m.secure_write) fix(m.secure_write->enable_tag);
  if (m.group_deactivation) {
    fix(m.group_deactivation->enable_tag);
    fix(m.group_deactivation->set_tag);
  }
}

// Matching by name first (names unique on both sides, case-insensitive as
// 6.3.4 compares them), then by number among the rest.
template <class T>
std::map<int, int> match(const std::vector<T>& olds, const std::vector<T>& news) {
  std::map<std::string, int> on, nn;
  std::set<std::string> dup;
  for (const auto& x : olds)
    if (!on.emplace(lower(x.name), x.id).second) dup.insert(lower(x.name));
  for (const auto& x : news)
    if (!nn.emplace(lower(x.name), x.id).second) dup.insert(lower(x.name));
  std::map<int, int> m;
  std::set<int> used_new;
  for (const auto& [name, id] : on) {
    if (dup.count(name) || name.empty()) continue;
    auto it = nn.find(name);
    if (it == nn.end()) continue;
    m[id] = it->second;
    used_new.insert(it->second);
  }
  std::set<int> new_ids;
  for (const auto& x : news) new_ids.insert(x.id);
  for (const auto& x : olds)
    if (!m.count(x.id) && new_ids.count(x.id) && !used_new.count(x.id)) {
      m[x.id] = x.id;
      used_new.insert(x.id);
    }
  return m;
}

json element_json(const json& doc, const char* list, int id) {
  for (const auto& e : doc[list])
    if (e["id"] == id) return e;
  return json();
}

json intersection_json(const json& doc, int c, int e) {
  for (const auto& i : doc["intersections"])
    if (i["cause"] == c && i["effect"] == e) return i;
  return json();
}

}  // namespace

const char* to_string(ChangeKind k) {
  switch (k) {
    case ChangeKind::Added: return "added";
    case ChangeKind::Removed: return "removed";
    case ChangeKind::Changed: return "changed";
    case ChangeKind::Moved: return "moved";
    case ChangeKind::Unchanged: return "unchanged";
  }
  return "changed";
}

bool ElementChange::critical() const {
  if (kind == ChangeKind::Added || kind == ChangeKind::Removed || kind == ChangeKind::Moved) return true;
  return std::any_of(fields.begin(), fields.end(), [](const FieldChange& f) { return f.critical; });
}

std::string ElementChange::label() const {
  auto id = [&](const char* what, int o, int n) {
    std::string s = std::string(what) + "[" + std::to_string(n ? n : o) + "]";
    return s;
  };
  switch (element) {
    case Element::Matrix: return "matrix";
    case Element::Cause: return id("cause", old_id, new_id) + (name.empty() ? "" : " " + name);
    case Element::Effect: return id("effect", old_id, new_id) + (name.empty() ? "" : " " + name);
    case Element::Intersection:
      return "intersection " + id("cause", old_id, new_id) + "/" + id("effect", old_effect, new_effect);
  }
  return "";
}

bool StructuralDiff::any_critical() const {
  return std::any_of(changes.begin(), changes.end(), [](const ElementChange& c) { return c.critical(); });
}

namespace {

// Compares OLD and NEW element by element, over their canonical JSON, with
// OLD's references already in NEW's numbering.
class StructureComparer {
 public:
  StructureComparer(const model::Matrix& old_m, const model::Matrix& new_m, StructuralDiff& d)
      : old_m_(old_m), new_m_(new_m), d_(d) {
    // OLD with its references in NEW's numbering: a reference that follows
    // its moved element is not a change.
    model::Matrix old_r = old_m;
    renumber_refs(old_r, d.cause_map, d.effect_map);
    o_ = json::parse(formats::to_canonical_json(old_r));
    n_ = json::parse(formats::to_canonical_json(new_m));
  }

  void compare() {
    compare_matrix_fields();
    compare_elements("causes", ElementChange::Element::Cause, d_.cause_map, old_m_.causes, new_m_.causes);
    compare_elements("effects", ElementChange::Element::Effect, d_.effect_map, old_m_.effects, new_m_.effects);
    compare_intersections();
  }

 private:
  void compare_matrix_fields() {
    ElementChange mx;
    mx.element = ElementChange::Element::Matrix;
    json om = o_, nm = n_;
    for (const char* k : {"causes", "effects", "intersections"}) {
      om.erase(k);
      nm.erase(k);
    }
    compare_json(om, nm, "", "matrix", mx.fields);
    if (!mx.fields.empty()) d_.changes.push_back(mx);
  }

  // Causes or effects: removed, moved, changed, then added.
  template <class E>
  void compare_elements(const char* list, ElementChange::Element kind, const std::map<int, int>& map,
                        const std::vector<E>& olds, const std::vector<E>& news) {
    std::set<int> matched_new;
    for (const auto& x : olds) {
      ElementChange c;
      c.element = kind;
      c.old_id = x.id;
      c.name = x.name;
      auto it = map.find(x.id);
      if (it == map.end()) {
        c.kind = ChangeKind::Removed;
        d_.changes.push_back(c);
        continue;
      }
      c.new_id = it->second;
      matched_new.insert(it->second);
      compare_json(element_json(o_, list, x.id), element_json(n_, list, c.new_id), "",
                   kind == ElementChange::Element::Cause ? "cause" : "effect", c.fields);
      for (const auto& y : news)
        if (y.id == c.new_id) c.name = y.name;
      if (c.old_id != c.new_id) c.kind = ChangeKind::Moved;
      else if (!c.fields.empty()) c.kind = ChangeKind::Changed;
      else continue;
      d_.changes.push_back(c);
    }
    for (const auto& y : news) {
      if (matched_new.count(y.id)) continue;
      ElementChange c;
      c.element = kind;
      c.kind = ChangeKind::Added;
      c.new_id = y.id;
      c.name = y.name;
      d_.changes.push_back(c);
    }
  }

  static int mapped(const std::map<int, int>& m, int id) {
    auto it = m.find(id);
    return it == m.end() ? 0 : it->second;
  }

  // Intersections by their matched cells; a cell of an unmatched element is
  // added or removed with it.
  void compare_intersections() {
    std::set<std::pair<int, int>> seen_new;
    for (const auto& is : old_m_.intersections) {
      ElementChange c;
      c.element = ElementChange::Element::Intersection;
      c.old_id = is.cause;
      c.old_effect = is.effect;
      c.new_id = mapped(d_.cause_map, is.cause);
      c.new_effect = mapped(d_.effect_map, is.effect);
      const model::Intersection* other =
          c.new_id && c.new_effect ? new_m_.find_intersection(c.new_id, c.new_effect) : nullptr;
      if (!other) {
        c.kind = ChangeKind::Removed;
        c.new_id = c.new_effect = 0;
        d_.changes.push_back(c);
        continue;
      }
      seen_new.insert({other->cause, other->effect});
      json a = intersection_json(o_, is.cause, is.effect), b = intersection_json(n_, other->cause, other->effect);
      for (json* x : {&a, &b}) {
        x->erase("cause");
        x->erase("effect");
      }
      compare_json(a, b, "", "intersection", c.fields);
      if (c.fields.empty()) continue;
      c.kind = ChangeKind::Changed;
      d_.changes.push_back(c);
    }
    for (const auto& is : new_m_.intersections) {
      if (seen_new.count({is.cause, is.effect})) continue;
      ElementChange c;
      c.element = ElementChange::Element::Intersection;
      c.kind = ChangeKind::Added;
      c.new_id = is.cause;
      c.new_effect = is.effect;
      c.fields.push_back(FieldChange{"type", "", std::string("\"") + model::to_string(is.type) + "\"", true});
      d_.changes.push_back(c);
    }
  }

  const model::Matrix& old_m_;
  const model::Matrix& new_m_;
  StructuralDiff& d_;
  json o_, n_;
};

}  // namespace

StructuralDiff compare_structure(const model::Matrix& old_m, const model::Matrix& new_m) {
  StructuralDiff d;
  d.cause_map = match(old_m.causes, new_m.causes);
  d.effect_map = match(old_m.effects, new_m.effects);
  StructureComparer(old_m, new_m, d).compare();
  return d;
}

Relabelling relabel(const model::Matrix& new_m, const StructuralDiff& d, const model::Matrix& old_m) {
  Relabelling r;
  auto build = [](const std::map<int, int>& old_to_new, const auto& news, const auto& olds) {
    std::map<int, int> out;
    std::set<int> taken;
    for (const auto& [o, n] : old_to_new) {
      out[n] = o;
      taken.insert(o);
    }
    for (const auto& x : olds) taken.insert(x.id);
    int next = 1;
    for (const auto& y : news) {
      if (out.count(y.id)) continue;
      if (!taken.count(y.id)) {
        out[y.id] = y.id;
        taken.insert(y.id);
        continue;
      }
      while (taken.count(next)) ++next;
      out[y.id] = next;
      taken.insert(next);
    }
    return out;
  };
  r.cause_ids = build(d.cause_map, new_m.causes, old_m.causes);
  r.effect_ids = build(d.effect_map, new_m.effects, old_m.effects);
  r.matrix = new_m;
  for (auto& c : r.matrix.causes) c.id = r.cause_ids.at(c.id);
  for (auto& e : r.matrix.effects) e.id = r.effect_ids.at(e.id);
  for (auto& is : r.matrix.intersections) {
    is.cause = r.cause_ids.at(is.cause);
    is.effect = r.effect_ids.at(is.effect);
  }
  renumber_refs(r.matrix, r.cause_ids, r.effect_ids);
  r.matrix.sort_by_id();
  std::sort(r.matrix.intersections.begin(), r.matrix.intersections.end(),
            [](const model::Intersection& a, const model::Intersection& b) {
              return std::tie(a.cause, a.effect) < std::tie(b.cause, b.effect);
            });
  return r;
}

}  // namespace cemv::diff
