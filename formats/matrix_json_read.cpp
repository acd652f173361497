// cemv-matrix/1: reading the document, its tag descriptions and provenance
// (docs/format.md). Structural checks only; plausibility is model/validate.cpp.
#include "formats/matrix_json_reader.hpp"

#include <charconv>

#include "model/names.hpp"

namespace cemv::formats::matrix_json_detail {

// Entries of one provenance list or of the tag descriptions: more than any
// matrix of 3.4 needs (128 causes x 3 + 128 effects x 4 tags and the control tags).
constexpr std::size_t kMaxRecordEntries = 4096;

// A list of texts (warnings, defaults, limitations): one line each.
void read_texts(Reader& r, const InJson& j, const std::string& path, std::vector<std::string>& out) {
  read_array(r, j, path, out, kMaxRecordEntries, "the entries of a provenance list",
             [&](const InJson& v, const std::string& p, std::string& t) { return r.text(v, p, t); });
}

// `tag_descriptions`: [{"tag": NAME, "description": TEXT}], one entry per tag
// (names compare case-insensitively, 6.1.4).
void read_tag_descriptions(Reader& r, const InJson& j, const std::string& path, Matrix& m) {
  struct Entry {
    std::string tag, description;
  };
  std::vector<Entry> entries;
  read_array(r, j, path, entries, kMaxRecordEntries, "the tag descriptions of a matrix",
             [&](const InJson& v, const std::string& p, Entry& e) {
               bool named = false;
               r.object(v, p, {
                   {"tag", true, [&](const InJson& v2, const std::string& p2) { named = r.tag(v2, p2, e.tag); }},
                   {"description", true,
                    [&](const InJson& v2, const std::string& p2) { read_description(r, v2, p2, e.description); }},
               });
               return named;
             });
  std::map<std::string, std::string> by_key;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    auto [it, fresh] = by_key.emplace(tag_key(entries[i].tag), entries[i].tag);
    if (!fresh) {
      r.error(element_path(path, i), "tag " + in_quotes(entries[i].tag) + " is described twice (also as " +
                                         in_quotes(it->second) + "; tag names compare case-insensitively, 6.1.4)");
      continue;
    }
    m.tag_descriptions[entries[i].tag] = entries[i].description;
  }
}

void read_provenance(Reader& r, const InJson& j, const std::string& path, Provenance& out) {
  auto str = [&](std::string& field) {
    return [&r, &field](const InJson& v, const std::string& p) { r.text(v, p, field); };
  };
  r.object(j, path, {
      {"imports", false,
       [&](const InJson& v, const std::string& p) {
         read_array(r, v, p, out.imports, kMaxRecordEntries, "the import records of a matrix",
                    [&](const InJson& e, const std::string& ep, ImportRecord& rec) {
                      return r.object(e, ep, {
                          {"file", true, str(rec.file)},
                          {"sha256", false, str(rec.sha256)},
                          {"reader", false, str(rec.reader)},
                          {"encoding", false, str(rec.encoding)},
                          {"summary", false, str(rec.summary)},
                          {"warnings", false,
                           [&](const InJson& v2, const std::string& p2) { read_texts(r, v2, p2, rec.warnings); }},
                          {"defaults", false,
                           [&](const InJson& v2, const std::string& p2) { read_texts(r, v2, p2, rec.defaults); }},
                      });
                    });
       }},
      {"parameters", false,
       [&](const InJson& v, const std::string& p) {
         read_array(r, v, p, out.parameters, kMaxRecordEntries, "the parameter records of a matrix",
                    [&](const InJson& e, const std::string& ep, ParameterRecord& rec) {
                      return r.object(e, ep, {
                          {"file", true, str(rec.file)},
                          {"sha256", false, str(rec.sha256)},
                          {"origin", false, str(rec.origin)},
                          {"values", false,
                           [&](const InJson& v2, const std::string& p2) {
                             read_array(r, v2, p2, rec.values, kMaxRecordEntries, "the values of a parameters file",
                                        [&](const InJson& x, const std::string& xp, ParameterValue& pv) {
                                          return r.object(x, xp, {
                                              {"element", true, str(pv.element)},
                                              {"field", true, str(pv.field)},
                                              {"value", true, str(pv.value)},
                                              {"previous", false, str(pv.previous)},
                                              {"origin", false, str(pv.origin)},
                                          });
                                        });
                           }},
                          {"footnotes", false,
                           [&](const InJson& v2, const std::string& p2) {
                             read_array(r, v2, p2, rec.footnotes, kMaxRecordEntries, "the footnotes of a sheet",
                                        [&](const InJson& x, const std::string& xp, FootnoteRecord& f) {
                                          return r.object(x, xp, {
                                              {"mark", true, str(f.mark)},
                                              {"text", false, str(f.text)},
                                              {"modelled", false, str(f.modelled)},
                                              {"not_modelled", false, str(f.not_modelled)},
                                          });
                                        });
                           }},
                          {"limitations", false,
                           [&](const InJson& v2, const std::string& p2) { read_texts(r, v2, p2, rec.limitations); }},
                      });
                    });
       }},
  });
}

namespace {

// `format` names cemv-matrix/1; false when the document is not read further.
// A different format would drown the real problem in unknown keys, and a
// file that is no matrix at all (a path in a scenario may name any file)
// gets no word of its content quoted: only a cemv format's name is.
bool read_format(Reader& r, const InJson& root) {
  if (!root.contains("format")) {
    r.error("format", "required key is missing (expected '" + std::string(kMatrixFormat) + "')");
    return root.contains("causes") || root.contains("effects");
  }
  const auto& f = root["format"];
  if (f.is_string() && f.get_ref<const std::string&>() == kMatrixFormat) return true;
  const bool ours = f.is_string() && f.get_ref<const std::string&>().rfind("cemv-", 0) == 0;
  r.error("format", (ours ? in_quotes(f.get_ref<const std::string&>()) : f.is_string() ? std::string("the value") : Reader::describe(f)) +
                        " is not a supported format; expected '" + kMatrixFormat + "'");
  return false;
}

// One SIF group: a name, or {"name": ..., "process_safety_time_ms": N}.
void read_sif_group(Reader& r, const InJson& v, const std::string& kp, int number, Matrix& m) {
  std::string name;
  if (!v.is_object()) {
    if (r.text(v, kp, name)) m.sif_groups[number] = name;
    return;
  }
  std::optional<std::uint32_t> pst;
  bool named = false;
  r.object(v, kp, {
      {"name", true, [&](const InJson& v2, const std::string& p2) { named = r.text(v2, p2, name); }},
      {"process_safety_time_ms", false,
       [&](const InJson& v2, const std::string& p2) {
         std::uint32_t ms = 0;
         if (!v2.is_null() && r.integer(v2, p2, 1, kU32Max, ms, "a process safety time is positive")) pst = ms;
       }},
  });
  if (!named) return;
  m.sif_groups[number] = name;
  if (pst) m.process_safety_time_ms[number] = *pst;
}

void read_sif_groups(Reader& r, const InJson& v, const std::string& p, Matrix& m) {
  if (!v.is_object()) {
    r.error(p, "expected an object mapping group numbers to names, got " + Reader::describe(v));
    return;
  }
  for (auto it = v.begin(); it != v.end(); ++it) {
    const std::string& key = it.key();
    const std::string kp = member_path(p, key);
    int number = 0;
    auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), number);
    const bool canonical = ec == std::errc{} && end == key.data() + key.size() && key[0] != '0';
    if (!canonical || number < 1 || number > kMaxSifGroups) {
      r.error(kp, "SIF group numbers are 1-64 written without leading zeros, got " + in_quotes(key));
      continue;
    }
    read_sif_group(r, it.value(), kp, number, m);
  }
}

}  // namespace

void read_matrix(Reader& r, const InJson& root, Matrix& m) {
  if (!root.is_object()) {
    r.error("", "the top level must be a JSON object (a cemv-matrix/1 document), got " + Reader::describe(root));
    return;
  }
  if (!read_format(r, root)) return;
  r.object(root, "", {
      {"format", false, [](const InJson&, const std::string&) {}},
      {"name", true, [&](const InJson& v, const std::string& p) { r.element_name(v, p, m.name); }},
      {"title", false, [&](const InJson& v, const std::string& p) { r.text(v, p, m.title); }},
      {"cycle_ms", false,
       [&](const InJson& v, const std::string& p) { r.integer(v, p, 1, kU32Max, m.cycle_ms, "must be positive"); }},
      {"watchdog_ms", false,
       [&](const InJson& v, const std::string& p) {
         std::uint32_t ms = 0;
         if (!v.is_null() && r.integer(v, p, 1, kU32Max, ms, "must be positive")) m.watchdog_ms = ms;
       }},
      {"sif_groups", false, [&](const InJson& v, const std::string& p) { read_sif_groups(r, v, p, m); }},
      {"secure_write", false,
       [&](const InJson& v, const std::string& p) {
         if (v.is_null()) return;
         SecureWrite s;
         if (r.object(v, p, {{"enable_tag", true,
                              [&](const InJson& v2, const std::string& p2) { r.tag(v2, p2, s.enable_tag); }}}))
           m.secure_write = s;
       }},
      {"group_deactivation", false,
       [&](const InJson& v, const std::string& p) {
         if (v.is_null()) return;
         GroupDeactivation g;
         bool read = r.object(v, p, {
             {"enable_tag", true, [&](const InJson& v2, const std::string& p2) { r.tag(v2, p2, g.enable_tag); }},
             {"set_tag", true, [&](const InJson& v2, const std::string& p2) { r.tag(v2, p2, g.set_tag); }},
         });
         if (read) m.group_deactivation = g;
       }},
      {"causes", false,
       [&](const InJson& v, const std::string& p) {
         read_array(r, v, p, m.causes, kMaxCauses, "the 128 causes of a matrix (3.4)",
                    [&](const InJson& e, const std::string& ep, Cause& c) {
                      bool ok = false;
                      c = read_cause(r, e, ep, ok);
                      return ok;
                    });
       }},
      {"effects", false,
       [&](const InJson& v, const std::string& p) {
         read_array(r, v, p, m.effects, kMaxEffects, "the 128 effects of a matrix (3.4)",
                    [&](const InJson& e, const std::string& ep, Effect& x) {
                      bool ok = false;
                      x = read_effect(r, e, ep, ok);
                      return ok;
                    });
       }},
      {"tag_descriptions", false,
       [&](const InJson& v, const std::string& p) { read_tag_descriptions(r, v, p, m); }},
      {"provenance", false,
       [&](const InJson& v, const std::string& p) {
         if (!v.is_null()) read_provenance(r, v, p, m.provenance);
       }},
      {"intersections", false,
       [&](const InJson& v, const std::string& p) {
         read_array(r, v, p, m.intersections, kMaxIntersections, "the 1024 intersections of a matrix (3.4)",
                    [&](const InJson& e, const std::string& ep, Intersection& x) {
                      bool ok = false;
                      x = read_intersection(r, e, ep, ok);
                      return ok;
                    });
       }},
  });
}

}  // namespace cemv::formats::matrix_json_detail
