#include "diff/print.hpp"

#include <sstream>

#include <nlohmann/json.hpp>

#include "diff/print_words.hpp"

namespace cemv::diff {

using checker::EquivalenceVerdict;

std::string value_text(model::FieldType t, int v) {
  if (t == model::FieldType::Voting) return model::to_string(static_cast<model::Voting>(v));
  return std::to_string(v);
}

// One line per behaviour verdict of an effect, the words an assessor reads.
std::string behaviour_words(const EffectBehaviour& e) {
  switch (e.result.verdict) {
    case EquivalenceVerdict::Equivalent:
      return e.structurally_changed ? "changed, behaviour equivalent" : "unchanged, behaviour equivalent";
    case EquivalenceVerdict::Differs:
      if (!e.new_id) return "removed";
      if (!e.old_id) return "added";
      return "behaviour changed";
    case EquivalenceVerdict::Unknown: return "undecided (" + e.result.reason + ")";
  }
  return "";
}

std::string effect_label(const EffectBehaviour& e) {
  return "effect[" + std::to_string(e.new_id ? e.new_id : e.old_id) + "] " + e.name;
}

std::string change_line(const ElementChange& c) {
  std::string s = std::string(c.critical() ? "critical     " : "non-critical ") + to_string(c.kind) + " " + c.label();
  if (c.kind == ChangeKind::Moved)
    s += " (number " + std::to_string(c.old_id) + " -> " + std::to_string(c.new_id) + ")";
  return s;
}

std::string field_line(const FieldChange& f) {
  return f.field + ": " + (f.old_value.empty() ? "(none)" : f.old_value) + " -> " +
         (f.new_value.empty() ? "(none)" : f.new_value) + (f.critical ? "" : "  [non-critical]");
}

std::string distinction_text(const checker::Distinction& d) {
  return d.key + " in cycle " + std::to_string(d.cycle + 1) + ": OLD " + value_text(d.type, d.value_a) + ", NEW " +
         value_text(d.type, d.value_b);
}

std::string scenario_of(const DiffReport& r, const std::string& group) {
  for (const auto& [g, f] : r.scenarios)
    if (g == group) return f;
  return "";
}

namespace {

using json = nlohmann::ordered_json;

std::string join_ints(const std::set<int>& s, const char* prefix) {
  std::string out;
  for (int i : s) out += (out.empty() ? "" : ", ") + std::string(prefix) + std::to_string(i);
  return out.empty() ? "none" : out;
}

std::string html_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

std::string impact_effects_text(const DiffReport& r) {
  std::string out;
  for (const auto& e : r.behaviour.effects)
    if (e.behaviour_changed())
      out += (out.empty() ? "" : ", ") + effect_label(e) + " (" + behaviour_words(e) + ")";
  return out.empty() ? "none" : out;
}

std::string retest_line(const DiffReport& r) {
  const RetestScope s = retest_scope(r.behaviour);
  return std::string(s.partial ? "partial retest: " : "retest the whole matrix: ") + s.reason;
}

}  // namespace

int DiffReport::exit_code() const {
  if (!not_compared.empty()) return 2;
  if (behaviour.any_changed()) return 1;
  if (behaviour.any_unknown()) return 3;
  return 0;
}

std::string DiffReport::verdict() const {
  switch (exit_code()) {
    case 2:
      return "behaviour not compared: a matrix with validation errors cannot be executed; the structural "
             "comparison above is complete";
    case 1: return "behaviour changed: retest the impacted effects";
    case 3: return "undecided: some effect's behaviour was not decided within the time limit";
    default:
      return structure.empty() ? "no change" : "no behaviour changed: only non-critical or behaviour-equivalent edits";
  }
}

std::string to_text(const DiffReport& r) {
  std::ostringstream o;
  o << "cemv diff\n";
  o << "OLD " << r.old_file << "  " << r.old_m->name << "  signature " << r.old_signature << "\n";
  o << "NEW " << r.new_file << "  " << r.new_m->name << "  signature " << r.new_signature << "\n\n";
  o << "Structural comparison: " << r.structure.changes.size() << " change(s)"
    << (r.structure.any_critical() ? ", critical" : "") << "\n";
  for (const auto& c : r.structure.changes) {
    o << "  " << change_line(c) << "\n";
    for (const auto& f : c.fields) o << "      " << field_line(f) << "\n";
  }
  if (!r.not_compared.empty()) {
    o << "\nSemantic comparison: not given. A matrix with validation errors cannot be executed or encoded, so "
         "no behaviour is compared; fix these errors (cemv validate) and compare again:\n";
    for (const auto& line : r.not_compared) o << "  " << line << "\n";
    o << "\n" << r.verdict() << "\n";
    return o.str();
  }
  o << "\nSemantic comparison, per effect:\n";
  for (const auto& e : r.behaviour.effects) {
    o << "  " << effect_label(e) << ": " << behaviour_words(e);
    if (!e.result.method.empty()) o << " [" << e.result.method << "]";
    o << "\n";
    if (e.result.verdict == EquivalenceVerdict::Differs && !e.result.reason.empty())
      o << "      " << e.result.reason << "\n";
    if (e.result.distinction) {
      o << "      shortest difference: " << distinction_text(*e.result.distinction) << "\n";
      std::string f = scenario_of(r, e.result.group);
      if (!f.empty()) o << "      scenario: " << f << "\n";
    }
    for (const auto& out : e.outputs)
      o << "      " << out.group << ": " << to_string(out.verdict)
        << (out.distinction ? " (" + distinction_text(*out.distinction) + ")" : "") << "\n";
  }
  const auto& im = r.behaviour.impact;
  o << "\nImpact set:\n";
  std::set<int> effects(im.effects.begin(), im.effects.end());
  o << "  effects: " << join_ints(effects, "") << "\n";
  o << "  causes: " << join_ints(im.causes, "") << "\n";
  std::string tags;
  for (const auto& t : im.tags) tags += (tags.empty() ? "" : ", ") + t;
  o << "  tags: " << (tags.empty() ? "none" : tags) << "\n";
  o << "  SIF groups: " << join_ints(im.sif_groups, "") << "\n";
  o << "\nRetest (manual 12): " << retest_line(r) << "\n";
  o << "\n" << r.verdict() << "\n";
  return o.str();
}

std::string to_markdown(const DiffReport& r) {
  std::ostringstream o;
  o << "# Change comparison: " << r.old_m->name << "\n\n";
  o << "| | file | signature |\n| --- | --- | --- |\n";
  o << "| OLD | `" << r.old_file << "` | `" << r.old_signature << "` |\n";
  o << "| NEW | `" << r.new_file << "` | `" << r.new_signature << "` |\n\n";
  o << "**" << r.verdict() << "**\n\n## Structural comparison\n\n";
  if (r.structure.empty()) o << "No change.\n";
  else {
    o << "| class | change | element | fields |\n| --- | --- | --- | --- |\n";
    for (const auto& c : r.structure.changes) {
      std::string fields;
      for (const auto& f : c.fields) fields += (fields.empty() ? "" : "<br>") + field_line(f);
      if (c.kind == ChangeKind::Moved)
        fields = "number " + std::to_string(c.old_id) + " -> " + std::to_string(c.new_id) +
                 (fields.empty() ? "" : "<br>" + fields);
      o << "| " << (c.critical() ? "critical" : "non-critical") << " | " << to_string(c.kind) << " | " << c.label()
        << " | " << fields << " |\n";
    }
  }
  if (!r.not_compared.empty()) {
    o << "\n## Semantic comparison\n\nNot given: a matrix with validation errors cannot be executed or encoded, "
         "so no behaviour is compared. Fix these errors (`cemv validate`) and compare again:\n\n";
    for (const auto& line : r.not_compared) o << "- " << line << "\n";
    return o.str();
  }
  o << "\n## Semantic comparison\n\n| effect | behaviour | method | shortest difference |\n| --- | --- | --- | --- |\n";
  for (const auto& e : r.behaviour.effects) {
    std::string diff = e.result.distinction ? distinction_text(*e.result.distinction) : e.result.reason;
    std::string f = scenario_of(r, e.result.group);
    if (!f.empty()) diff += " (`" + f + "`)";
    o << "| " << effect_label(e) << " | " << behaviour_words(e) << " | " << e.result.method << " | " << diff << " |\n";
  }
  const auto& im = r.behaviour.impact;
  std::set<int> effects(im.effects.begin(), im.effects.end());
  o << "\n## Impact set\n\n- effects: " << join_ints(effects, "") << "\n- causes: " << join_ints(im.causes, "")
    << "\n- tags: ";
  std::string tags;
  for (const auto& t : im.tags) tags += (tags.empty() ? "" : ", ") + t;
  o << (tags.empty() ? "none" : tags) << "\n- SIF groups: " << join_ints(im.sif_groups, "") << "\n";
  o << "\n## Retest (manual 12)\n\n" << retest_line(r) << ".\n";
  return o.str();
}

std::string to_html(const DiffReport& r) {
  // The Markdown's content as one self-contained, printable page.
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>cemv diff "
    << html_escape(r.old_m->name) << "</title>\n<style>body{font-family:sans-serif;margin:2em}"
    << "table{border-collapse:collapse}td,th{border:1px solid #888;padding:2px 6px;text-align:left;vertical-align:top}"
    << ".critical{color:#a00}code{font-size:90%}</style></head><body>\n";
  o << "<h1>Change comparison: " << html_escape(r.old_m->name) << "</h1>\n<table><tr><th></th><th>file</th><th>"
    << "signature</th></tr>\n<tr><td>OLD</td><td>" << html_escape(r.old_file) << "</td><td><code>"
    << r.old_signature << "</code></td></tr>\n<tr><td>NEW</td><td>" << html_escape(r.new_file)
    << "</td><td><code>" << r.new_signature << "</code></td></tr></table>\n";
  o << "<p><strong>" << html_escape(r.verdict()) << "</strong></p>\n<h2>Structural comparison</h2>\n";
  o << "<table><tr><th>class</th><th>change</th><th>element</th><th>fields</th></tr>\n";
  for (const auto& c : r.structure.changes) {
    std::string fields;
    for (const auto& f : c.fields) fields += (fields.empty() ? "" : "<br>") + html_escape(field_line(f));
    o << "<tr><td" << (c.critical() ? " class=\"critical\">critical" : ">non-critical") << "</td><td>"
      << to_string(c.kind) << "</td><td>" << html_escape(c.label()) << "</td><td>" << fields << "</td></tr>\n";
  }
  if (!r.not_compared.empty()) {
    o << "</table>\n<h2>Semantic comparison</h2>\n<p>Not given: a matrix with validation errors cannot be executed "
         "or encoded, so no behaviour is compared. Fix these errors (<code>cemv validate</code>) and compare "
         "again:</p>\n<ul>\n";
    for (const auto& line : r.not_compared) o << "<li>" << html_escape(line) << "</li>\n";
    o << "</ul>\n</body></html>\n";
    return o.str();
  }
  o << "</table>\n<h2>Semantic comparison</h2>\n<table><tr><th>effect</th><th>behaviour</th><th>method</th>"
    << "<th>shortest difference</th></tr>\n";
  for (const auto& e : r.behaviour.effects) {
    std::string diff = e.result.distinction ? distinction_text(*e.result.distinction) : e.result.reason;
    std::string f = scenario_of(r, e.result.group);
    if (!f.empty()) diff += " (" + f + ")";
    o << "<tr><td" << (e.behaviour_changed() ? " class=\"critical\"" : "") << ">" << html_escape(effect_label(e)) << "</td><td>" << html_escape(behaviour_words(e)) << "</td><td>"
      << html_escape(e.result.method) << "</td><td>" << html_escape(diff) << "</td></tr>\n";
  }
  const auto& im = r.behaviour.impact;
  std::set<int> effects(im.effects.begin(), im.effects.end());
  std::string tags;
  for (const auto& t : im.tags) tags += (tags.empty() ? "" : ", ") + t;
  o << "</table>\n<h2>Impact set</h2>\n<ul><li>effects: " << join_ints(effects, "") << "</li><li>causes: "
    << join_ints(im.causes, "") << "</li><li>tags: " << html_escape(tags.empty() ? "none" : tags)
    << "</li><li>SIF groups: " << join_ints(im.sif_groups, "") << "</li></ul>\n<h2>Retest (manual 12)</h2>\n<p>"
    << html_escape(retest_line(r)) << ".</p>\n</body></html>\n";
  return o.str();
}

std::string to_json(const DiffReport& r) {
  json j;
  j["format"] = kDiffFormat;
  j["old"] = json{{"file", r.old_file}, {"name", r.old_m->name}, {"signature", r.old_signature}};
  j["new"] = json{{"file", r.new_file}, {"name", r.new_m->name}, {"signature", r.new_signature}};
  j["exit_code"] = r.exit_code();
  j["verdict"] = r.verdict();
  json changes = json::array();
  for (const auto& c : r.structure.changes) {
    json x;
    const char* el = c.element == ElementChange::Element::Matrix  ? "matrix"
                     : c.element == ElementChange::Element::Cause ? "cause"
                     : c.element == ElementChange::Element::Effect ? "effect"
                                                                   : "intersection";
    x["element"] = el;
    x["change"] = to_string(c.kind);
    x["critical"] = c.critical();
    x["label"] = c.label();
    if (c.element == ElementChange::Element::Intersection) {
      x["old"] = c.old_id ? json{{"cause", c.old_id}, {"effect", c.old_effect}} : json();
      x["new"] = c.new_id ? json{{"cause", c.new_id}, {"effect", c.new_effect}} : json();
    } else if (c.element != ElementChange::Element::Matrix) {
      x["old_id"] = c.old_id ? json(c.old_id) : json();
      x["new_id"] = c.new_id ? json(c.new_id) : json();
      x["name"] = c.name;
    }
    json fields = json::array();
    for (const auto& f : c.fields)
      fields.push_back(json{{"field", f.field},
                            {"old", f.old_value.empty() ? json() : json::parse(f.old_value)},
                            {"new", f.new_value.empty() ? json() : json::parse(f.new_value)},
                            {"critical", f.critical}});
    x["fields"] = fields;
    changes.push_back(x);
  }
  j["structural"] = json{{"critical", r.structure.any_critical()}, {"changes", changes}};
  j["behaviour_not_compared"] = r.not_compared;  // empty when the behaviour was compared
  auto group_json = [&](const checker::GroupEquivalence& g) {
    json x;
    x["group"] = g.group;
    x["verdict"] = checker::to_string(g.verdict);
    x["method"] = g.method;
    if (!g.reason.empty()) x["reason"] = g.reason;
    if (g.distinction) {
      const auto& d = *g.distinction;
      x["distinction"] = json{{"key", d.key},
                              {"cycle", d.cycle + 1},
                              {"old", value_text(d.type, d.value_a)},
                              {"new", value_text(d.type, d.value_b)}};
      std::string f = scenario_of(r, g.group);
      if (!f.empty()) x["distinction"]["scenario"] = f;
    }
    return x;
  };
  json effects = json::array();
  for (const auto& e : r.behaviour.effects) {
    json x = group_json(e.result);
    x["old_id"] = e.old_id ? json(e.old_id) : json();
    x["new_id"] = e.new_id ? json(e.new_id) : json();
    x["name"] = e.name;
    x["behaviour"] = behaviour_words(e);
    x["structurally_changed"] = e.structurally_changed;
    json outs = json::array();
    for (const auto& g : e.outputs) outs.push_back(group_json(g));
    x["outputs"] = outs;
    effects.push_back(x);
  }
  j["semantic"] = json{{"relabelled", r.behaviour.relabelled}, {"effects", effects}};
  const auto& im = r.behaviour.impact;
  j["impact"] = json{{"effects", im.effects},
                     {"causes", json(std::vector<int>(im.causes.begin(), im.causes.end()))},
                     {"tags", json(std::vector<std::string>(im.tags.begin(), im.tags.end()))},
                     {"sif_groups", json(std::vector<int>(im.sif_groups.begin(), im.sif_groups.end()))}};
  const RetestScope scope = retest_scope(r.behaviour);
  j["retest"] = json{{"scope", scope.partial ? "partial" : "whole"}, {"reason", scope.reason}};
  return j.dump(1) + "\n";
}

std::string change_preface_markdown(const DiffReport& r) {
  std::ostringstream o;
  o << "## The change\n\nCompared with the accepted version `" << r.old_file << "` (signature `" << r.old_signature
    << "`), docs/change-acceptance.md.\n\n";
  if (r.structure.empty()) o << "No structural change.\n";
  for (const auto& c : r.structure.changes) {
    o << "- " << (c.critical() ? "critical" : "non-critical") << ": " << to_string(c.kind) << " " << c.label();
    if (c.kind == ChangeKind::Moved) o << " (number " << c.old_id << " -> " << c.new_id << ")";
    o << "\n";
    for (const auto& f : c.fields) o << "  - " << field_line(f) << "\n";
  }
  o << "\nBehaviour changed: " << impact_effects_text(r) << ".\n\n**" << retest_line(r) << ".**\n\n";
  return o.str();
}

std::string change_preface_html(const DiffReport& r) {
  std::ostringstream o;
  o << "<h2>The change</h2>\n<p>Compared with the accepted version <code>" << html_escape(r.old_file)
    << "</code> (signature <code>" << r.old_signature << "</code>).</p>\n<ul>\n";
  if (r.structure.empty()) o << "<li>No structural change.</li>\n";
  for (const auto& c : r.structure.changes) {
    o << "<li>" << (c.critical() ? "critical" : "non-critical") << ": " << to_string(c.kind) << " "
      << html_escape(c.label());
    if (c.kind == ChangeKind::Moved) o << " (number " << c.old_id << " -&gt; " << c.new_id << ")";
    for (const auto& f : c.fields) o << "<br>" << html_escape(field_line(f));
    o << "</li>\n";
  }
  o << "</ul>\n<p>Behaviour changed: " << html_escape(impact_effects_text(r)) << ".</p>\n<p><strong>"
    << html_escape(retest_line(r)) << ".</strong></p>\n";
  return o.str();
}

std::vector<std::string> change_preface_lines(const DiffReport& r) {
  std::vector<std::string> out{"changed from " + r.old_file + " signature " + r.old_signature};
  for (const auto& c : r.structure.changes) {
    std::string line = std::string(c.critical() ? "critical: " : "non-critical: ") + to_string(c.kind) + " " + c.label();
    for (const auto& f : c.fields) line += "; " + field_line(f);
    out.push_back(line);
  }
  out.push_back("behaviour changed: " + impact_effects_text(r));
  out.push_back(retest_line(r));
  return out;
}

}  // namespace cemv::diff
