#include "properties/names.hpp"

#include <algorithm>
#include <charconv>
#include <limits>

#include "model/text.hpp"

namespace cemv::properties {

namespace {

bool processed(const model::Cause& c) { return c.function != model::CauseFunction::Comment; }
bool processed(const model::Effect& e) { return e.function != model::EffectFunction::Comment; }

template <class Elements>
std::variant<int, std::string> find_element(const Elements& elements, const char* what,
                                            std::string_view id_or_name, bool is_number) {
  if (is_number) {
    int id = 0;
    auto [p, ec] = std::from_chars(id_or_name.data(), id_or_name.data() + id_or_name.size(), id);
    for (const auto& e : elements)
      if (ec == std::errc() && p == id_or_name.data() + id_or_name.size() && e.id == id) {
        if (!processed(e))
          return std::string(what) + " " + std::to_string(id) + " is comment-only (not processed)";
        return id;
      }
    return "no " + std::string(what) + " with id " + std::string(id_or_name);
  }
  std::vector<std::string> names;
  for (const auto& e : elements) {
    if (!processed(e)) continue;
    if (model::tag_key(e.name) == model::tag_key(id_or_name)) return e.id;
    names.push_back(e.name);
  }
  return "unknown " + std::string(what) + " " + in_quotes(id_or_name) + did_you_mean(id_or_name, names);
}

}  // namespace

std::string in_quotes(std::string_view text) { return model::in_quotes(text); }

std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates) {
  std::vector<std::string_view> views(candidates.begin(), candidates.end());
  return model::did_you_mean(word, views);
}

MatrixNames::MatrixNames(const model::Matrix& m) : m_(m), inputs_(m), observables_(model::observables(m)) {
  std::stable_sort(observables_.begin(), observables_.end(),
                   [](const auto& a, const auto& b) { return a.key < b.key; });
}

std::optional<model::Observable> MatrixNames::observable(const std::string& key) const {
  auto it = std::lower_bound(observables_.begin(), observables_.end(), key,
                             [](const model::Observable& o, const std::string& k) { return o.key < k; });
  if (it == observables_.end() || it->key != key) return std::nullopt;
  return *it;
}

std::variant<int, std::string> MatrixNames::cause(std::string_view id_or_name, bool is_number) const {
  return find_element(m_.causes, "cause", id_or_name, is_number);
}

std::variant<int, std::string> MatrixNames::effect(std::string_view id_or_name, bool is_number) const {
  return find_element(m_.effects, "effect", id_or_name, is_number);
}

std::variant<model::Observable, std::string> MatrixNames::cause_field(int id, std::string_view field) const {
  if (auto o = observable("cause[" + std::to_string(id) + "]." + std::string(field))) return *o;
  std::vector<std::string> names;
  for (const auto& f : model::cause_fields()) names.push_back(f.name);
  return "unknown cause field " + in_quotes(field) + did_you_mean(field, names);
}

std::variant<model::Observable, std::string> MatrixNames::effect_field(int id, std::string_view field) const {
  if (field != "tag")
    if (auto o = observable("effect[" + std::to_string(id) + "]." + std::string(field))) return *o;
  std::vector<std::string> names;
  for (const auto& f : model::effect_fields()) names.push_back(f.name);
  names.push_back("tag");
  return "unknown effect field " + in_quotes(field) + did_you_mean(field, names);
}

std::variant<model::Observable, std::string> MatrixNames::effect_tag(int id, long k) const {
  const model::Effect* e = m_.find_effect(id);
  long n = e ? static_cast<long>(e->tags.size()) : 0;
  if (k < 1 || k > n)
    return "effect " + std::to_string(id) + " has no tag[" + std::to_string(k) + "] (it has " +
           std::to_string(n) + (n == 1 ? " tag)" : " tags)");
  return *observable("effect[" + std::to_string(id) + "].tag[" + std::to_string(k) + "]");
}

std::variant<TagRef, std::string> MatrixNames::tag(std::string_view name) const {
  TagRef ref;
  ref.name = std::string(name);
  if (auto r = model::parse_internal_ref(name)) {
    std::string key = r->kind == model::InternalRef::Kind::Cause ? "cause[" + std::to_string(r->id) + "].active"
                      : r->kind == model::InternalRef::Kind::Effect
                          ? "effect[" + std::to_string(r->id) + "].active"
                          : "effect[" + std::to_string(r->id) + "].tag[" + std::to_string(r->tag) + "]";
    ref.value = observable(key);
    if (!ref.value) return "internal reference " + in_quotes(name) + " names no processed element";
    return ref;
  }
  if (auto i = inputs_.find(name)) {
    ref.name = inputs_.tags()[*i].name;
    ref.input = *i;
    return ref;
  }
  std::vector<std::string> names;
  for (const auto& t : inputs_.tags()) names.push_back(t.name);
  for (const auto& e : m_.effects) {
    for (std::size_t k = 0; k < e.tags.size(); ++k) {
      if (processed(e) && model::tag_key(e.tags[k].name) == model::tag_key(name)) {
        ref.name = e.tags[k].name;
        ref.value = std::get<model::Observable>(effect_tag(e.id, static_cast<long>(k) + 1));
        return ref;
      }
      names.push_back(e.tags[k].name);
    }
  }
  return "unknown tag " + in_quotes(name) + did_you_mean(name, names);
}

std::vector<Element> MatrixNames::all_causes() const {
  std::vector<Element> out;
  for (const auto& c : m_.causes)
    if (processed(c)) out.push_back({Element::Kind::Cause, c.id, {}});
  return out;
}

std::vector<Element> MatrixNames::all_effects() const {
  std::vector<Element> out;
  for (const auto& e : m_.effects)
    if (processed(e)) out.push_back({Element::Kind::Effect, e.id, {}});
  return out;
}

std::variant<std::vector<Element>, std::string> MatrixNames::sif_members(int group, bool causes) const {
  bool known = m_.sif_groups.count(group) > 0;
  std::vector<Element> out;
  auto in_group = [&](const std::vector<int>& sif) { return std::find(sif.begin(), sif.end(), group) != sif.end(); };
  if (causes) {
    for (const auto& c : m_.causes)
      if (in_group(c.sif)) {
        known = true;
        if (processed(c)) out.push_back({Element::Kind::Cause, c.id, {}});
      }
  } else {
    for (const auto& e : m_.effects)
      if (in_group(e.sif)) {
        known = true;
        if (processed(e)) out.push_back({Element::Kind::Effect, e.id, {}});
      }
  }
  if (!known) return "no SIF group " + std::to_string(group) + " in the matrix";
  return out;
}

std::variant<std::vector<Element>, std::string> MatrixNames::sif_causes(int group) const {
  return sif_members(group, true);
}

std::variant<std::vector<Element>, std::string> MatrixNames::sif_effects(int group) const {
  return sif_members(group, false);
}

std::vector<Element> MatrixNames::causes_of_effect(int effect) const {
  std::vector<Element> out;
  for (const auto* i : m_.intersections_of_effect(effect)) {
    const model::Cause* c = m_.find_cause(i->cause);
    if (c && processed(*c) && model::is_processed(i->type)) out.push_back({Element::Kind::Cause, c->id, {}});
  }
  return out;
}

std::vector<Element> MatrixNames::effects_of_cause(int cause) const {
  std::vector<Element> out;
  for (const auto* i : m_.intersections_of_cause(cause)) {
    const model::Effect* e = m_.find_effect(i->effect);
    if (e && processed(*e) && model::is_processed(i->type)) out.push_back({Element::Kind::Effect, e->id, {}});
  }
  return out;
}

std::vector<Element> MatrixNames::tags_of_cause(int cause) const {
  std::vector<Element> out;
  if (const model::Cause* c = m_.find_cause(cause))
    for (const auto& t : c->tags)
      if (auto ref = tag(t.name); std::holds_alternative<TagRef>(ref))
        out.push_back({Element::Kind::Tag, 0, std::get<TagRef>(ref)});
  return out;
}

std::vector<Element> MatrixNames::tags_of_effect(int effect) const {
  std::vector<Element> out;
  if (const model::Effect* e = m_.find_effect(effect))
    for (std::size_t k = 0; k < e->tags.size(); ++k) {
      TagRef ref;
      ref.name = e->tags[k].name;
      ref.value = std::get<model::Observable>(effect_tag(effect, static_cast<long>(k) + 1));
      out.push_back({Element::Kind::Tag, 0, ref});
    }
  return out;
}

}  // namespace cemv::properties
