// cemv-matrix/1: the canonical writer (sorted keys, elements in id order), the
// file it saves and the signature over it.
#include "formats/matrix_json.hpp"

#include <openssl/evp.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats {

using namespace cemv::model;

namespace {

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
