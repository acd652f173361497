#include "model/matrix.hpp"

#include <algorithm>

namespace cemv::model {

void Matrix::sort_by_id() {
  std::stable_sort(causes.begin(), causes.end(),
                   [](const Cause& a, const Cause& b) { return a.id < b.id; });
  std::stable_sort(effects.begin(), effects.end(),
                   [](const Effect& a, const Effect& b) { return a.id < b.id; });
  std::stable_sort(intersections.begin(), intersections.end(),
                   [](const Intersection& a, const Intersection& b) {
                     return std::pair{a.cause, a.effect} < std::pair{b.cause, b.effect};
                   });
}

const Cause* Matrix::find_cause(int id) const {
  auto it = std::lower_bound(causes.begin(), causes.end(), id,
                             [](const Cause& c, int v) { return c.id < v; });
  return it != causes.end() && it->id == id ? &*it : nullptr;
}

const Effect* Matrix::find_effect(int id) const {
  auto it = std::lower_bound(effects.begin(), effects.end(), id,
                             [](const Effect& e, int v) { return e.id < v; });
  return it != effects.end() && it->id == id ? &*it : nullptr;
}

const Intersection* Matrix::find_intersection(int cause, int effect) const {
  auto it = std::lower_bound(intersections.begin(), intersections.end(), std::pair{cause, effect},
                             [](const Intersection& x, std::pair<int, int> v) {
                               return std::pair{x.cause, x.effect} < v;
                             });
  return it != intersections.end() && it->cause == cause && it->effect == effect ? &*it : nullptr;
}

std::vector<const Intersection*> Matrix::intersections_of_effect(int effect) const {
  std::vector<const Intersection*> out;
  for (const auto& x : intersections)
    if (x.effect == effect) out.push_back(&x);
  return out;
}

std::vector<const Intersection*> Matrix::intersections_of_cause(int cause) const {
  std::vector<const Intersection*> out;
  for (const auto& x : intersections)
    if (x.cause == cause) out.push_back(&x);
  return out;
}

const char* to_string(InputKind v) { return v == InputKind::Analog ? "analog" : "discrete"; }

const char* to_string(CauseFunction v) {
  switch (v) {
    case CauseFunction::Normal: return "normal";
    case CauseFunction::And: return "and";
    case CauseFunction::Or: return "or";
    case CauseFunction::TwoOoThree: return "2oo3";
    case CauseFunction::Comment: return "comment";
  }
  return "?";
}

const char* to_string(LimitType v) { return v == LimitType::Low ? "low" : "high"; }

const char* to_string(BadQuality v) {
  switch (v) {
    case BadQuality::Ignore: return "ignore";
    case BadQuality::Trip: return "trip";
    case BadQuality::Degrade: return "degrade";
  }
  return "?";
}

const char* to_string(TimeMode v) {
  switch (v) {
    case TimeMode::None: return "none";
    case TimeMode::OnDelay: return "on_delay";
    case TimeMode::OffDelay: return "off_delay";
    case TimeMode::Timed: return "timed";
  }
  return "?";
}

const char* to_string(EffectFunction v) { return v == EffectFunction::Comment ? "comment" : "normal"; }

const char* to_string(IntersectionType v) {
  switch (v) {
    case IntersectionType::N: return "N";
    case IntersectionType::S: return "S";
    case IntersectionType::V: return "V";
    case IntersectionType::R: return "R";
    case IntersectionType::X: return "X";
    case IntersectionType::Note: return "*";
  }
  return "?";
}

TagCount tag_count_of(CauseFunction f) {
  switch (f) {
    case CauseFunction::Normal: return {1, 1};
    case CauseFunction::And:
    case CauseFunction::Or: return {2, 3};
    case CauseFunction::TwoOoThree: return {3, 3};
    case CauseFunction::Comment: return {0, 3};
  }
  return {1, 1};
}

bool is_processed(IntersectionType t) {
  return t == IntersectionType::N || t == IntersectionType::S || t == IntersectionType::V ||
         t == IntersectionType::R;
}

}  // namespace cemv::model
