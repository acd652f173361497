// cemv-matrix/1: the loader (structural checks only; plausibility is
// validate.cpp), the canonical writer and the signature. docs/format.md is the
// field-by-field description of what this file accepts.
#include "formats/matrix_json.hpp"

#include <openssl/evp.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <tuple>
#include <nlohmann/json.hpp>

#include "model/names.hpp"
#include "model/text.hpp"
#include "model/validate.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats {

using namespace cemv::model;

namespace {

// The loader reads into an insertion-ordered DOM so that issues come out in
// file order.
using InJson = nlohmann::ordered_json;

// ---- Text helpers ------------------------------------------------------------

// ---- Enumerations ----------------------------------------------------------------

template <class E>
struct EnumNames {
  std::vector<E> values;
  std::vector<std::string_view> names() const {
    std::vector<std::string_view> out;
    for (E v : values) out.push_back(to_string(v));
    return out;
  }
};

const EnumNames<InputKind> kInputKinds{{InputKind::Discrete, InputKind::Analog}};
const EnumNames<CauseFunction> kCauseFunctions{{CauseFunction::Normal, CauseFunction::And, CauseFunction::Or,
                                                CauseFunction::TwoOoThree, CauseFunction::Comment}};
const EnumNames<LimitType> kLimitTypes{{LimitType::High, LimitType::Low}};
const EnumNames<BadQuality> kBadQualities{{BadQuality::Ignore, BadQuality::Trip, BadQuality::Degrade}};
const EnumNames<TimeMode> kTimeModes{{TimeMode::None, TimeMode::OnDelay, TimeMode::OffDelay, TimeMode::Timed}};
const EnumNames<EffectFunction> kEffectFunctions{{EffectFunction::Normal, EffectFunction::Comment}};
const EnumNames<IntersectionType> kIntersectionTypes{
    {IntersectionType::N, IntersectionType::S, IntersectionType::V, IntersectionType::R, IntersectionType::X,
     IntersectionType::Note}};

// ---- The reader --------------------------------------------------------------

// Walks the DOM, converting into the model while recording every problem with
// its JSON path. Each typed read returns false (leaving the target untouched)
// after recording why the value was not accepted.
class Reader {
 public:
  explicit Reader(std::vector<LoadIssue>& issues) : issues_(issues) {}

  void error(const std::string& where, std::string what) {
    if (issues_.size() < kMaxIssues) {
      issues_.push_back({where, std::move(what)});
    } else if (issues_.size() == kMaxIssues) {
      issues_.push_back({"", "too many problems; the rest are not listed"});
    }
  }

  using Handler = std::function<void(const InJson&, const std::string&)>;
  struct Field {
    std::string_view key;
    bool required;
    Handler read;
  };

  // Members in file order: a known key goes to its handler, an unknown one is
  // an error (a misspelt optional key must never pass as "absent"). Missing
  // required keys are reported after the members. Returns false when `j` is not
  // an object at all.
  bool object(const InJson& j, const std::string& path, const std::vector<Field>& fields) {
    if (!j.is_object()) {
      error(path, "expected an object, got " + describe(j));
      return false;
    }
    std::vector<bool> seen(fields.size(), false);
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string& key = it.key();
      auto field = std::find_if(fields.begin(), fields.end(), [&](const Field& f) { return f.key == key; });
      if (field == fields.end()) {
        std::vector<std::string_view> known;
        for (const auto& f : fields) known.push_back(f.key);
        error(member_path(path, key), "unknown key" + did_you_mean(key, known));
        continue;
      }
      seen[static_cast<std::size_t>(field - fields.begin())] = true;
      field->read(it.value(), member_path(path, key));
    }
    for (std::size_t i = 0; i < fields.size(); ++i)
      if (fields[i].required && !seen[i]) error(member_path(path, fields[i].key), "required key is missing");
    return true;
  }

  bool boolean(const InJson& j, const std::string& path, bool& out) {
    if (!j.is_boolean()) {
      error(path, "expected true or false, got " + describe(j));
      return false;
    }
    out = j.get<bool>();
    return true;
  }

  // Integers accept integral-valued floats (2.0) but nothing else.
  template <class T>
  bool integer(const InJson& j, const std::string& path, long long lo, long long hi, T& out,
               std::string_view why = "") {
    long long v = 0;
    if (j.is_number_unsigned()) {
      auto u = j.get<std::uint64_t>();
      if (u > static_cast<std::uint64_t>(hi)) return out_of_range(path, j.dump(), lo, hi, why);
      v = static_cast<long long>(u);
    } else if (j.is_number_integer()) {
      v = j.get<std::int64_t>();
    } else if (j.is_number_float()) {
      double d = j.get<double>();
      if (!std::isfinite(d) || std::trunc(d) != d) {
        error(path, "expected an integer, got " + describe(j));
        return false;
      }
      if (d < static_cast<double>(lo) || d > static_cast<double>(hi))
        return out_of_range(path, j.dump(), lo, hi, why);
      v = static_cast<long long>(d);
    } else {
      error(path, "expected an integer, got " + describe(j));
      return false;
    }
    if (v < lo || v > hi) return out_of_range(path, std::to_string(v), lo, hi, why);
    out = static_cast<T>(v);
    return true;
  }

  // IEEE single precision (REAL, 6.3.1): a value that would round to infinity
  // is rejected rather than silently saturated.
  bool real(const InJson& j, const std::string& path, float& out) {
    if (!j.is_number()) {
      error(path, "expected a number, got " + describe(j));
      return false;
    }
    double d = j.get<double>();
    // Half an ulp above FLT_MAX: anything from here on rounds to infinity.
    constexpr double kFloatOverflow = 0x1.ffffffp+127;
    if (!std::isfinite(d) || std::fabs(d) >= kFloatOverflow) {
      error(path, j.dump() + " is out of the range of a single-precision REAL (about +/-3.4e38, 6.3.1)");
      return false;
    }
    out = static_cast<float>(d);
    if (out == 0.0f) out = 0.0f;  // -0 and 0 are one value; keep the canonical form unique
    return true;
  }

  // Free text: no control characters (they would corrupt reports), at most
  // max_chars characters (UTF-8 code points).
  bool text(const InJson& j, const std::string& path, std::string& out,
            std::size_t max_chars = std::string::npos, std::string_view why = "") {
    if (!j.is_string()) {
      error(path, "expected a string, got " + describe(j));
      return false;
    }
    const auto& s = j.get_ref<const std::string&>();
    for (unsigned char c : s) {
      if (c < 0x20 || c == 0x7f) {
        error(path, in_quotes(s) + " contains a control character");
        return false;
      }
    }
    if (max_chars != std::string::npos && utf8_length(s) > max_chars) {
      error(path, in_quotes(s) + " is longer than " + std::to_string(max_chars) + " characters" +
                      (why.empty() ? "" : " (" + std::string(why) + ")"));
      return false;
    }
    out = s;
    return true;
  }

  bool tag(const InJson& j, const std::string& path, std::string& out) {
    if (!j.is_string()) {
      error(path, "expected a tag name (string), got " + describe(j));
      return false;
    }
    const auto& s = j.get_ref<const std::string&>();
    if (auto problem = tag_name_problem(s)) {
      error(path, *problem);
      return false;
    }
    out = s;
    return true;
  }

  // Optional tag: null and absence both mean "no tag".
  bool optional_tag(const InJson& j, const std::string& path, std::optional<std::string>& out) {
    if (j.is_null()) {
      out.reset();
      return true;
    }
    std::string s;
    if (!tag(j, path, s)) return false;
    out = std::move(s);
    return true;
  }

  bool element_name(const InJson& j, const std::string& path, std::string& out) {
    if (!j.is_string()) {
      error(path, "expected a name (string), got " + describe(j));
      return false;
    }
    const auto& s = j.get_ref<const std::string&>();
    if (auto problem = element_name_problem(s)) {
      error(path, *problem);
      return false;
    }
    out = s;
    return true;
  }

  template <class E>
  bool enumeration(const InJson& j, const std::string& path, const EnumNames<E>& names, E& out) {
    std::string list;
    for (auto n : names.names()) list += (list.empty() ? "'" : ", '") + std::string(n) + "'";
    if (!j.is_string()) {
      error(path, "expected one of " + list + ", got " + describe(j));
      return false;
    }
    const auto& s = j.get_ref<const std::string&>();
    for (E v : names.values) {
      if (s == to_string(v)) {
        out = v;
        return true;
      }
    }
    error(path, in_quotes(s) + " is not one of " + list + did_you_mean(s, names.names()));
    return false;
  }

  static std::string describe(const InJson& j) {
    switch (j.type()) {
      case InJson::value_t::object: return "an object";
      case InJson::value_t::array: return "an array";
      case InJson::value_t::string: return "the string " + in_quotes(j.get_ref<const std::string&>());
      case InJson::value_t::null: return "null";
      default: return printable(j.dump());
    }
  }

 private:
  bool out_of_range(const std::string& path, const std::string& shown, long long lo, long long hi,
                    std::string_view why) {
    error(path, shown + " is out of range " + std::to_string(lo) + "-" + std::to_string(hi) +
                    (why.empty() ? "" : " (" + std::string(why) + ")"));
    return false;
  }

  std::vector<LoadIssue>& issues_;
};

constexpr long long kU32Max = std::numeric_limits<std::uint32_t>::max();
// Entries of one provenance list or of the tag descriptions: more than any
// matrix of 3.4 needs (128 causes x 3 + 128 effects x 4 tags and the control tags).
constexpr std::size_t kMaxRecordEntries = 4096;

// Reads a JSON array whose elements `read_one` converts; `limit` (of 3.4) is
// checked on the count first so that the message names the limit.
template <class T, class ReadOne>
void read_array(Reader& r, const InJson& j, const std::string& path, std::vector<T>& out, std::size_t limit,
                const std::string& limit_text, ReadOne read_one) {
  if (!j.is_array()) {
    r.error(path, "expected an array, got " + Reader::describe(j));
    return;
  }
  if (j.size() > limit) r.error(path, std::to_string(j.size()) + " entries, more than " + limit_text);
  for (std::size_t i = 0; i < j.size(); ++i) {
    T item;
    if (read_one(j[i], element_path(path, i), item)) out.push_back(std::move(item));
  }
}

// `sif`: up to 4 group numbers of 1-64 (6.3, 6.4 "SIF Grouping"; 6.1 properties).
void read_sif_list(Reader& r, const InJson& j, const std::string& path, std::vector<int>& out) {
  std::vector<int> groups;
  read_array(r, j, path, groups, kMaxSifPerElement, "the 4 SIF groups an element can belong to (6.3.6)",
             [&](const InJson& v, const std::string& p, int& g) {
               return r.integer(v, p, 1, kMaxSifGroups, g, "SIF groups are numbered 1-64");
             });
  std::sort(groups.begin(), groups.end());
  auto dup = std::adjacent_find(groups.begin(), groups.end());
  if (dup != groups.end()) r.error(path, "lists SIF group " + std::to_string(*dup) + " twice");
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  out = std::move(groups);
}

void read_description(Reader& r, const InJson& j, const std::string& path, std::string& out) {
  r.text(j, path, out, kMaxDescriptionLength, "descriptions, 6.3.4 and 6.4.4");
}

Cause read_cause(Reader& r, const InJson& j, const std::string& path, bool& ok) {
  Cause c;
  bool has_tags = false;
  ok = r.object(j, path, {
      {"id", true, [&](const InJson& v, const std::string& p) {
         r.integer(v, p, 1, kMaxCauses, c.id, "causes are numbered 1-128, 3.4");
       }},
      {"name", true, [&](const InJson& v, const std::string& p) { r.element_name(v, p, c.name); }},
      {"description", false, [&](const InJson& v, const std::string& p) { read_description(r, v, p, c.description); }},
      {"sil", false, [&](const InJson& v, const std::string& p) { r.integer(v, p, 0, 4, c.sil, "0 = not stated"); }},
      {"input", false, [&](const InJson& v, const std::string& p) { r.enumeration(v, p, kInputKinds, c.input); }},
      {"function", false,
       [&](const InJson& v, const std::string& p) { r.enumeration(v, p, kCauseFunctions, c.function); }},
      {"tags", false,
       [&](const InJson& v, const std::string& p) {
         has_tags = true;
         read_array(r, v, p, c.tags, kMaxCauseTags, "the 3 input tags of a cause (3.4)",
                    [&](const InJson& t, const std::string& tp, CauseTag& tag) {
                      bool named = false;
                      r.object(t, tp, {
                          {"name", true, [&](const InJson& v2, const std::string& p2) { named = r.tag(v2, p2, tag.name); }},
                          {"ett", false, [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, tag.ett); }},
                          {"soft_bypass_allowed", false,
                           [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, tag.soft_bypass_allowed); }},
                          {"simulation_allowed", false,
                           [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, tag.simulation_allowed); }},
                      });
                      return named;
                    });
       }},
      {"analog", false,
       [&](const InJson& v, const std::string& p) {
         if (v.is_null()) return;
         AnalogParams a;
         bool read = r.object(v, p, {
             {"limit_type", true, [&](const InJson& v2, const std::string& p2) { r.enumeration(v2, p2, kLimitTypes, a.limit_type); }},
             {"limit", true, [&](const InJson& v2, const std::string& p2) { r.real(v2, p2, a.limit); }},
             {"hysteresis", false, [&](const InJson& v2, const std::string& p2) { r.real(v2, p2, a.hysteresis); }},
             {"prewarning", false,
              [&](const InJson& v2, const std::string& p2) {
                float f = 0.0f;
                if (!v2.is_null() && r.real(v2, p2, f)) a.prewarning = f;
              }},
             {"delta", false, [&](const InJson& v2, const std::string& p2) { r.real(v2, p2, a.delta); }},
             {"unit", false, [&](const InJson& v2, const std::string& p2) { r.text(v2, p2, a.unit); }},
         });
         if (read) c.analog = a;
       }},
      {"bad_quality", false,
       [&](const InJson& v, const std::string& p) { r.enumeration(v, p, kBadQualities, c.bad_quality); }},
      {"time", false,
       [&](const InJson& v, const std::string& p) {
         r.object(v, p, {
             {"mode", false, [&](const InJson& v2, const std::string& p2) { r.enumeration(v2, p2, kTimeModes, c.time.mode); }},
             {"ms", false, [&](const InJson& v2, const std::string& p2) { r.integer(v2, p2, 0, kU32Max, c.time.ms); }},
         });
       }},
      {"auto_ack", false, [&](const InJson& v, const std::string& p) { r.boolean(v, p, c.auto_ack); }},
      {"soft_bypass", false,
       [&](const InJson& v, const std::string& p) {
         r.object(v, p, {
             {"allowed", false, [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, c.soft_bypass.allowed); }},
             {"max_s", false, [&](const InJson& v2, const std::string& p2) { r.integer(v2, p2, 0, kU32Max, c.soft_bypass.max_s); }},
             {"prealarm_s", false,
              [&](const InJson& v2, const std::string& p2) { r.integer(v2, p2, 0, kU32Max, c.soft_bypass.prealarm_s); }},
         });
       }},
      {"bypass_tag", false, [&](const InJson& v, const std::string& p) { r.optional_tag(v, p, c.bypass_tag); }},
      {"inhibit_tag", false, [&](const InJson& v, const std::string& p) { r.optional_tag(v, p, c.inhibit_tag); }},
      {"first_out_group", false,
       [&](const InJson& v, const std::string& p) {
         r.integer(v, p, 0, kMaxFirstOutGroup, c.first_out_group, "0 = none, groups 1-15");
       }},
      {"mutually_locked_maintenance", false,
       [&](const InJson& v, const std::string& p) { r.boolean(v, p, c.mutually_locked_maintenance); }},
      {"sif", false, [&](const InJson& v, const std::string& p) { read_sif_list(r, v, p, c.sif); }},
      {"note", false, [&](const InJson& v, const std::string& p) { r.text(v, p, c.note); }},
      {"sensor_ms", false, [&](const InJson& v, const std::string& p) { r.integer(v, p, 0, kU32Max, c.sensor_ms); }},
  });
  if (!ok) return c;
  // 3.4: 1-3 input tags; a comment-only cause is not processed and may have none.
  if (c.function != CauseFunction::Comment && c.tags.empty()) {
    if (!has_tags)
      r.error(member_path(path, "tags"), "required key is missing");
    else if (j.at("tags").is_array() && j.at("tags").empty())
      r.error(member_path(path, "tags"), "a cause needs 1-3 input tags (3.4), got none");
  }
  if (c.input == InputKind::Analog && (!j.contains("analog") || j.at("analog").is_null()))
    r.error(member_path(path, "analog"), "required for an analog cause (limit_type and limit, 6.3.5)");
  return c;
}

Effect read_effect(Reader& r, const InJson& j, const std::string& path, bool& ok) {
  Effect e;
  bool has_tags = false;
  ok = r.object(j, path, {
      {"id", true, [&](const InJson& v, const std::string& p) {
         r.integer(v, p, 1, kMaxEffects, e.id, "effects are numbered 1-128, 3.4");
       }},
      {"name", true, [&](const InJson& v, const std::string& p) { r.element_name(v, p, e.name); }},
      {"description", false, [&](const InJson& v, const std::string& p) { read_description(r, v, p, e.description); }},
      {"sil", false, [&](const InJson& v, const std::string& p) { r.integer(v, p, 0, 4, e.sil, "0 = not stated"); }},
      {"function", false,
       [&](const InJson& v, const std::string& p) { r.enumeration(v, p, kEffectFunctions, e.function); }},
      {"tags", false,
       [&](const InJson& v, const std::string& p) {
         has_tags = true;
         read_array(r, v, p, e.tags, kMaxEffectTags, "the 4 output tags of an effect (3.4)",
                    [&](const InJson& t, const std::string& tp, EffectTag& tag) {
                      bool named = false;
                      r.object(t, tp, {
                          {"name", true, [&](const InJson& v2, const std::string& p2) { named = r.tag(v2, p2, tag.name); }},
                          {"ett", false, [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, tag.ett); }},
                          {"simulation_allowed", false,
                           [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, tag.simulation_allowed); }},
                      });
                      return named;
                    });
       }},
      {"output_delay_ms", false,
       [&](const InJson& v, const std::string& p) { r.integer(v, p, 0, kU32Max, e.output_delay_ms); }},
      {"soft_bypass_allowed", false, [&](const InJson& v, const std::string& p) { r.boolean(v, p, e.soft_bypass_allowed); }},
      {"bypass_tag", false, [&](const InJson& v, const std::string& p) { r.optional_tag(v, p, e.bypass_tag); }},
      {"reset_tag", false, [&](const InJson& v, const std::string& p) { r.optional_tag(v, p, e.reset_tag); }},
      {"override", false,
       [&](const InJson& v, const std::string& p) {
         if (v.is_null()) return;
         Override o;
         bool read = r.object(v, p, {
             {"max_s", true, [&](const InJson& v2, const std::string& p2) { r.integer(v2, p2, 0, kU32Max, o.max_s); }},
             {"prealarm_s", false, [&](const InJson& v2, const std::string& p2) { r.integer(v2, p2, 0, kU32Max, o.prealarm_s); }},
         });
         if (read) e.override_time = o;
       }},
      {"process_data", false,
       [&](const InJson& v, const std::string& p) {
         if (v.is_null()) return;
         ProcessData d;
         bool read = r.object(v, p, {
             {"tag", false, [&](const InJson& v2, const std::string& p2) { r.optional_tag(v2, p2, d.tag); }},
             {"pass_through", false, [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, d.pass_through); }},
             {"mask_tag", false, [&](const InJson& v2, const std::string& p2) { r.optional_tag(v2, p2, d.mask_tag); }},
         });
         if (read) e.process_data = d;
       }},
      {"mutually_locked_maintenance", false,
       [&](const InJson& v, const std::string& p) { r.boolean(v, p, e.mutually_locked_maintenance); }},
      {"sif", false, [&](const InJson& v, const std::string& p) { read_sif_list(r, v, p, e.sif); }},
      {"note", false, [&](const InJson& v, const std::string& p) { r.text(v, p, e.note); }},
      {"actuator_ms", false,
       [&](const InJson& v, const std::string& p) { r.integer(v, p, 0, kU32Max, e.actuator_ms); }},
  });
  if (!ok) return e;
  // 3.4: 1-4 output tags; a comment-only effect drives nothing and may have none.
  if (e.function != EffectFunction::Comment && e.tags.empty()) {
    if (!has_tags)
      r.error(member_path(path, "tags"), "required key is missing");
    else if (j.at("tags").is_array() && j.at("tags").empty())
      r.error(member_path(path, "tags"), "an effect needs 1-4 output tags (3.4), got none");
  }
  return e;
}

Intersection read_intersection(Reader& r, const InJson& j, const std::string& path, bool& ok) {
  Intersection x;
  ok = r.object(j, path, {
      {"cause", true, [&](const InJson& v, const std::string& p) {
         r.integer(v, p, 1, kMaxCauses, x.cause, "causes are numbered 1-128, 3.4");
       }},
      {"effect", true, [&](const InJson& v, const std::string& p) {
         r.integer(v, p, 1, kMaxEffects, x.effect, "effects are numbered 1-128, 3.4");
       }},
      {"type", true, [&](const InJson& v, const std::string& p) { r.enumeration(v, p, kIntersectionTypes, x.type); }},
      {"xoon", false,
       [&](const InJson& v, const std::string& p) {
         int k = 0;
         if (!v.is_null() && r.integer(v, p, kMinXooN, kMaxXooN, k, "the X of XooN, 6.5.2")) x.xoon = k;
       }},
      {"note", false, [&](const InJson& v, const std::string& p) { r.text(v, p, x.note); }},
  });
  return x;
}

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

void read_matrix(Reader& r, const InJson& root, Matrix& m) {
  if (!root.is_object()) {
    r.error("", "the top level must be a JSON object (a cemv-matrix/1 document), got " + Reader::describe(root));
    return;
  }
  // A different format would drown the real problem in unknown keys, and a
  // file that is no matrix at all (a path in a scenario may name any file)
  // gets no word of its content quoted: only a cemv format's name is.
  if (!root.contains("format")) {
    r.error("format", "required key is missing (expected '" + std::string(kMatrixFormat) + "')");
    if (!root.contains("causes") && !root.contains("effects")) return;
  } else {
    const auto& f = root["format"];
    if (!f.is_string() || f.get_ref<const std::string&>() != kMatrixFormat) {
      const bool ours = f.is_string() && f.get_ref<const std::string&>().rfind("cemv-", 0) == 0;
      r.error("format", (ours ? in_quotes(f.get_ref<const std::string&>()) : f.is_string() ? std::string("the value") : Reader::describe(f)) +
                            " is not a supported format; expected '" + kMatrixFormat + "'");
      return;
    }
  }
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
      {"sif_groups", false,
       [&](const InJson& v, const std::string& p) {
         if (!v.is_object()) {
           r.error(p, "expected an object mapping group numbers to names, got " + Reader::describe(v));
           return;
         }
         for (auto it = v.begin(); it != v.end(); ++it) {
           const std::string& key = it.key();
           std::string kp = member_path(p, key);
           int number = 0;
           auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), number);
           bool canonical = ec == std::errc{} && end == key.data() + key.size() && key[0] != '0';
           if (!canonical || number < 1 || number > kMaxSifGroups) {
             r.error(kp, "SIF group numbers are 1-64 written without leading zeros, got " + in_quotes(key));
             continue;
           }
           // A name, or {"name": ..., "process_safety_time_ms": N}.
           std::string name;
           if (it.value().is_object()) {
             std::optional<std::uint32_t> pst;
             bool named = false;
             r.object(it.value(), kp, {
                 {"name", true, [&](const InJson& v2, const std::string& p2) { named = r.text(v2, p2, name); }},
                 {"process_safety_time_ms", false,
                  [&](const InJson& v2, const std::string& p2) {
                    std::uint32_t ms = 0;
                    if (!v2.is_null() && r.integer(v2, p2, 1, kU32Max, ms, "a process safety time is positive"))
                      pst = ms;
                  }},
             });
             if (!named) continue;
             m.sif_groups[number] = name;
             if (pst) m.process_safety_time_ms[number] = *pst;
           } else if (r.text(it.value(), kp, name)) {
             m.sif_groups[number] = name;
           }
         }
       }},
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

// ---- The canonical writer -------------------------------------------------------

// Writes JSON text directly (no DOM: the canonical form is on the path of every
// report). Each object's keys must be written in increasing byte order, which
// key() enforces, so the "sorted keys" promise cannot silently break.
class CanonicalWriter {
 public:
  std::string take() { return std::move(out_); }

  void begin_object() { open('{'); }
  void end_object() { close('}'); }
  void begin_array() { open('['); }
  void end_array() { close(']'); }

  CanonicalWriter& key(std::string_view k) {
    Level& level = levels_.back();
    if (level.count > 0 && !(level.last_key < k))
      throw std::logic_error("canonical writer: key '" + std::string(k) + "' out of order");
    level.last_key = k;
    next_member();
    write_string(k);
    out_ += ": ";
    return *this;
  }
  // Starts the next element of an array.
  CanonicalWriter& item() {
    next_member();
    return *this;
  }

  void value(std::string_view s) { write_string(s); }
  void value(const char* s) { write_string(s); }
  void value(const std::string& s) { write_string(s); }
  void value(bool b) { out_ += b ? "true" : "false"; }
  void value(int v) { out_ += std::to_string(v); }
  void value(std::uint32_t v) { out_ += std::to_string(v); }
  void value(float f) {
    if (!std::isfinite(f)) throw std::invalid_argument("a matrix value is NaN or infinite; it has no JSON form");
    out_ += float_text(f == 0.0f ? 0.0f : f);
  }
  void null() { out_ += "null"; }
  void value(const std::optional<std::string>& s) { s ? value(*s) : null(); }
  void value(const std::optional<float>& f) { f ? value(*f) : null(); }
  void value(const std::optional<int>& v) { v ? value(*v) : null(); }

 private:
  struct Level {
    std::size_t count = 0;
    std::string_view last_key;
  };
  void open(char c) {
    out_ += c;
    levels_.push_back({});
  }
  void close(char c) {
    bool empty = levels_.back().count == 0;
    levels_.pop_back();
    if (!empty) {
      out_ += '\n';
      indent();
    }
    out_ += c;
  }
  void next_member() {
    if (levels_.back().count++ > 0) out_ += ',';
    out_ += '\n';
    indent();
  }
  void indent() { out_.append(2 * levels_.size(), ' '); }

  // JSON string; UTF-8 kept as is, control characters escaped, and any byte
  // sequence that is not UTF-8 (possible only in matrices built in code)
  // replaced by U+FFFD so the output is always valid JSON.
  void write_string(std::string_view s) {
    out_ += '"';
    for (std::size_t i = 0; i < s.size();) {
      auto c = static_cast<unsigned char>(s[i]);
      if (c < 0x80) {
        switch (c) {
          case '"': out_ += "\\\""; break;
          case '\\': out_ += "\\\\"; break;
          case '\n': out_ += "\\n"; break;
          case '\r': out_ += "\\r"; break;
          case '\t': out_ += "\\t"; break;
          case '\b': out_ += "\\b"; break;
          case '\f': out_ += "\\f"; break;
          default:
            if (c < 0x20) {
              char buf[8];
              std::snprintf(buf, sizeof buf, "\\u%04x", c);
              out_ += buf;
            } else {
              out_ += static_cast<char>(c);
            }
        }
        ++i;
        continue;
      }
      std::size_t length = utf8_sequence_length(s.substr(i));
      if (length == 0) {
        out_ += "\xEF\xBF\xBD";
        ++i;
      } else {
        out_.append(s.substr(i, length));
        i += length;
      }
    }
    out_ += '"';
  }
  // Length of the well-formed UTF-8 sequence at the start of s (RFC 3629), 0 if none.
  static std::size_t utf8_sequence_length(std::string_view s) {
    auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    auto cont = [&](std::size_t k) { return k < s.size() && (b(k) & 0xC0) == 0x80; };
    unsigned char c = b(0);
    if (c >= 0xC2 && c <= 0xDF) return cont(1) ? 2 : 0;
    if (c >= 0xE0 && c <= 0xEF) {
      if (!cont(1) || !cont(2)) return 0;
      if (c == 0xE0 && b(1) < 0xA0) return 0;   // overlong
      if (c == 0xED && b(1) > 0x9F) return 0;   // surrogates
      return 3;
    }
    if (c >= 0xF0 && c <= 0xF4) {
      if (!cont(1) || !cont(2) || !cont(3)) return 0;
      if (c == 0xF0 && b(1) < 0x90) return 0;   // overlong
      if (c == 0xF4 && b(1) > 0x8F) return 0;   // beyond U+10FFFF
      return 4;
    }
    return 0;
  }

  std::string out_;
  std::vector<Level> levels_;
};

void write_sif(CanonicalWriter& w, std::vector<int> sif) {
  std::sort(sif.begin(), sif.end());
  w.begin_array();
  for (int g : sif) w.item().value(g);
  w.end_array();
}

// Keys in byte order, by hand: CanonicalWriter::key() checks it.
void write_cause(CanonicalWriter& w, const Cause& c) {
  w.begin_object();
  w.key("analog");
  if (c.analog) {
    const AnalogParams& a = *c.analog;
    w.begin_object();
    w.key("delta").value(a.delta);
    w.key("hysteresis").value(a.hysteresis);
    w.key("limit").value(a.limit);
    w.key("limit_type").value(to_string(a.limit_type));
    w.key("prewarning").value(a.prewarning);
    w.key("unit").value(a.unit);
    w.end_object();
  } else {
    w.null();
  }
  w.key("auto_ack").value(c.auto_ack);
  w.key("bad_quality").value(to_string(c.bad_quality));
  w.key("bypass_tag").value(c.bypass_tag);
  w.key("description").value(c.description);
  w.key("first_out_group").value(c.first_out_group);
  w.key("function").value(to_string(c.function));
  w.key("id").value(c.id);
  w.key("inhibit_tag").value(c.inhibit_tag);
  w.key("input").value(to_string(c.input));
  w.key("mutually_locked_maintenance").value(c.mutually_locked_maintenance);
  w.key("name").value(c.name);
  w.key("note").value(c.note);
  if (c.sensor_ms) w.key("sensor_ms").value(c.sensor_ms);  // only when declared: old signatures stay
  w.key("sif");
  write_sif(w, c.sif);
  w.key("sil").value(c.sil);
  w.key("soft_bypass").begin_object();
  w.key("allowed").value(c.soft_bypass.allowed);
  w.key("max_s").value(c.soft_bypass.max_s);
  w.key("prealarm_s").value(c.soft_bypass.prealarm_s);
  w.end_object();
  w.key("tags").begin_array();
  for (const auto& t : c.tags) {
    w.item().begin_object();
    w.key("ett").value(t.ett);
    w.key("name").value(t.name);
    if (!t.simulation_allowed) w.key("simulation_allowed").value(false);  // only when restricted: old signatures stay
    w.key("soft_bypass_allowed").value(t.soft_bypass_allowed);
    w.end_object();
  }
  w.end_array();
  w.key("time").begin_object();
  w.key("mode").value(to_string(c.time.mode));
  w.key("ms").value(c.time.ms);
  w.end_object();
  w.end_object();
}

void write_effect(CanonicalWriter& w, const Effect& e) {
  w.begin_object();
  if (e.actuator_ms) w.key("actuator_ms").value(e.actuator_ms);  // only when declared: old signatures stay
  w.key("bypass_tag").value(e.bypass_tag);
  w.key("description").value(e.description);
  w.key("function").value(to_string(e.function));
  w.key("id").value(e.id);
  w.key("mutually_locked_maintenance").value(e.mutually_locked_maintenance);
  w.key("name").value(e.name);
  w.key("note").value(e.note);
  w.key("output_delay_ms").value(e.output_delay_ms);
  w.key("override");
  if (e.override_time) {
    w.begin_object();
    w.key("max_s").value(e.override_time->max_s);
    w.key("prealarm_s").value(e.override_time->prealarm_s);
    w.end_object();
  } else {
    w.null();
  }
  w.key("process_data");
  if (e.process_data) {
    w.begin_object();
    w.key("mask_tag").value(e.process_data->mask_tag);
    w.key("pass_through").value(e.process_data->pass_through);
    w.key("tag").value(e.process_data->tag);
    w.end_object();
  } else {
    w.null();
  }
  w.key("reset_tag").value(e.reset_tag);
  w.key("sif");
  write_sif(w, e.sif);
  w.key("sil").value(e.sil);
  w.key("soft_bypass_allowed").value(e.soft_bypass_allowed);
  w.key("tags").begin_array();
  for (const auto& t : e.tags) {
    w.item().begin_object();
    w.key("ett").value(t.ett);
    w.key("name").value(t.name);
    if (!t.simulation_allowed) w.key("simulation_allowed").value(false);
    w.end_object();
  }
  w.end_array();
  w.end_object();
}

void write_intersection(CanonicalWriter& w, const Intersection& x) {
  w.begin_object();
  w.key("cause").value(x.cause);
  w.key("effect").value(x.effect);
  w.key("note").value(x.note);
  w.key("type").value(to_string(x.type));
  w.key("xoon").value(x.xoon);
  w.end_object();
}

void write_texts(CanonicalWriter& w, const std::vector<std::string>& texts) {
  w.begin_array();
  for (const auto& t : texts) w.item().value(t);
  w.end_array();
}

void write_provenance(CanonicalWriter& w, const Provenance& p) {
  w.key("provenance").begin_object();
  w.key("imports").begin_array();
  for (const auto& rec : p.imports) {
    w.item().begin_object();
    w.key("defaults");
    write_texts(w, rec.defaults);
    w.key("encoding").value(rec.encoding);
    w.key("file").value(rec.file);
    w.key("reader").value(rec.reader);
    w.key("sha256").value(rec.sha256);
    w.key("summary").value(rec.summary);
    w.key("warnings");
    write_texts(w, rec.warnings);
    w.end_object();
  }
  w.end_array();
  w.key("parameters").begin_array();
  for (const auto& rec : p.parameters) {
    w.item().begin_object();
    w.key("file").value(rec.file);
    w.key("footnotes").begin_array();
    for (const auto& f : rec.footnotes) {
      w.item().begin_object();
      w.key("mark").value(f.mark);
      w.key("modelled").value(f.modelled);
      w.key("not_modelled").value(f.not_modelled);
      w.key("text").value(f.text);
      w.end_object();
    }
    w.end_array();
    w.key("limitations");
    write_texts(w, rec.limitations);
    w.key("origin").value(rec.origin);
    w.key("sha256").value(rec.sha256);
    w.key("values").begin_array();
    for (const auto& v : rec.values) {
      w.item().begin_object();
      w.key("element").value(v.element);
      w.key("field").value(v.field);
      w.key("origin").value(v.origin);
      w.key("previous").value(v.previous);
      w.key("value").value(v.value);
      w.end_object();
    }
    w.end_array();
    w.end_object();
  }
  w.end_array();
  w.end_object();
}

// Elements in id order (stable), whatever order a matrix built in code has.
template <class T, class Less>
std::vector<const T*> ordered(const std::vector<T>& items, Less less) {
  std::vector<const T*> out;
  out.reserve(items.size());
  for (const auto& item : items) out.push_back(&item);
  std::stable_sort(out.begin(), out.end(), [&](const T* a, const T* b) { return less(*a, *b); });
  return out;
}

std::string canonical_text(const Matrix& m) {
  CanonicalWriter w;
  w.begin_object();
  w.key("causes").begin_array();
  for (const Cause* c : ordered(m.causes, [](const Cause& a, const Cause& b) { return a.id < b.id; }))
    write_cause(w.item(), *c);
  w.end_array();
  w.key("cycle_ms").value(m.cycle_ms);
  w.key("effects").begin_array();
  for (const Effect* e : ordered(m.effects, [](const Effect& a, const Effect& b) { return a.id < b.id; }))
    write_effect(w.item(), *e);
  w.end_array();
  w.key("format").value(kMatrixFormat);
  w.key("group_deactivation");
  if (m.group_deactivation) {
    w.begin_object();
    w.key("enable_tag").value(m.group_deactivation->enable_tag);
    w.key("set_tag").value(m.group_deactivation->set_tag);
    w.end_object();
  } else {
    w.null();
  }
  w.key("intersections").begin_array();
  for (const Intersection* x : ordered(m.intersections, [](const Intersection& a, const Intersection& b) {
         return std::pair{a.cause, a.effect} < std::pair{b.cause, b.effect};
       }))
    write_intersection(w.item(), *x);
  w.end_array();
  w.key("name").value(m.name);
  if (!m.provenance.empty()) write_provenance(w, m.provenance);  // only when recorded: old signatures stay
  w.key("secure_write");
  if (m.secure_write) {
    w.begin_object();
    w.key("enable_tag").value(m.secure_write->enable_tag);
    w.end_object();
  } else {
    w.null();
  }
  // JSON object keys are strings, so group numbers sort as text ("10" < "2").
  // A group without a process safety time keeps the string form, so the
  // canonical text (and the signature) of a matrix that declares none is what
  // it was before the object form existed.
  std::vector<std::pair<std::string, int>> groups;
  for (const auto& [number, name] : m.sif_groups) groups.emplace_back(std::to_string(number), number);
  std::sort(groups.begin(), groups.end());
  w.key("sif_groups").begin_object();
  for (const auto& [key, number] : groups) {
    const std::string& name = m.sif_groups.at(number);
    auto pst = m.process_safety_time_ms.find(number);
    if (pst == m.process_safety_time_ms.end()) {
      w.key(key).value(name);
      continue;
    }
    w.key(key).begin_object();
    w.key("name").value(name);
    w.key("process_safety_time_ms").value(pst->second);
    w.end_object();
  }
  w.end_object();
  if (!m.tag_descriptions.empty()) {
    // By tag key (case-insensitive), so the order does not depend on spelling.
    std::vector<std::pair<std::string, const std::string*>> tags;
    for (const auto& [tag, text] : m.tag_descriptions) tags.emplace_back(tag_key(tag), &tag);
    std::sort(tags.begin(), tags.end());
    w.key("tag_descriptions").begin_array();
    for (const auto& [key, tag] : tags) {
      w.item().begin_object();
      w.key("description").value(m.tag_descriptions.at(*tag));
      w.key("tag").value(*tag);
      w.end_object();
    }
    w.end_array();
  }
  w.key("title").value(m.title);
  // Optional timing keys (docs/response-time.md) only when declared, for the
  // same reason.
  if (m.watchdog_ms) w.key("watchdog_ms").value(*m.watchdog_ms);
  w.end_object();
  return w.take() + "\n";
}

}  // namespace

// A text that is not JSON and does not even start like a JSON object: one
// issue that names none of its bytes (it may be any file a path in an input
// names), with the command that reads it when it is a spreadsheet.
static std::optional<LoadIssue> not_a_json_object(std::string_view text, const std::string& source_name) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos && text[first] == '{') return std::nullopt;
  auto ends_with = [&](std::string_view suffix) {
    if (source_name.size() < suffix.size()) return false;
    for (std::size_t i = 0; i < suffix.size(); ++i)
      if (std::tolower(static_cast<unsigned char>(source_name[source_name.size() - suffix.size() + i])) != suffix[i])
        return false;
    return true;
  };
  const std::string_view first_line = text.substr(0, text.find('\n'));
  std::string what = "syntax error: not a JSON object (a cemv-matrix/1 file is one, docs/format.md)";
  if (text.substr(0, 4) == std::string_view("PK\x03\x04", 4) || ends_with(".ods") || ends_with(".xlsx"))
    what = "not a cemv-matrix/1 file but a zip archive, as ODS and XLSX workbooks are: convert a workbook with "
           "`cemv import-workbook FILE -o matrix.json` (docs/workbook.md)";
  else if (ends_with(".csv") || ends_with(".tsv") || first_line.find_first_of(",;\t") != std::string_view::npos)
    what = "not a cemv-matrix/1 file but a table (CSV): convert it with `cemv import-csv FILE -o matrix.json` "
           "(docs/csv.md)";
  const auto [line, column] = line_and_column(text, first == std::string_view::npos ? 0 : first);
  return LoadIssue{"line " + std::to_string(line) + ", column " + std::to_string(column), what, source_name, line,
                   column};
}

// ---- Public API ---------------------------------------------------------------------

Matrix parse_matrix(std::string_view json_text, const std::string& source_name) {
  std::vector<LoadIssue> issues;
  if (json_text.size() > kMaxFileBytes)
    throw LoadError({{source_name,
                      "input is " + std::to_string(json_text.size()) + " bytes, larger than the limit of " +
                          std::to_string(kMaxFileBytes) + " bytes",
                      source_name}});
  if (json_text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw LoadError({{source_name, "file is empty (expected a cemv-matrix/1 JSON object)", source_name}});
  std::optional<InJson> parsed = parse_guarded_json(json_text, source_name, issues);
  if (!parsed) {
    // The parser's syntax messages quote what it last read: not for a text
    // that does not even start like a matrix. (Its limits quote nothing.)
    const bool quoting = std::any_of(issues.begin(), issues.end(), [](const LoadIssue& i) {
      return i.what.find("syntax error") != std::string::npos || i.what.find("invalid UTF-8") != std::string::npos;
    });
    if (quoting)
      if (auto issue = not_a_json_object(json_text, source_name)) throw LoadError({*issue});
    throw LoadError(std::move(issues));
  }
  const InJson& root = *parsed;

  Matrix m;
  Reader reader(issues);
  read_matrix(reader, root, m);
  if (!issues.empty()) {
    locate_issues(json_text, source_name, issues);
    throw LoadError(std::move(issues));
  }
  m.sort_by_id();
  return m;
}

Matrix load_matrix(const std::filesystem::path& file) {
  return parse_matrix(read_text_file(file), file.string());
}

Matrix parse_valid_matrix(std::string_view json_text, const std::string& source_name, const std::string& use) {
  Matrix m = parse_matrix(json_text, source_name);
  auto diagnostics = validate(m);
  if (!has_errors(diagnostics)) return m;
  const std::string& where = source_name;
  std::vector<LoadIssue> issues{{where, "the matrix has validation errors; it cannot be " + use, where}};
  JsonPositions positions(json_text);
  for (const auto& d : diagnostics) {
    if (d.severity != Severity::Error) continue;
    LoadIssue issue{where, d.rule + " " + d.element + " (" + d.section + "): " + d.message, where};
    if (auto at = element_offset(positions, d.element))
      std::tie(issue.line, issue.column) = line_and_column(json_text, *at);
    issues.push_back(std::move(issue));
  }
  throw LoadError(std::move(issues));
}

Matrix load_valid_matrix(const std::filesystem::path& file, const std::string& use) {
  return parse_valid_matrix(read_text_file(file), file.string(), use);
}

std::string to_canonical_json(const Matrix& m) { return canonical_text(m); }

void save_matrix(const Matrix& m, const std::filesystem::path& file) {
  std::string text = to_canonical_json(m);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error(file.string() + ": cannot write: " + std::strerror(errno));
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw std::runtime_error(file.string() + ": write failed");
}

std::string signature(const Matrix& m) { return sha256_hex(to_canonical_json(m)); }

std::string sha256_hex(std::string_view text) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_Digest(text.data(), text.size(), digest, &length, EVP_sha256(), nullptr) != 1)
    throw std::runtime_error("SHA-256 failed (OpenSSL EVP_Digest)");
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < length; ++i) {
    out += hex[digest[i] >> 4];
    out += hex[digest[i] & 0xF];
  }
  return out;
}

}  // namespace cemv::formats
