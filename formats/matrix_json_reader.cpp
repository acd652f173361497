// The typed reads of a cemv-matrix/1 DOM: each records why a value was not
// accepted, at its JSON path.
#include "formats/matrix_json_reader.hpp"

#include <algorithm>

#include "model/names.hpp"

namespace cemv::formats::matrix_json_detail {

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

void Reader::error(const std::string& where, std::string what) {
  if (issues_.size() < kMaxIssues) {
    issues_.push_back({where, std::move(what)});
  } else if (issues_.size() == kMaxIssues) {
    issues_.push_back({"", "too many problems; the rest are not listed"});
  }
}

bool Reader::object(const InJson& j, const std::string& path, const std::vector<Field>& fields) {
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

bool Reader::boolean(const InJson& j, const std::string& path, bool& out) {
  if (!j.is_boolean()) {
    error(path, "expected true or false, got " + describe(j));
    return false;
  }
  out = j.get<bool>();
  return true;
}

bool Reader::real(const InJson& j, const std::string& path, float& out) {
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

bool Reader::text(const InJson& j, const std::string& path, std::string& out,
                std::size_t max_chars, std::string_view why) {
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

bool Reader::tag(const InJson& j, const std::string& path, std::string& out) {
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

bool Reader::optional_tag(const InJson& j, const std::string& path, std::optional<std::string>& out) {
  if (j.is_null()) {
    out.reset();
    return true;
  }
  std::string s;
  if (!tag(j, path, s)) return false;
  out = std::move(s);
  return true;
}

bool Reader::element_name(const InJson& j, const std::string& path, std::string& out) {
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

std::string Reader::describe(const InJson& j) {
  switch (j.type()) {
    case InJson::value_t::object: return "an object";
    case InJson::value_t::array: return "an array";
    case InJson::value_t::string: return "the string " + in_quotes(j.get_ref<const std::string&>());
    case InJson::value_t::null: return "null";
    default: return printable(j.dump());
  }
}

bool Reader::out_of_range(const std::string& path, const std::string& shown, long long lo, long long hi,
                  std::string_view why) {
  error(path, shown + " is out of range " + std::to_string(lo) + "-" + std::to_string(hi) +
                  (why.empty() ? "" : " (" + std::string(why) + ")"));
  return false;
}

}  // namespace cemv::formats::matrix_json_detail
