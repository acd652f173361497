// The sections of the configuration report (manual section 11.4), in the
// order the manual lists them, as blocks of the document.
#include "reports/config_document.hpp"

#include <algorithm>
#include <optional>

#include "formats/matrix_json.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::reports::config {

using namespace cemv::model;
using namespace cemv::formats;

namespace {

// Appends item to a separated list (not `s += (s.empty() ? "" : sep) + item`,
// which trips GCC 12's -Wrestrict false positive at -O3).
void join_to(std::string& list, std::string_view separator, const std::string& item) {
  if (!list.empty()) list += separator;
  list += item;
}


std::string yes_no(bool b) { return b ? "yes" : "no"; }
Text tag_or_none(const std::optional<std::string>& s) { return s ? code(*s) : plain("none"); }

std::string sif_list(const std::vector<int>& sif) {
  if (sif.empty()) return "none";
  std::string out;
  for (int g : sif) join_to(out, ", ", std::to_string(g));
  return out;
}

// "S", "V 2oo3" (the X of XooN over the N intersections of that effect carrying xoon).
std::string cell_text(const Matrix& m, const Intersection& x) {
  std::string s = to_string(x.type);
  if (x.xoon) {
    int n = 0;
    for (const auto* y : m.intersections_of_effect(x.effect))
      if (y->xoon) ++n;
    s += " " + std::to_string(*x.xoon) + "oo" + std::to_string(n);
  }
  return s;
}

const char* type_meaning(const std::string& t) {
  if (t == "N") return "not stored (non-latching)";
  if (t == "S") return "stored (latching, reset needed)";
  if (t == "V") return "overridable";
  if (t == "R") return "resettable and overridable";
  if (t == "X") return "not yet specified (blocks transfer)";
  return "for note only (not processed)";
}

// ---- the content ------------------------------------------------------------------------

struct FieldRow {
  std::string field;
  Text value;
  std::string section;
};

Table field_table(const std::vector<FieldRow>& rows) {
  Table t;
  t.header = {"Field", "Value", "Manual"};
  for (const auto& r : rows) t.rows.push_back({code(r.field), r.value, plain(r.section)});
  return t;
}

std::vector<FieldRow> cause_fields_of(const Cause& c) {
  std::vector<FieldRow> r = {
      {"id", plain(std::to_string(c.id)), "6.3"},
      {"name", code(c.name), "6.3"},
      {"description", plain(c.description), "6.3"},
      {"sil", plain(c.sil ? std::to_string(c.sil) : "not stated"), "6.3"},
      {"input", plain(to_string(c.input)), "6.3.4"},
      {"function", plain(to_string(c.function)), "3.4, 6.3.1"},
  };
  if (c.analog) {
    const auto& a = *c.analog;
    r.push_back({"analog.limit_type", plain(to_string(a.limit_type)), "6.3.5"});
    r.push_back({"analog.limit", plain(float_text(a.limit)), "6.3.5"});
    r.push_back({"analog.hysteresis", plain(float_text(a.hysteresis)), "6.3.5"});
    r.push_back({"analog.prewarning", plain(a.prewarning ? float_text(*a.prewarning) : "none"), "6.3.5"});
    r.push_back({"analog.delta", plain(a.delta == 0.0f ? "0 (off)" : float_text(a.delta)), "6.3.5"});
    r.push_back({"analog.unit", plain(a.unit.empty() ? "none" : a.unit), "6.3.5"});
  } else {
    r.push_back({"analog", plain("none"), "6.3.5"});
  }
  r.push_back({"bad_quality", plain(to_string(c.bad_quality)), "6.1.6, 13.1.5"});
  r.push_back({"time.mode", plain(to_string(c.time.mode)), "6.3.6, 13.1.1"});
  r.push_back({"time.ms", plain(std::to_string(c.time.ms)), "6.3.6, 13.1.1"});
  r.push_back({"auto_ack", plain(yes_no(c.auto_ack)), "13.1.4"});
  r.push_back({"soft_bypass.allowed", plain(yes_no(c.soft_bypass.allowed)), "6.3.6"});
  r.push_back({"soft_bypass.max_s",
               plain(c.soft_bypass.max_s ? std::to_string(c.soft_bypass.max_s) : "0 (untimed)"), "6.3.6"});
  r.push_back({"soft_bypass.prealarm_s", plain(std::to_string(c.soft_bypass.prealarm_s)), "6.3.6"});
  r.push_back({"bypass_tag", tag_or_none(c.bypass_tag), "13.1.2"});
  r.push_back({"inhibit_tag", tag_or_none(c.inhibit_tag), "13.1.3"});
  r.push_back({"first_out_group",
               plain(c.first_out_group ? std::to_string(c.first_out_group) : "0 (none)"), "6.3"});
  r.push_back({"mutually_locked_maintenance", plain(yes_no(c.mutually_locked_maintenance)), "6.3"});
  r.push_back({"sif", plain(sif_list(c.sif)), "3.4"});
  r.push_back({"note", plain(c.note.empty() ? "none" : c.note), ""});
  return r;
}

std::vector<FieldRow> effect_fields_of(const Effect& e) {
  std::vector<FieldRow> r = {
      {"id", plain(std::to_string(e.id)), "6.4"},
      {"name", code(e.name), "6.4"},
      {"description", plain(e.description), "6.4"},
      {"sil", plain(e.sil ? std::to_string(e.sil) : "not stated"), "6.4"},
      {"function", plain(to_string(e.function)), "6.4.4"},
      {"output_delay_ms",
       plain(e.output_delay_ms ? std::to_string(e.output_delay_ms) : "0 (none)"), "6.4.5, 13.2.2"},
      {"soft_bypass_allowed", plain(yes_no(e.soft_bypass_allowed)), "6.4.5"},
      {"bypass_tag", tag_or_none(e.bypass_tag), "6.4.5"},
      {"reset_tag", tag_or_none(e.reset_tag), "6.4.5"},
  };
  if (e.override_time) {
    r.push_back({"override.max_s", plain(std::to_string(e.override_time->max_s)), "6.5.2"});
    r.push_back({"override.prealarm_s", plain(std::to_string(e.override_time->prealarm_s)), "6.5.2"});
  } else {
    r.push_back({"override", plain("none"), "6.5.2"});
  }
  if (e.process_data) {
    r.push_back({"process_data.tag", tag_or_none(e.process_data->tag), "6.4.5, 13.2.5"});
    r.push_back({"process_data.pass_through", plain(yes_no(e.process_data->pass_through)), "6.4.5, 13.2.5"});
    r.push_back({"process_data.mask_tag", tag_or_none(e.process_data->mask_tag), "6.4.5, 13.2.5"});
  } else {
    r.push_back({"process_data", plain("none"), "6.4.5, 13.2.5"});
  }
  r.push_back({"mutually_locked_maintenance", plain(yes_no(e.mutually_locked_maintenance)), "6.4"});
  r.push_back({"sif", plain(sif_list(e.sif)), "3.4"});
  r.push_back({"note", plain(e.note.empty() ? "none" : e.note), ""});
  return r;
}

// 1 Properties: the matrix-level fields (11.4).
void add_properties(Document& d, const Matrix& m) {
  d.h(2, "1 Properties", "properties");
  d.table(field_table({
      {"format", plain(kMatrixFormat), ""},
      {"name", code(m.name), "11.4"},
      {"title", plain(m.title.empty() ? "none" : m.title), "11.4"},
      {"cycle_ms", plain(std::to_string(m.cycle_ms)), "11.4, 13"},
      {"secure_write.enable_tag",
       m.secure_write ? code(m.secure_write->enable_tag) : plain("not configured"), "3.4"},
      {"group_deactivation.enable_tag",
       m.group_deactivation ? code(m.group_deactivation->enable_tag) : plain("not configured"), "6.1.7"},
      {"group_deactivation.set_tag",
       m.group_deactivation ? code(m.group_deactivation->set_tag) : plain("not configured"), "6.1.7"},
  }));
}

// 2 Size and usage: the limits of 3.4 and what the matrix uses.
void add_size_and_usage(Document& d, const Matrix& m, const Statistics& s) {
  d.h(2, "2 Size and usage", "size");
  {
    Table t;
    t.header = {"Element", "Configured", "Limit (3.4)"};
    t.rows.push_back({plain("Causes (rows)"), plain(std::to_string(m.causes.size())),
                      plain(std::to_string(kMaxCauses))});
    t.rows.push_back({plain("Effects (columns)"), plain(std::to_string(m.effects.size())),
                      plain(std::to_string(kMaxEffects))});
    t.rows.push_back({plain("Intersections"), plain(std::to_string(m.intersections.size())),
                      plain(std::to_string(kMaxIntersections))});
    t.rows.push_back({plain("Matrix size"),
                      plain(std::to_string(m.causes.size()) + " x " + std::to_string(m.effects.size())),
                      plain(std::to_string(kMaxCauses) + " x " + std::to_string(kMaxEffects))});
    d.table(t);
  }
  auto count_table = [&](const std::string& what, const std::map<std::string, int>& counts,
                         const std::vector<std::string>& order, bool meanings) {
    Table t;
    t.header = meanings ? std::vector<std::string>{what, "Meaning (6.5.2)", "Count"}
                        : std::vector<std::string>{what, "Count"};
    for (const auto& k : order) {
      std::vector<Text> row{code(k)};
      if (meanings) row.push_back(plain(type_meaning(k)));
      row.push_back(plain(std::to_string(counts.at(k))));
      t.rows.push_back(row);
    }
    d.table(t);
  };
  count_table("Intersection type", s.by_type, {"N", "S", "V", "R", "X", "*"}, true);
  count_table("Cause function type (3.4)", s.by_function, {"normal", "and", "or", "2oo3", "comment"}, false);
  count_table("Cause input (6.3.4)", s.by_input, {"discrete", "analog"}, false);
  count_table("Cause time response (13.1.1)", s.by_time, {"none", "on_delay", "off_delay", "timed"}, false);
  count_table("Cause bad quality handling (6.1.6)", s.by_bad_quality, {"ignore", "trip", "degrade"}, false);
  count_table("Effect function type (6.4.4)", s.by_effect_function, {"normal", "comment"}, false);
  {
    Table t;
    t.header = {"Tags", "Count"};
    auto row = [&](const std::string& what, std::size_t n) {
      t.rows.push_back({plain(what), plain(std::to_string(n))});
    };
    row("Cause input tags (1-3 per cause)", static_cast<std::size_t>(s.cause_tags));
    row("Effect output tags (1-4 per effect)", static_cast<std::size_t>(s.effect_tags));
    row("Internal references among the input tags (6.1.3)", static_cast<std::size_t>(s.internal_refs));
    row("Distinct external input tags the matrix reads", s.external_inputs);
    row("Cause bypass tags", static_cast<std::size_t>(s.bypass_tags));
    row("Cause inhibit tags", static_cast<std::size_t>(s.inhibit_tags));
    row("Effect bypass tags", static_cast<std::size_t>(s.effect_bypass_tags));
    row("Effect reset tags", static_cast<std::size_t>(s.reset_tags));
    row("Effects with an XooN assignment", static_cast<std::size_t>(s.xoon_effects));
    row("Intersections with a note", static_cast<std::size_t>(s.noted_intersections));
    row("First-out groups used", s.first_out_groups.size());
    row("SIF groups defined", m.sif_groups.size());
    d.table(t);
  }
}

// 3 Validation summary: the findings of 11.5.
void add_validation_summary(Document& d, const std::vector<Diagnostic>& diags) {
  std::size_t errors = 0, warnings = 0;
  for (const auto& x : diags) (x.severity == Severity::Error ? errors : warnings)++;
  d.h(2, "3 Validation summary", "validation");
  d.p("Plausibility check of 11.5 (cemv validate): " + std::to_string(errors) + " error(s), " +
      std::to_string(warnings) + " warning(s).");
  if (!diags.empty()) {
    Table t;
    t.header = {"Severity", "Rule", "Element", "Manual", "Message"};
    for (const auto& x : diags)
      t.rows.push_back({plain(x.severity == Severity::Error ? "error" : "warning"), code(x.rule),
                        plain(x.element), plain(x.section), plain(x.message)});
    d.table(t);
  }
}

// 4 SIF groups and their causes and effects.
void add_sif_groups(Document& d, const Matrix& m, const Statistics& s) {
  d.h(2, "4 SIF groups", "sif");
  {
    std::set<int> groups(s.sif_used);
    for (const auto& [g, name] : m.sif_groups) groups.insert(g);
    if (groups.empty()) {
      d.p("No safety instrumented function groups are configured.");
    } else {
      Table t;
      t.header = {"Group", "Name", "Causes", "Effects"};
      for (int g : groups) {
        std::string causes, effects;
        for (const auto& c : m.causes)
          for (int x : c.sif)
            if (x == g) join_to(causes, ", ", std::to_string(c.id) + " " + c.name);
        for (const auto& e : m.effects)
          for (int x : e.sif)
            if (x == g) join_to(effects, ", ", std::to_string(e.id) + " " + e.name);
        auto name = m.sif_groups.find(g);
        t.rows.push_back({plain(std::to_string(g)),
                          plain(name != m.sif_groups.end() ? name->second : "(not defined)"),
                          plain(causes.empty() ? "none" : causes), plain(effects.empty() ? "none" : effects)});
      }
      d.table(t);
    }
  }
}

// 5 First-out groups (6.3.4) and their causes.
void add_first_out_groups(Document& d, const Matrix& m, const Statistics& s) {
  d.h(2, "5 First-out groups", "first-out");
  if (s.first_out_groups.empty()) {
    d.p("No cause belongs to a first-out group.");
  } else {
    Table t;
    t.header = {"Group", "Causes"};
    for (int g : s.first_out_groups) {
      std::string causes;
      for (const auto& c : m.causes)
        if (c.first_out_group == g) join_to(causes, ", ", std::to_string(c.id) + " " + c.name);
      t.rows.push_back({plain(std::to_string(g)), plain(causes)});
    }
    d.table(t);
  }
}

// 6 Causes: every field, the input tags, the intersections.
void add_causes(Document& d, const Matrix& m) {
  d.h(2, "6 Causes", "causes");
  if (m.causes.empty()) d.p("No causes.");
  for (const auto& c : m.causes) {
    d.h(3, "Cause " + std::to_string(c.id) + ": " + c.name, "cause-" + std::to_string(c.id));
    d.table(field_table(cause_fields_of(c)));
    Table tags;
    tags.header = {"Tag", "Name", "Energize-to-trip (6.3.4)", "Soft bypass allowed (6.3.6)"};
    for (std::size_t k = 0; k < c.tags.size(); ++k)
      tags.rows.push_back({plain(std::to_string(k + 1)), code(c.tags[k].name), plain(yes_no(c.tags[k].ett)),
                           plain(yes_no(c.tags[k].soft_bypass_allowed))});
    if (tags.rows.empty()) d.p("No input tags.");
    else d.table(tags);
    std::string xs;
    for (const auto* x : m.intersections_of_cause(c.id)) {
      const Effect* e = m.find_effect(x->effect);
      join_to(xs, ", ", "effect " + std::to_string(x->effect) + " " + (e ? e->name : "?") + " (" +
                            cell_text(m, *x) + ")");
    }
    d.p("Intersections: " + (xs.empty() ? std::string("none") : xs) + ".");
  }
}

// 7 Effects: every field, the output tags, the intersections.
void add_effects(Document& d, const Matrix& m) {
  d.h(2, "7 Effects", "effects");
  if (m.effects.empty()) d.p("No effects.");
  for (const auto& e : m.effects) {
    d.h(3, "Effect " + std::to_string(e.id) + ": " + e.name, "effect-" + std::to_string(e.id));
    d.table(field_table(effect_fields_of(e)));
    Table tags;
    tags.header = {"Tag", "Name", "Energize-to-trip (6.4.4)"};
    for (std::size_t k = 0; k < e.tags.size(); ++k)
      tags.rows.push_back({plain(std::to_string(k + 1)), code(e.tags[k].name), plain(yes_no(e.tags[k].ett))});
    if (tags.rows.empty()) d.p("No output tags.");
    else d.table(tags);
    std::string xs;
    for (const auto* x : m.intersections_of_effect(e.id)) {
      const Cause* c = m.find_cause(x->cause);
      join_to(xs, ", ", "cause " + std::to_string(x->cause) + " " + (c ? c->name : "?") + " (" +
                            cell_text(m, *x) + ")");
    }
    d.p("Intersections: " + (xs.empty() ? std::string("none") : xs) + ".");
  }
}

// 8 Intersections: the grid (6.5.2), then the list with notes.
void add_intersections(Document& d, const Matrix& m) {
  d.h(2, "8 Intersections", "intersections");
  if (m.intersections.empty() || m.effects.empty() || m.causes.empty()) {
    d.p("No intersections.");
  } else {
    d.p("The grid: one row per cause, one column per effect (by id); a cell shows the "
        "intersection type (6.5.2) and, for an XooN assignment, XooN; '+' marks a note. "
        "The list below gives every intersection with its note.");
    Table grid;
    grid.grid = true;
    grid.header = {"Cause \\ Effect"};
    for (const auto& e : m.effects) grid.header.push_back(std::to_string(e.id) + " " + e.name);
    for (const auto& c : m.causes) {
      std::vector<Text> row{plain(std::to_string(c.id) + " " + c.name)};
      for (const auto& e : m.effects) {
        const Intersection* x = m.find_intersection(c.id, e.id);
        Text t;
        if (x) {
          t.text = cell_text(m, *x);
          if (!x->note.empty()) t.text += "+";
          std::string type = to_string(x->type);
          t.css = "t-" + std::string(type == "*" ? "note" : type);
        }
        row.push_back(t);
      }
      grid.rows.push_back(row);
    }
    d.table(grid);
    Table list;
    list.header = {"Cause", "Effect", "Type", "XooN", "Note"};
    for (const auto& x : m.intersections) {
      const Cause* c = m.find_cause(x.cause);
      const Effect* e = m.find_effect(x.effect);
      std::string xoon = "none";
      if (x.xoon) {
        std::string t = cell_text(m, x);
        xoon = t.substr(t.find(' ') + 1);
      }
      list.rows.push_back({plain(std::to_string(x.cause) + " " + (c ? c->name : "?")),
                           plain(std::to_string(x.effect) + " " + (e ? e->name : "?")),
                           code(to_string(x.type)), plain(xoon), plain(x.note.empty() ? "none" : x.note)});
    }
    d.table(list);
  }
}

// 9 User notes.
void add_user_notes(Document& d, const Matrix& m) {
  // 11.4 "List of user notes": every note in one place, so none is overlooked.
  d.h(2, "9 User notes", "notes");
  {
    Table t;
    t.header = {"Element", "Note"};
    for (const auto& c : m.causes)
      if (!c.note.empty()) t.rows.push_back({plain("cause " + std::to_string(c.id) + " " + c.name), plain(c.note)});
    for (const auto& e : m.effects)
      if (!e.note.empty()) t.rows.push_back({plain("effect " + std::to_string(e.id) + " " + e.name), plain(e.note)});
    for (const auto& x : m.intersections)
      if (!x.note.empty())
        t.rows.push_back({plain("intersection cause " + std::to_string(x.cause) + " / effect " +
                                std::to_string(x.effect)),
                          plain(x.note)});
    if (t.rows.empty()) d.p("No notes.");
    else d.table(t);
  }
}

// The closing line: the signature again, at the end.
void add_closing_signature(Document& d, const Matrix& m, const std::string& sig) {
  d.h(2, "Signature", "signature");
  d.p({plain("End of the configuration report of "), code(m.name), plain(". Matrix signature: "),
       code(sig)});
}

// The configuration report of 11.4, section by section.

}  // namespace

Document build(const Matrix& m, const std::string& sig, const std::vector<Diagnostic>& diags) {
  Document d;
  d.title = "Configuration report: " + m.name;
  const Statistics s = statistics(m);

  d.h(1, d.title);
  d.p({plain("Matrix signature (SHA-256 of the canonical form): "), code(sig)});
  d.p("Configuration report of manual section 11.4, written by cemv from the canonical form of "
      "the matrix. It carries no time stamp: the same matrix always gives the same report.");

  // An invalid matrix (11.5 errors) gets a banner and its validation section
  // first: the report is how an engineer sees what must be fixed.
  const std::size_t errors = static_cast<std::size_t>(std::count_if(
      diags.begin(), diags.end(), [](const Diagnostic& x) { return x.severity == Severity::Error; }));
  if (errors > 0) {
    d.h(2, "INVALID MATRIX: " + std::to_string(errors) + " validation error(s)", "invalid");
    d.p("This matrix has validation errors (manual section 11.5), listed in the validation summary "
        "that follows. cemv refuses to simulate, encode or check it until they are fixed.");
    add_validation_summary(d, diags);
  }
  add_properties(d, m);
  add_size_and_usage(d, m, s);
  if (errors == 0) add_validation_summary(d, diags);
  add_sif_groups(d, m, s);
  add_first_out_groups(d, m, s);
  add_causes(d, m);
  add_effects(d, m);
  add_intersections(d, m);
  add_user_notes(d, m);
  add_closing_signature(d, m, sig);
  return d;
}

}  // namespace cemv::reports::config
