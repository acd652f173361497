// The typed reader of a cemv-matrix/1 document's DOM, shared by the files that
// read its parts (matrix_json_read.cpp: the document and its records;
// matrix_json_elements.cpp: causes, effects, intersections). Internal to formats/.
#pragma once

#include <cmath>
#include <limits>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>
#include <nlohmann/json.hpp>

#include "formats/diagnostics.hpp"
#include "model/matrix.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats::matrix_json_detail {

using namespace cemv::model;

// The loader reads into an insertion-ordered DOM so that issues come out in
// file order.
using InJson = nlohmann::ordered_json;

template <class E>
struct EnumNames {
  std::vector<E> values;
  std::vector<std::string_view> names() const {
    std::vector<std::string_view> out;
    for (E v : values) out.push_back(to_string(v));
    return out;
  }
};

extern const EnumNames<InputKind> kInputKinds;
extern const EnumNames<CauseFunction> kCauseFunctions;
extern const EnumNames<LimitType> kLimitTypes;
extern const EnumNames<BadQuality> kBadQualities;
extern const EnumNames<TimeMode> kTimeModes;
extern const EnumNames<EffectFunction> kEffectFunctions;
extern const EnumNames<IntersectionType> kIntersectionTypes;

// ---- The reader --------------------------------------------------------------

// Walks the DOM, converting into the model while recording every problem with
// its JSON path. Each typed read returns false (leaving the target untouched)
// after recording why the value was not accepted.
class Reader {
 public:
  explicit Reader(std::vector<LoadIssue>& issues) : issues_(issues) {}

  void error(const std::string& where, std::string what);

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
  bool object(const InJson& j, const std::string& path, const std::vector<Field>& fields);

  bool boolean(const InJson& j, const std::string& path, bool& out);

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
  bool real(const InJson& j, const std::string& path, float& out);

  // Free text: no control characters (they would corrupt reports), at most
  // max_chars characters (UTF-8 code points).
  bool text(const InJson& j, const std::string& path, std::string& out,
            std::size_t max_chars = std::string::npos, std::string_view why = "");

  bool tag(const InJson& j, const std::string& path, std::string& out);

  // Optional tag: null and absence both mean "no tag".
  bool optional_tag(const InJson& j, const std::string& path, std::optional<std::string>& out);

  bool element_name(const InJson& j, const std::string& path, std::string& out);

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

  static std::string describe(const InJson& j);

 private:
  bool out_of_range(const std::string& path, const std::string& shown, long long lo, long long hi,
                    std::string_view why);

  std::vector<LoadIssue>& issues_;
};

inline constexpr long long kU32Max = std::numeric_limits<std::uint32_t>::max();

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

// The parts of a document (matrix_json_elements.cpp).
void read_sif_list(Reader& r, const InJson& j, const std::string& path, std::vector<int>& out);
void read_description(Reader& r, const InJson& j, const std::string& path, std::string& out);
Cause read_cause(Reader& r, const InJson& j, const std::string& path, bool& ok);
Effect read_effect(Reader& r, const InJson& j, const std::string& path, bool& ok);
Intersection read_intersection(Reader& r, const InJson& j, const std::string& path, bool& ok);

// The whole document (matrix_json_read.cpp).
void read_matrix(Reader& r, const InJson& root, Matrix& m);

}  // namespace cemv::formats::matrix_json_detail
