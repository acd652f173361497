// Plausibility checks of a matrix: the validation report of 11.5 ("errors and
// warnings, such as missing intersection configurations, effects without reset
// tags, multiple effects with the same output tag") and the conditions the
// manual states for each field (6.1.3-6.1.7, 6.3, 6.4, 6.5.2, 13).
//
// The loader checks each field on its own (types, ranges, tag syntax); this file
// checks what only the whole matrix can tell. It must never throw or loop on a
// matrix built in code, so nothing here assumes the loader ran: ids may repeat,
// intersections may dangle, vectors may be unsorted.
#include "model/validate.hpp"
#include "model/validate_checks.hpp"
#include "model/validate_timing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <charconv>
#include <map>
#include <set>
#include <stdexcept>
#include <string_view>
#include <tuple>

#include "model/graph.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::model {

namespace {

constexpr Severity E = Severity::Error;
constexpr Severity W = Severity::Warning;

// Sorted by id (the test checks it); docs/validation.md repeats this table.
const std::vector<RuleInfo> kRules = {
    {"E-ANALOG-MISSING", E, "6.3.4", "an analog cause has no analog parameters (limit type, limit)"},
    {"E-ANALOG-NOT-FINITE", E, "6.3.1", "an analog parameter is NaN or infinite (REAL must be a normalized number)"},
    {"E-COMMENT-INTERSECTION", E, "6.5.2", "a comment-only cause or effect has an N/S/V/R/X intersection, which is never processed"},
    {"E-CONTROL-TAG-COLLISION", E, "6.1.7", "a secure_write or group_deactivation tag is also a process tag of the matrix"},
    {"E-CYCLE-TIME", E, "6.2.1", "cycle_ms is 0"},
    {"E-DELTA-NEGATIVE", E, "6.3.5", "the delta (discrepancy) of an analog cause is negative"},
    {"E-DUPLICATE-CAUSE-ID", E, "6.3.3", "two causes have the same number"},
    {"E-DUPLICATE-CAUSE-NAME", E, "6.3.4", "two causes have the same name (case-insensitive)"},
    {"E-DUPLICATE-EFFECT-ID", E, "6.4.3", "two effects have the same number"},
    {"E-DUPLICATE-EFFECT-NAME", E, "6.4.4", "two effects have the same name (case-insensitive)"},
    {"E-EFFECT-TAG-COUNT", E, "6.4.1", "an effect has no output tag or more than four"},
    {"E-FIRST-OUT-RANGE", E, "6.3.6", "first_out_group is not 0 (none) or 1-15"},
    {"E-FUNCTION-TAG-COUNT", E, "6.3.1", "the number of input tags does not fit the function type (normal 1, and/or 2-3, 2oo3 3, comment 0-3)"},
    {"E-GDM-SAME-TAG", E, "6.1.7", "group deactivation uses one tag as both enable_tag and set_tag"},
    {"E-HYSTERESIS-NEGATIVE", E, "6.3.5", "the hysteresis of an analog cause is negative"},
    {"E-ID-RANGE", E, "3.4", "a cause or effect number is outside 1-128"},
    {"E-INTERSECTION-DANGLING", E, "6.5.1", "an intersection names a cause or effect that does not exist"},
    {"E-INTERSECTION-REPEATED", E, "6.5.1", "the same cause/effect pair has more than one intersection"},
    {"E-INTERSECTION-X", E, "6.5.2", "intersection type X (not yet specified): the matrix cannot be verified or transferred"},
    {"E-LIMIT", E, "3.4", "more than 128 causes, 128 effects or 1024 intersections"},
    {"E-OUTPUT-TAG-REFERENCE", E, "6.1.3", "an output tag is an internal reference (Cause[x], Effect[x], Effect[x][y]), which can only be read"},
    {"E-OUTPUT-TAG-REPEATED", E, "6.4.4", "one effect lists the same output tag twice"},
    {"E-OUTPUT-TAG-SHARED", E, "11.5", "several effects write the same output tag"},
    {"E-OVERRIDE-TIME-MISSING", E, "6.5.2", "an effect with V or R intersections has no maximum override time (override.max_s)"},
    {"E-PROCESS-DATA-TAG-MISSING", E, "13.2.5", "pass-through or mask is configured without a process data tag"},
    {"E-REF-ANALOG", E, "6.3.4", "an analog cause reads an internal reference, which is Boolean"},
    {"E-REF-MISSING", E, "6.1.3", "an internal reference names a cause, effect or effect tag that does not exist"},
    {"E-SIF-GROUP-RANGE", E, "6.2.1", "a sif_groups number is outside 1-64"},
    {"E-SIF-RANGE", E, "6.3.6", "an element has a SIF number outside 1-64 or more than four SIF groups"},
    {"E-TAG-IN-AND-OUT", E, "6.1.3", "a tag is both written by an effect and read by the matrix"},
    {"E-TAG-KIND-CONFLICT", E, "6.3.4", "a tag is read as an analog value by one cause and as a Boolean elsewhere"},
    {"E-TIMED-CAUSE-ZERO", E, "6.3.6", "a timed cause with duration 0 would never be active"},
    {"E-WATCHDOG-CYCLE", E, "HIMatrix 3.2.3", "the watchdog time is shorter than the cycle"},
    {"E-XOON-COUNT", E, "6.5.2", "the X of an XooN assignment exceeds N, the number of its intersections"},
    {"E-XOON-MIXED-TYPE", E, "6.5.2", "the intersections of one XooN assignment are not all of one type"},
    {"E-XOON-MIXED-X", E, "6.5.2", "the intersections of one effect carry different X values (only one XooN assignment per effect)"},
    {"E-XOON-NOT-PROCESSED", E, "6.5.2", "an XooN value on a '*' (note only) intersection, which is not processed"},
    {"E-XOON-RANGE", E, "6.5.2", "the X of an XooN assignment is outside 2-15"},
    {"W-ACK-NO-EFFECT", W, "6.3.6", "manual acknowledgement (auto_ack false) has no effect with an OFF delay or a timed cause"},
    {"W-ANALOG-UNUSED", W, "6.3.5", "a discrete cause has analog parameters, which are ignored"},
    {"W-BAD-QUALITY-IGNORED", W, "6.3.6", "bad quality is ignored where the channel driver's substitute value 0.0 / FALSE does not trip: a channel fault goes unnoticed"},
    {"W-CAUSE-SELF-BYPASS", W, "6.3.6", "a cause's bypass or inhibit tag is one of its own input tags"},
    {"W-CAUSE-UNUSED", W, "11.5", "a cause has no intersection and no internal reference reads it"},
    {"W-DELTA-HYSTERESIS", W, "6.3.5", "hysteresis >= delta: the discrepancy alarm can never clear"},
    {"W-DELTA-SINGLE-TAG", W, "6.3.5", "a delta on a cause with one input tag is ignored"},
    {"W-EFFECT-UNDRIVEN", W, "11.5", "an effect has no cause (no intersection): it never trips"},
    {"W-INPUT-TAG-REPEATED", W, "6.3.1", "one cause lists the same input tag twice, defeating its redundancy"},
    {"W-INPUT-TAG-SHARED", W, "6.1.3", "the same input tag is read by two causes"},
    {"W-OVERRIDE-PREALARM", W, "6.4.5", "the override prealarm is not shorter than the maximum override time"},
    {"W-OVERRIDE-UNUSED", W, "13.2.1", "an override time on an effect without V or R intersections has no effect"},
    {"W-PREWARNING-BEYOND-LIMIT", W, "6.3.5", "the prewarning is at or beyond the limit (high: >= limit, low: <= limit), which disables it"},
    {"W-PROCESS-DATA-UNUSED", W, "13.2.5", "a process data tag without pass-through and without mask has no effect"},
    {"W-PST-CONTROLLER", W, "HIMatrix 3.2.3", "a process safety time is not longer than twice the watchdog time (or cycle)"},
    {"W-REF-COMMENT", W, "6.1.3", "an internal reference names a comment-only cause or effect, which is never active"},
    {"W-REF-CYCLE", W, "8.3", "internal references form a cycle: one reader sees the previous scan cycle's value"},
    {"W-RESET-OPERATOR-ONLY", W, "6.5.2", "an effect with S or R intersections has no reset tag: only the operator can reset it"},
    {"W-RESET-TAG-UNUSED", W, "13.2.1", "a reset/override tag on an effect with only N intersections has no effect"},
    {"W-SIF-NO-PST", W, "HIMatrix 3.2.1", "a SIF group with members declares no process safety time"},
    {"W-SIF-PST-NO-MEMBERS", W, "6.2.1", "a SIF group declares a process safety time but has no members"},
    {"W-SIF-UNDEFINED", W, "6.2.1", "an element names a SIF group that sif_groups does not define"},
    {"W-SIMULATION-UNRESTRICTED", W, "10.7.3.4", "every cause input tag and output tag may be simulated: no tag restricts simulation (simulation_allowed)"},
    {"W-SOFT-BYPASS-PREALARM", W, "6.3.6", "the soft bypass prealarm is set without a bypass time or is not shorter than it"},
    {"W-SOFT-BYPASS-UNTIMED", W, "6.3.6", "a SIL-rated cause may be soft-bypassed without a time limit (soft_bypass.max_s 0)"},
    {"W-SOFT-BYPASS-UNUSED", W, "6.3.6", "a soft bypass time on a cause whose soft bypass is not allowed"},
    {"W-TIME-UNUSED", W, "6.3.6", "a cause with time mode none has a duration, which is ignored"},
    {"W-TIME-ZERO", W, "6.3.6", "an ON or OFF delay of 0 ms acts as no delay"},
    {"W-TIMER-ROUNDING", W, "13", "a duration is not a multiple of cycle_ms: it is rounded up to whole cycles"},
};

const RuleInfo& rule_info(std::string_view id) {
  auto it = std::lower_bound(kRules.begin(), kRules.end(), id,
                             [](const RuleInfo& r, std::string_view v) { return r.id < v; });
  if (it == kRules.end() || it->id != id)  // a programming error, caught by the tests
    throw std::logic_error("validate: unknown rule " + std::string(id));
  return *it;
}

}  // namespace

namespace validation {

Where at_matrix() { return {0, 0, 0, "matrix"}; }
std::string cause_label(const Cause& c) {
  return "cause[" + std::to_string(c.id) + "]" + (c.name.empty() ? "" : " " + c.name);
}
std::string effect_label(const Effect& e) {
  return "effect[" + std::to_string(e.id) + "]" + (e.name.empty() ? "" : " " + e.name);
}
Where at(const Cause& c) { return {1, c.id, 0, cause_label(c)}; }
Where at(const Effect& e) { return {2, e.id, 0, effect_label(e)}; }
Where at(const Intersection& x) {
  return {3, x.cause, x.effect,
          "intersection cause[" + std::to_string(x.cause) + "]/effect[" + std::to_string(x.effect) +
              "]"};
}
Where at(const Node& n) {
  return {n.kind == Node::Kind::Cause ? 1 : 2, n.id, 0, to_string(n)};
}

Checks::Checks(const Matrix& m, std::vector<Finding>& out) : m_(m), out_(out) {
  for (const auto& c : m.causes) causes_by_id_.emplace(c.id, &c);
  for (const auto& e : m.effects) effects_by_id_.emplace(e.id, &e);
}

void record(std::vector<Finding>& out, std::string_view rule, const Where& where, std::string message) {
  const RuleInfo& info = rule_info(rule);
  out.push_back({where, Diagnostic{info.severity, info.id, where.text, info.section, std::move(message)}});
}

void Checks::add(std::string_view rule, const Where& where, std::string message) {
  record(out_, rule, where, std::move(message));
}

const Cause* Checks::cause_by_id(int id) const {
  auto it = causes_by_id_.find(id);
  return it == causes_by_id_.end() ? nullptr : it->second;
}

const Effect* Checks::effect_by_id(int id) const {
  auto it = effects_by_id_.find(id);
  return it == effects_by_id_.end() ? nullptr : it->second;
}

std::vector<const Intersection*> Checks::links_of_effect(int effect) const {
  std::vector<const Intersection*> out;
  for (const auto& x : m_.intersections)
    if (x.effect == effect && cause_by_id(x.cause)) out.push_back(&x);
  return out;
}

}  // namespace validation

std::vector<Diagnostic> validate(const Matrix& m) {
  using namespace validation;
  std::vector<Finding> found;
  check_elements(m, found);
  check_intersections(m, found);
  check_tags(m, found);
  check_graph(m, found);
  for (auto& f : detail::timing_findings(m))
    record(found, f.rule, Where{f.rank, f.id, 0, f.element}, std::move(f.message));
  std::stable_sort(found.begin(), found.end(), [](const Finding& x, const Finding& y) {
    return std::tie(x.d.rule, x.where.rank, x.where.a, x.where.b, x.d.message) <
           std::tie(y.d.rule, y.where.rank, y.where.a, y.where.b, y.d.message);
  });
  std::vector<Diagnostic> ds;
  for (auto& f : found) ds.push_back(std::move(f.d));
  return ds;
}

bool has_errors(const std::vector<Diagnostic>& ds) {
  return std::any_of(ds.begin(), ds.end(),
                     [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

const std::vector<RuleInfo>& validation_rules() { return kRules; }

const char* to_string(Severity s) { return s == Severity::Error ? "error" : "warning"; }

}  // namespace cemv::model