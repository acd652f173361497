#include "formats/matrix_extras.hpp"

#include <algorithm>
#include <charconv>

#include <nlohmann/json.hpp>

#include "formats/diagnostics.hpp"
#include "formats/matrix_json.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats {

namespace {

using Json = nlohmann::ordered_json;

bool starts(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }
bool ends(std::string_view s, std::string_view p) { return s.size() >= p.size() && s.substr(s.size() - p.size()) == p; }

bool number(std::string_view s, int& out) {
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc{} && end == s.data() + s.size() && !s.empty();
}

// "cause.3.tag.2.simulation_allowed" -> kind "cause", id 3, position 2.
bool simulation_key(std::string_view key, std::string& kind, int& id, int& position) {
  const std::string_view suffix = ".simulation_allowed";
  for (const char* k : {"cause.", "effect."}) {
    if (!starts(key, k) || !ends(key, suffix)) continue;
    std::string_view mid = key.substr(std::string_view(k).size(), key.size() - std::string_view(k).size() - suffix.size());
    std::size_t dot = mid.find(".tag.");
    if (dot == std::string_view::npos) return false;
    kind = std::string(k).substr(0, std::string(k).size() - 1);
    return number(mid.substr(0, dot), id) && number(mid.substr(dot + 5), position);
  }
  return false;
}

// One provenance record through the matrix format: written and read by the
// one canonical writer and loader, inside a minimal matrix.
std::string record_json(const model::Matrix& m, bool import, std::size_t k) {
  model::Matrix one;
  one.name = "X";
  if (import) one.provenance.imports.push_back(m.provenance.imports[k]);
  else one.provenance.parameters.push_back(m.provenance.parameters[k]);
  Json j = Json::parse(to_canonical_json(one));
  return j["provenance"][import ? "imports" : "parameters"][0].dump();
}

}  // namespace

std::vector<ExtraProperty> extra_properties(const model::Matrix& m) {
  std::vector<ExtraProperty> out;
  std::vector<std::pair<std::string, std::string>> tags;
  for (const auto& [tag, text] : m.tag_descriptions) tags.emplace_back(model::tag_key(tag), tag);
  std::sort(tags.begin(), tags.end());
  for (const auto& [key, tag] : tags) out.push_back({"tag." + tag + ".description", m.tag_descriptions.at(tag)});
  for (const auto& c : m.causes)
    for (std::size_t k = 0; k < c.tags.size(); ++k)
      if (!c.tags[k].simulation_allowed)
        out.push_back({"cause." + std::to_string(c.id) + ".tag." + std::to_string(k + 1) + ".simulation_allowed", "false"});
  for (const auto& e : m.effects)
    for (std::size_t k = 0; k < e.tags.size(); ++k)
      if (!e.tags[k].simulation_allowed)
        out.push_back({"effect." + std::to_string(e.id) + ".tag." + std::to_string(k + 1) + ".simulation_allowed", "false"});
  for (std::size_t k = 0; k < m.provenance.imports.size(); ++k)
    out.push_back({"provenance.import." + std::to_string(k + 1), record_json(m, true, k)});
  for (std::size_t k = 0; k < m.provenance.parameters.size(); ++k)
    out.push_back({"provenance.parameters." + std::to_string(k + 1), record_json(m, false, k)});
  return out;
}

bool is_extra_property(std::string_view key) {
  std::string kind;
  int id = 0, position = 0;
  return (starts(key, "tag.") && ends(key, ".description") && key.size() > 16) ||
         simulation_key(key, kind, id, position) || starts(key, "provenance.import.") ||
         starts(key, "provenance.parameters.");
}

std::vector<std::pair<std::size_t, std::string>> apply_extra_properties(model::Matrix& m,
                                                                        const std::vector<ExtraProperty>& rows) {
  std::vector<std::pair<std::size_t, std::string>> problems;
  std::vector<std::pair<int, std::size_t>> imports, parameters;  // (K, row)
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string& key = rows[i].key;
    std::string kind;
    int id = 0, position = 0;
    if (starts(key, "tag.") && ends(key, ".description")) {
      m.tag_descriptions[key.substr(4, key.size() - 4 - 12)] = rows[i].value;
    } else if (simulation_key(key, kind, id, position)) {
      if (rows[i].value != "false") {
        problems.push_back({i, key + ": '" + rows[i].value + "' is not false (only a forbidden simulation is written)"});
        continue;
      }
      bool found = false;
      if (kind == "cause")
        for (auto& c : m.causes)
          if (c.id == id && position >= 1 && position <= static_cast<int>(c.tags.size()))
            found = true, c.tags[static_cast<std::size_t>(position - 1)].simulation_allowed = false;
      if (kind == "effect")
        for (auto& e : m.effects)
          if (e.id == id && position >= 1 && position <= static_cast<int>(e.tags.size()))
            found = true, e.tags[static_cast<std::size_t>(position - 1)].simulation_allowed = false;
      if (!found) problems.push_back({i, key + ": no " + kind + " " + std::to_string(id) + " with a tag " +
                                             std::to_string(position)});
    } else {
      const bool import = starts(key, "provenance.import.");
      int k = 0;
      if (!number(std::string_view(key).substr(import ? 18 : 22), k) || k < 1) {
        problems.push_back({i, key + ": expected provenance.import.K or provenance.parameters.K, K = 1, 2, ..."});
        continue;
      }
      (import ? imports : parameters).push_back({k, i});
    }
  }
  // The records, in their order, through the matrix loader.
  for (bool import : {true, false}) {
    auto& list = import ? imports : parameters;
    std::sort(list.begin(), list.end());
    for (std::size_t n = 0; n < list.size(); ++n) {
      const std::size_t row = list[n].second;
      if (list[n].first != static_cast<int>(n + 1)) {
        problems.push_back({row, rows[row].key + ": records are numbered 1, 2, ... without gaps or repeats"});
        continue;
      }
      std::string text = std::string("{\"format\": \"cemv-matrix/1\", \"name\": \"X\", \"provenance\": {\"") +
                         (import ? "imports" : "parameters") + "\": [" + rows[row].value + "]}}";
      try {
        model::Matrix one = parse_matrix(text, rows[row].key);
        if (import) m.provenance.imports.push_back(one.provenance.imports.at(0));
        else m.provenance.parameters.push_back(one.provenance.parameters.at(0));
      } catch (const LoadError& e) {
        problems.push_back({row, rows[row].key + ": not a provenance record: " + e.issues().front().str()});
      }
    }
  }
  return problems;
}

}  // namespace cemv::formats
