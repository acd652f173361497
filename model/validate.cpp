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

// Where a finding is, and how it sorts: matrix, then causes, effects and
// intersections by id.
struct Where {
  int rank = 0;
  int a = 0;
  int b = 0;
  std::string text;
};

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

struct Finding {
  Where where;
  Diagnostic d;
};

// One use of an external tag by the matrix.
enum class Use { AnalogInput, DiscreteInput, Control, Output, MatrixControl };
struct TagUse {
  Use use;
  Where where;       // the element (or the matrix)
  std::string what;  // "input tag 2", "bypass_tag", "output tag 1", "secure_write.enable_tag"
  std::string name;  // as written
  int owner = 0;     // element id (0 for the matrix)
};

class Validator {
 public:
  explicit Validator(const Matrix& m) : m_(m) {
    for (const auto& c : m.causes) causes_by_id_.emplace(c.id, &c);
    for (const auto& e : m.effects) effects_by_id_.emplace(e.id, &e);
  }

  std::vector<Diagnostic> run() {
    matrix_level();
    ids_and_names();
    for (const auto& c : m_.causes) cause(c);
    for (const auto& e : m_.effects) effect(e);
    intersections();
    xoon();
    tags();
    references();
    connectivity();
    simulation();
    for (auto& f : detail::timing_findings(m_)) add(f.rule, Where{f.rank, f.id, 0, f.element}, std::move(f.message));
    std::stable_sort(out_.begin(), out_.end(), [](const Finding& x, const Finding& y) {
      return std::tie(x.d.rule, x.where.rank, x.where.a, x.where.b, x.d.message) <
             std::tie(y.d.rule, y.where.rank, y.where.a, y.where.b, y.d.message);
    });
    std::vector<Diagnostic> ds;
    for (auto& f : out_) ds.push_back(std::move(f.d));
    return ds;
  }

 private:
  const Matrix& m_;
  std::multimap<int, const Cause*> causes_by_id_;
  std::multimap<int, const Effect*> effects_by_id_;
  std::vector<Finding> out_;

  void add(std::string_view rule, const Where& where, std::string message) {
    const RuleInfo& info = rule_info(rule);
    out_.push_back({where, Diagnostic{info.severity, info.id, where.text, info.section,
                                      std::move(message)}});
  }

  const Cause* cause_by_id(int id) const {
    auto it = causes_by_id_.find(id);
    return it == causes_by_id_.end() ? nullptr : it->second;
  }
  const Effect* effect_by_id(int id) const {
    auto it = effects_by_id_.find(id);
    return it == effects_by_id_.end() ? nullptr : it->second;
  }
  static bool processed(const Cause& c) { return c.function != CauseFunction::Comment; }
  static bool processed(const Effect& e) { return e.function != EffectFunction::Comment; }

  // Intersections of an effect that exist and are valid links (both ends exist).
  std::vector<const Intersection*> links_of_effect(int effect) const {
    std::vector<const Intersection*> out;
    for (const auto& x : m_.intersections)
      if (x.effect == effect && cause_by_id(x.cause)) out.push_back(&x);
    return out;
  }

  // ---- matrix ---------------------------------------------------------------

  void matrix_level() {
    if (m_.cycle_ms == 0)
      add("E-CYCLE-TIME", at_matrix(), "cycle_ms is 0: a scan cycle must take time");
    auto limit = [&](std::size_t n, int max, const char* what) {
      if (n > static_cast<std::size_t>(max))
        add("E-LIMIT", at_matrix(),
            std::to_string(n) + " " + what + " (at most " + std::to_string(max) + ")");
    };
    limit(m_.causes.size(), kMaxCauses, "causes");
    limit(m_.effects.size(), kMaxEffects, "effects");
    limit(m_.intersections.size(), kMaxIntersections, "intersections");
    for (const auto& [number, name] : m_.sif_groups)
      if (number < 1 || number > kMaxSifGroups)
        add("E-SIF-GROUP-RANGE", at_matrix(),
            "sif_groups defines group " + std::to_string(number) + " " + in_quotes(name) +
                " (groups are numbered 1-" + std::to_string(kMaxSifGroups) + ")");
    if (m_.group_deactivation && !m_.group_deactivation->enable_tag.empty() &&
        tag_key(m_.group_deactivation->enable_tag) == tag_key(m_.group_deactivation->set_tag))
      add("E-GDM-SAME-TAG", at_matrix(),
          "group_deactivation uses " + in_quotes(m_.group_deactivation->set_tag) +
              " as enable_tag and set_tag: enabling and executing the deactivation would be one "
              "operation, which 6.1.7 forbids");
  }

  // ---- ids, names, SIF, first out ------------------------------------------

  template <class T>
  void duplicates(const std::vector<T>& elements, const char* id_rule, const char* name_rule,
                  const char* kind) {
    std::map<int, const T*> by_id;
    std::map<std::string, const T*> by_name;
    for (const auto& el : elements) {
      auto [it, fresh] = by_id.emplace(el.id, &el);
      if (!fresh)
        add(id_rule, at(el),
            std::string(kind) + " number " + std::to_string(el.id) + " is also used by " +
                (it->second->name.empty() ? std::string("another ") + kind
                                          : in_quotes(it->second->name)));
      if (el.name.empty()) continue;
      auto [nit, nfresh] = by_name.emplace(tag_key(el.name), &el);
      if (!nfresh)
        add(name_rule, at(el),
            "name " + in_quotes(el.name) + " is also the name of " + kind + "[" +
                std::to_string(nit->second->id) + "] (names are compared case-insensitively)");
    }
  }

  template <class T>
  void element_common(const T& el, const char* kind, int max_id) {
    if (el.id < 1 || el.id > max_id)
      add("E-ID-RANGE", at(el),
          std::string(kind) + " number " + std::to_string(el.id) + " is outside 1-" +
              std::to_string(max_id));
    if (el.sif.size() > static_cast<std::size_t>(kMaxSifPerElement))
      add("E-SIF-RANGE", at(el),
          std::to_string(el.sif.size()) + " SIF groups (at most " +
              std::to_string(kMaxSifPerElement) + ")");
    for (int s : el.sif) {
      if (s < 1 || s > kMaxSifGroups) {
        add("E-SIF-RANGE", at(el),
            "SIF " + std::to_string(s) + " is outside 1-" + std::to_string(kMaxSifGroups));
      } else if (!m_.sif_groups.count(s)) {
        add("W-SIF-UNDEFINED", at(el),
            "SIF " + std::to_string(s) + " is not defined in sif_groups (it has no name)");
      }
    }
  }

  void ids_and_names() {
    duplicates(m_.causes, "E-DUPLICATE-CAUSE-ID", "E-DUPLICATE-CAUSE-NAME", "cause");
    duplicates(m_.effects, "E-DUPLICATE-EFFECT-ID", "E-DUPLICATE-EFFECT-NAME", "effect");
    for (const auto& c : m_.causes) element_common(c, "cause", kMaxCauses);
    for (const auto& e : m_.effects) element_common(e, "effect", kMaxEffects);
  }

  // ---- timers ----------------------------------------------------------------

  // Durations in seconds are converted to ms (docs/semantics.md T.2: durations "given in
  // seconds ... are first converted to ms") and then count whole cycles like every other timer.
  void rounding(const Where& where, const std::string& field, std::uint64_t ms,
                bool seconds = false) {
    if (m_.cycle_ms == 0 || ms == 0 || ms % m_.cycle_ms == 0) return;
    std::uint64_t cycles = (ms + m_.cycle_ms - 1) / m_.cycle_ms;
    std::string value = seconds ? std::to_string(ms / 1000) + " s (" + std::to_string(ms) + " ms)"
                                : std::to_string(ms) + " ms";
    add("W-TIMER-ROUNDING", where,
        field + " = " + value + " is not a multiple of cycle_ms " +
            std::to_string(m_.cycle_ms) + ": it acts as " + std::to_string(cycles * m_.cycle_ms) +
            " ms (" + std::to_string(cycles) + " cycles)");
  }

  // ---- causes ----------------------------------------------------------------

  void cause(const Cause& c) {
    const Where w = at(c);
    TagCount tc = tag_count_of(c.function);
    int n = static_cast<int>(c.tags.size());
    if (n < tc.min || n > tc.max)
      add("E-FUNCTION-TAG-COUNT", w,
          "function " + std::string(to_string(c.function)) + " takes " +
              (tc.min == tc.max ? std::to_string(tc.min)
                                : std::to_string(tc.min) + "-" + std::to_string(tc.max)) +
              (tc.max == 1 ? " input tag" : " input tags") + ", the cause has " +
              std::to_string(n));
    if (c.first_out_group < 0 || c.first_out_group > kMaxFirstOutGroup)
      add("E-FIRST-OUT-RANGE", w,
          "first_out_group " + std::to_string(c.first_out_group) + " is not 0 (none) or 1-" +
              std::to_string(kMaxFirstOutGroup));
    if (!processed(c)) return;  // parameters of a comment-only cause are never used

    if (c.input == InputKind::Analog && !c.analog)
      add("E-ANALOG-MISSING", w, "input is analog but the cause has no analog block (limit)");
    if (c.input == InputKind::Discrete && c.analog)
      add("W-ANALOG-UNUSED", w,
          "input is discrete: the analog block (limit " + float_text(c.analog->limit) + ") is ignored");
    if (c.input == InputKind::Analog && c.analog) analog(c, *c.analog);

    // Time function (6.3.6, 13.1.1).
    if (c.time.mode == TimeMode::None && c.time.ms != 0)
      add("W-TIME-UNUSED", w,
          "time.mode is none: time.ms = " + std::to_string(c.time.ms) + " is ignored");
    if ((c.time.mode == TimeMode::OnDelay || c.time.mode == TimeMode::OffDelay) && c.time.ms == 0)
      add("W-TIME-ZERO", w,
          std::string("time.mode is ") + to_string(c.time.mode) + " with time.ms = 0: no delay");
    if (c.time.mode == TimeMode::Timed && c.time.ms == 0)
      add("E-TIMED-CAUSE-ZERO", w,
          "time.mode is timed with time.ms = 0: the timer expires in the cycle it starts, so the "
          "cause is never active");
    if (c.time.mode != TimeMode::None) rounding(w, "time.ms", c.time.ms);
    if (!c.auto_ack && (c.time.mode == TimeMode::OffDelay || c.time.mode == TimeMode::Timed))
      add("W-ACK-NO-EFFECT", w,
          std::string("auto_ack is false but time.mode is ") + to_string(c.time.mode) +
              ": acknowledgement applies only with none or on_delay");

    // 6.3.6 note on 'Ignore "Bad Quality"': the F-channel drivers deliver the
    // substitute value 0.0 (FALSE) on a channel fault. Where that value is not
    // a trip, ignoring bad quality hides a failed sensor.
    if (c.bad_quality == BadQuality::Ignore) {
      if (c.input == InputKind::Analog && c.analog && c.analog->limit_type == LimitType::High &&
          c.analog->limit > 0.0f)
        add("W-BAD-QUALITY-IGNORED", w,
            "bad_quality is ignore: on a channel fault the substitute value 0.0 stays below the "
            "high limit " + float_text(c.analog->limit) + ", so a failed sensor never trips the cause");
      if (c.input == InputKind::Discrete)
        for (std::size_t i = 0; i < c.tags.size(); ++i)
          if (c.tags[i].ett && !parse_internal_ref(c.tags[i].name))
            add("W-BAD-QUALITY-IGNORED", w,
                "bad_quality is ignore: input tag " + std::to_string(i + 1) + " " +
                    in_quotes(c.tags[i].name) +
                    " is energize-to-trip, so the substitute value FALSE of a channel fault "
                    "never trips it");
    }

    // Soft bypass of the whole cause (6.3.6).
    const auto& sb = c.soft_bypass;
    if (!sb.allowed && (sb.max_s != 0 || sb.prealarm_s != 0))
      add("W-SOFT-BYPASS-UNUSED", w,
          "soft_bypass.allowed is false: max_s = " + std::to_string(sb.max_s) +
              " and prealarm_s = " + std::to_string(sb.prealarm_s) + " are never used");
    if (sb.allowed && sb.prealarm_s != 0 && (sb.max_s == 0 || sb.prealarm_s >= sb.max_s))
      add("W-SOFT-BYPASS-PREALARM", w,
          sb.max_s == 0 ? "soft_bypass.prealarm_s = " + std::to_string(sb.prealarm_s) +
                              " but the soft bypass is untimed (max_s = 0): no prealarm"
                        : "soft_bypass.prealarm_s = " + std::to_string(sb.prealarm_s) +
                              " >= max_s = " + std::to_string(sb.max_s) +
                              ": the prealarm never comes before the timeout");
    if (sb.allowed && sb.max_s == 0 && c.sil >= 1)
      add("W-SOFT-BYPASS-UNTIMED", w,
          "a SIL " + std::to_string(c.sil) + " cause whose soft bypass is allowed without a time limit "
          "(soft_bypass.max_s = 0): a forgotten bypass disables it for good; set a maximum bypass time or "
          "disallow the soft bypass");
    if (sb.allowed) {
      rounding(w, "soft_bypass.max_s", std::uint64_t{sb.max_s} * 1000, true);
      rounding(w, "soft_bypass.prealarm_s", std::uint64_t{sb.prealarm_s} * 1000, true);
    }

    // A cause that bypasses or inhibits itself with its own input (6.3.6).
    for (std::size_t i = 0; i < c.tags.size(); ++i) {
      auto same = [&](const std::optional<std::string>& t) {
        return t && !parse_internal_ref(*t) && tag_key(*t) == tag_key(c.tags[i].name);
      };
      if (same(c.bypass_tag))
        add("W-CAUSE-SELF-BYPASS", w,
            "bypass_tag " + in_quotes(*c.bypass_tag) + " is also input tag " + std::to_string(i + 1));
      if (same(c.inhibit_tag))
        add("W-CAUSE-SELF-BYPASS", w,
            "inhibit_tag " + in_quotes(*c.inhibit_tag) + " is also input tag " +
                std::to_string(i + 1));
    }
  }

  void analog(const Cause& c, const AnalogParams& a) {
    const Where w = at(c);
    bool finite = std::isfinite(a.limit) && std::isfinite(a.hysteresis) &&
                  std::isfinite(a.delta) && (!a.prewarning || std::isfinite(*a.prewarning));
    if (!finite) {
      add("E-ANALOG-NOT-FINITE", w, "an analog parameter (limit, hysteresis, prewarning, delta) is "
                                    "NaN or infinite");
      return;
    }
    if (a.hysteresis < 0)
      add("E-HYSTERESIS-NEGATIVE", w, "hysteresis " + float_text(a.hysteresis) + " is negative");
    if (a.delta < 0) add("E-DELTA-NEGATIVE", w, "delta " + float_text(a.delta) + " is negative");
    if (a.delta > 0 && c.tags.size() < 2)
      add("W-DELTA-SINGLE-TAG", w,
          "delta " + float_text(a.delta) + " on a cause with one input tag: there is nothing to compare");
    if (a.delta > 0 && c.tags.size() >= 2 && a.hysteresis >= a.delta)
      add("W-DELTA-HYSTERESIS", w,
          "hysteresis " + float_text(a.hysteresis) + " >= delta " + float_text(a.delta) +
              ": the discrepancy alarm clears only below delta - hysteresis <= 0, i.e. never");
    if (a.prewarning) {
      bool high = a.limit_type == LimitType::High;
      if (high ? *a.prewarning >= a.limit : *a.prewarning <= a.limit)
        add("W-PREWARNING-BEYOND-LIMIT", w,
            "prewarning " + float_text(*a.prewarning) + (high ? " >= " : " <= ") + std::string(high ? "high" : "low") +
                " limit " + float_text(a.limit) + ": the prewarning is disabled");
    }
  }

  // ---- effects ---------------------------------------------------------------

  void effect(const Effect& e) {
    const Where w = at(e);
    int n = static_cast<int>(e.tags.size());
    int min = processed(e) ? 1 : 0;
    if (n < min || n > kMaxEffectTags)
      add("E-EFFECT-TAG-COUNT", w,
          "the effect has " + std::to_string(n) + " output tags (" + std::to_string(min) + "-" +
              std::to_string(kMaxEffectTags) + ")");
    if (!processed(e)) return;

    bool has_v_or_r = false, has_s_or_r = false, has_svr = false;
    for (const auto* x : links_of_effect(e.id)) {
      has_v_or_r |= x->type == IntersectionType::V || x->type == IntersectionType::R;
      has_s_or_r |= x->type == IntersectionType::S || x->type == IntersectionType::R;
    }
    has_svr = has_v_or_r || has_s_or_r;
    std::uint32_t max_s = e.override_time ? e.override_time->max_s : 0;
    std::uint32_t prealarm_s = e.override_time ? e.override_time->prealarm_s : 0;
    if (has_v_or_r && max_s == 0) {
      std::string links;
      for (const auto* x : links_of_effect(e.id))
        if (x->type == IntersectionType::V || x->type == IntersectionType::R)
          links += (links.empty() ? "" : ", ") + std::string(to_string(x->type)) + " from cause[" +
                   std::to_string(x->cause) + "]";
      add("E-OVERRIDE-TIME-MISSING", w,
          "the effect has V or R intersections (" + links +
              ") but no maximum override time (override.max_s)");
    }
    if (!has_v_or_r && e.override_time && (max_s != 0 || prealarm_s != 0))
      add("W-OVERRIDE-UNUSED", w,
          "override.max_s = " + std::to_string(max_s) +
              " but the effect has no V or R intersection: it can never be overridden");
    if (has_v_or_r && max_s != 0 && prealarm_s != 0 && prealarm_s >= max_s)
      add("W-OVERRIDE-PREALARM", w,
          "override.prealarm_s = " + std::to_string(prealarm_s) + " >= max_s = " +
              std::to_string(max_s) + ": the prealarm never comes before the timeout");
    if (has_s_or_r && !e.reset_tag)
      add("W-RESET-OPERATOR-ONLY", w,
          "the effect has S or R intersections but no reset_tag: only an operator reset (secure "
          "write) clears it");
    if (!has_svr && e.reset_tag)
      add("W-RESET-TAG-UNUSED", w,
          "reset_tag " + in_quotes(*e.reset_tag) +
              " on an effect without S, V or R intersections: nothing to reset or override");

    rounding(w, "output_delay_ms", e.output_delay_ms);
    if (has_v_or_r) {
      rounding(w, "override.max_s", std::uint64_t{max_s} * 1000, true);
      rounding(w, "override.prealarm_s", std::uint64_t{prealarm_s} * 1000, true);
    }

    if (e.process_data) {
      const auto& pd = *e.process_data;
      bool has_tag = pd.tag && !pd.tag->empty();
      if (!has_tag && (pd.pass_through || pd.mask_tag))
        add("E-PROCESS-DATA-TAG-MISSING", w,
            std::string(pd.pass_through ? "pass_through" : "mask_tag") +
                " is configured but process_data.tag is not: there is no process value to pass");
      if (has_tag && !pd.pass_through && !pd.mask_tag)
        add("W-PROCESS-DATA-UNUSED", w,
            "process_data.tag " + in_quotes(*pd.tag) +
                " without pass_through or mask_tag has no effect on the outputs");
    }
  }

  // ---- intersections ---------------------------------------------------------

  void intersections() {
    std::set<std::pair<int, int>> seen;
    for (const auto& x : m_.intersections) {
      const Where w = at(x);
      const Cause* c = cause_by_id(x.cause);
      const Effect* e = effect_by_id(x.effect);
      if (!c || !e) {
        std::string missing = !c ? "cause " + std::to_string(x.cause) : "";
        if (!e) missing += (missing.empty() ? "" : " and ") + ("effect " + std::to_string(x.effect));
        add("E-INTERSECTION-DANGLING", w, missing + " does not exist");
      }
      if (!seen.insert({x.cause, x.effect}).second)
        add("E-INTERSECTION-REPEATED", w,
            "a second intersection (type " + std::string(to_string(x.type)) +
                ") for the same cause and effect");
      if (x.type == IntersectionType::X)
        add("E-INTERSECTION-X", w,
            "intersection type X is not yet specified: the matrix can be neither verified nor "
            "transferred until the type is chosen");
      if (x.type != IntersectionType::Note && c && e && (!processed(*c) || !processed(*e)))
        add("E-COMMENT-INTERSECTION", w,
            "type " + std::string(to_string(x.type)) + " links " +
                (!processed(*c) ? "a comment-only cause" : "a comment-only effect") +
                ": it is never processed (use '*' for a note)");
    }
  }

  // XooN majority assignment (6.5.2): X from the user, N the number of the
  // effect's intersections carrying X, one assignment per effect, one type.
  void xoon() {
    std::map<int, std::vector<const Intersection*>> by_effect;
    for (const auto& x : m_.intersections)
      if (x.xoon) by_effect[x.effect].push_back(&x);
    for (const auto& [effect_id, xs] : by_effect) {
      const Effect* e = effect_by_id(effect_id);
      Where w = e ? at(*e) : Where{2, effect_id, 0, "effect[" + std::to_string(effect_id) + "]"};
      int n = static_cast<int>(xs.size());
      std::set<int> xvals;
      std::set<IntersectionType> types;
      for (const auto* x : xs) {
        if (*x->xoon < kMinXooN || *x->xoon > kMaxXooN)
          add("E-XOON-RANGE", at(*x),
              "xoon " + std::to_string(*x->xoon) + " is outside " + std::to_string(kMinXooN) +
                  "-" + std::to_string(kMaxXooN));
        if (x->type == IntersectionType::Note)
          add("E-XOON-NOT-PROCESSED", at(*x),
              "xoon " + std::to_string(*x->xoon) +
                  " on a '*' (note only) intersection, which is never processed");
        xvals.insert(*x->xoon);
        types.insert(x->type);
      }
      if (xvals.size() > 1) {
        std::string list;
        for (int v : xvals) list += (list.empty() ? "" : ", ") + std::to_string(v);
        add("E-XOON-MIXED-X", w,
            "the intersections carry X = " + list +
                ": only one XooN assignment is allowed per effect");
      }
      if (types.size() > 1) {
        std::string list;
        for (auto t : types) list += (list.empty() ? "" : ", ") + std::string(to_string(t));
        add("E-XOON-MIXED-TYPE", w,
            "the XooN intersections have types " + list + ": they must all be of one type");
      }
      int x_max = *xvals.rbegin();
      if (x_max > n)
        add("E-XOON-COUNT", w,
            std::to_string(x_max) + "oo" + std::to_string(n) + ": X exceeds N = " +
                std::to_string(n) + " (the number of the effect's intersections with an xoon "
                                     "value), so the assignment can never trip");
    }
  }

  // ---- external tags ---------------------------------------------------------

  void tags() {
    std::map<std::string, std::vector<TagUse>> uses;
    auto use = [&](const std::optional<std::string>& name, Use kind, const Where& where,
                   std::string what, int owner) {
      if (!name || name->empty() || parse_internal_ref(*name)) return;
      uses[tag_key(*name)].push_back({kind, where, std::move(what), *name, owner});
    };
    if (m_.secure_write)
      use(m_.secure_write->enable_tag, Use::MatrixControl, at_matrix(), "secure_write.enable_tag",
          0);
    if (m_.group_deactivation) {
      use(m_.group_deactivation->enable_tag, Use::MatrixControl, at_matrix(),
          "group_deactivation.enable_tag", 0);
      use(m_.group_deactivation->set_tag, Use::MatrixControl, at_matrix(),
          "group_deactivation.set_tag", 0);
    }
    for (const auto& c : m_.causes) {
      if (!processed(c)) continue;
      for (std::size_t i = 0; i < c.tags.size(); ++i)
        use(c.tags[i].name, c.input == InputKind::Analog ? Use::AnalogInput : Use::DiscreteInput,
            at(c), "input tag " + std::to_string(i + 1), c.id);
      use(c.bypass_tag, Use::Control, at(c), "bypass_tag", c.id);
      use(c.inhibit_tag, Use::Control, at(c), "inhibit_tag", c.id);
    }
    for (const auto& e : m_.effects) {
      if (!processed(e)) continue;
      for (std::size_t i = 0; i < e.tags.size(); ++i) {
        if (parse_internal_ref(e.tags[i].name))
          add("E-OUTPUT-TAG-REFERENCE", at(e),
              "output tag " + std::to_string(i + 1) + " " + in_quotes(e.tags[i].name) +
                  " is an internal reference: references can only be read");
        use(e.tags[i].name, Use::Output, at(e), "output tag " + std::to_string(i + 1), e.id);
      }
      use(e.bypass_tag, Use::Control, at(e), "bypass_tag", e.id);
      use(e.reset_tag, Use::Control, at(e), "reset_tag", e.id);
      if (e.process_data) {
        use(e.process_data->tag, Use::Control, at(e), "process_data.tag", e.id);
        use(e.process_data->mask_tag, Use::Control, at(e), "process_data.mask_tag", e.id);
      }
    }

    auto describe = [](const TagUse& u) { return u.where.text + " (" + u.what + ")"; };
    for (const auto& [key, list] : uses) {
      const std::string& name = list.front().name;
      // Outputs: one writer per tag (11.5), never read by the matrix itself.
      std::vector<const TagUse*> outputs, readers, inputs, matrix_controls, others, analog,
          boolean;
      for (const auto& u : list) {
        (u.use == Use::Output ? outputs : readers).push_back(&u);
        if (u.use == Use::AnalogInput || u.use == Use::DiscreteInput) inputs.push_back(&u);
        (u.use == Use::MatrixControl ? matrix_controls : others).push_back(&u);
        if (u.use == Use::AnalogInput) analog.push_back(&u);
        if (u.use == Use::DiscreteInput || u.use == Use::Control || u.use == Use::MatrixControl)
          boolean.push_back(&u);
      }
      for (std::size_t i = 1; i < outputs.size(); ++i) {
        const TagUse* first = outputs.front();
        if (outputs[i]->owner == first->owner)
          add("E-OUTPUT-TAG-REPEATED", outputs[i]->where,
              outputs[i]->what + " " + in_quotes(outputs[i]->name) + " repeats " + first->what);
        else
          add("E-OUTPUT-TAG-SHARED", outputs[i]->where,
              outputs[i]->what + " " + in_quotes(outputs[i]->name) + " is also written by " +
                  describe(*first));
      }
      if (!outputs.empty() && !readers.empty()) {
        std::string list_text;
        for (const auto* r : readers) list_text += (list_text.empty() ? "" : ", ") + describe(*r);
        add("E-TAG-IN-AND-OUT", outputs.front()->where,
            outputs.front()->what + " " + in_quotes(name) + " is also read by " + list_text +
                " (use an internal reference Effect[x] or Effect[x][y] to read an effect)");
      }
      for (std::size_t i = 1; i < inputs.size(); ++i) {
        const TagUse* prev = inputs[i - 1];
        if (inputs[i]->owner == prev->owner)
          add("W-INPUT-TAG-REPEATED", inputs[i]->where,
              inputs[i]->what + " " + in_quotes(inputs[i]->name) + " repeats " + prev->what +
                  ": the voting counts one sensor twice");
        else
          add("W-INPUT-TAG-SHARED", inputs[i]->where,
              inputs[i]->what + " " + in_quotes(inputs[i]->name) + " is also read by " +
                  describe(*inputs.front()));
      }
      if (!analog.empty() && !boolean.empty())
        add("E-TAG-KIND-CONFLICT", analog.front()->where,
            analog.front()->what + " " + in_quotes(name) + " is analog (REAL) but " +
                describe(*boolean.front()) + " reads it as a Boolean");
      if (!matrix_controls.empty() && !others.empty()) {
        std::string list_text;
        for (const auto* o : others) list_text += (list_text.empty() ? "" : ", ") + describe(*o);
        add("E-CONTROL-TAG-COLLISION", at_matrix(),
            matrix_controls.front()->what + " " + in_quotes(name) + " is also used by " + list_text);
      }
    }
  }

  // ---- internal references ---------------------------------------------------

  // A reference must name an existing element (and output tag); naming a
  // comment-only element is legal but constant.
  void check_reference(const Where& where, const std::string& field, const std::string& tag,
                       const Node& source, int source_tag) {
    std::string prefix = field + " " + in_quotes(tag) + ": ";
    if (source.kind == Node::Kind::Cause) {
      const Cause* c = cause_by_id(source.id);
      if (!c) {
        add("E-REF-MISSING", where, prefix + "cause " + std::to_string(source.id) + " does not exist");
      } else if (!processed(*c)) {
        add("W-REF-COMMENT", where,
            prefix + cause_label(*c) + " is comment-only: the reference is always FALSE");
      }
      return;
    }
    const Effect* e = effect_by_id(source.id);
    if (!e) {
      add("E-REF-MISSING", where, prefix + "effect " + std::to_string(source.id) + " does not exist");
    } else if (!processed(*e)) {
      add("W-REF-COMMENT", where,
          prefix + effect_label(*e) + " is comment-only: the reference never changes");
    } else if (source_tag != 0 &&
               (source_tag < 1 || source_tag > static_cast<int>(e->tags.size()))) {
      add("E-REF-MISSING", where,
          prefix + effect_label(*e) + " has " + std::to_string(e->tags.size()) +
              " output tags, there is no tag " + std::to_string(source_tag));
    }
  }

  void references() {
    for (const auto& r : internal_references(m_)) {
      Where where = at(r.reader);
      if (r.reader.kind == Node::Kind::Cause) {
        if (const Cause* c = cause_by_id(r.reader.id)) where = at(*c);
      } else if (const Effect* e = effect_by_id(r.reader.id)) {
        where = at(*e);
      }
      check_reference(where, r.field, r.tag, r.source, r.source_tag);
      if (r.reader.kind == Node::Kind::Cause && r.field.starts_with("input tag")) {
        const Cause* c = cause_by_id(r.reader.id);
        if (c && c->input == InputKind::Analog)
          add("E-REF-ANALOG", where,
              r.field + " " + in_quotes(r.tag) +
                  " is an internal reference (Boolean) but the cause's input is analog");
      }
    }
    // Matrix-level control tags may be internal references too.
    auto matrix_ref = [&](const std::string& field, const std::string& tag) {
      auto ref = parse_internal_ref(tag);
      if (!ref) return;
      Node source{ref->kind == InternalRef::Kind::Cause ? Node::Kind::Cause : Node::Kind::Effect,
                  ref->id};
      check_reference(at_matrix(), field, tag, source,
                      ref->kind == InternalRef::Kind::EffectTag ? ref->tag : 0);
    };
    if (m_.secure_write) matrix_ref("secure_write.enable_tag", m_.secure_write->enable_tag);
    if (m_.group_deactivation) {
      matrix_ref("group_deactivation.enable_tag", m_.group_deactivation->enable_tag);
      matrix_ref("group_deactivation.set_tag", m_.group_deactivation->set_tag);
    }

    // Cycles (8.3): the run sequence follows the data flow, which a cycle cannot;
    // the graph breaks each cycle and the reader sees the previous cycle's value.
    DependencyGraph graph(m_);
    auto cycles = graph.cycles();
    for (const auto& cycle : cycles) {
      std::string text, stale;
      for (std::size_t i = 0; i < cycle.size(); ++i) {
        const Node& from = cycle[i];
        const Node& to = cycle[(i + 1) % cycle.size()];
        text += to_string(from) + " -> ";
        if (graph.reads_previous(from, to))
          stale += (stale.empty() ? "" : "; ") + to_string(to) + " reads " + to_string(from) +
                   " from the previous scan cycle";
      }
      text += to_string(cycle.front());
      Where where = at(cycle.front());
      if (cycle.front().kind == Node::Kind::Cause) {
        if (const Cause* c = cause_by_id(cycle.front().id)) where = at(*c);
      } else if (const Effect* e = effect_by_id(cycle.front().id)) {
        where = at(*e);
      }
      add("W-REF-CYCLE", where, "cycle " + text + (stale.empty() ? "" : ": " + stale));
    }
    if (cycles.size() >= kMaxReportedCycles)
      add("W-REF-CYCLE", at_matrix(),
          "at least " + std::to_string(kMaxReportedCycles) +
              " cycles through internal references; only the first " +
              std::to_string(kMaxReportedCycles) + " are listed");
  }

  // ---- missing intersection configurations (11.5) ----------------------------

  void connectivity() {
    std::set<int> cause_linked, effect_linked, cause_read;
    for (const auto& x : m_.intersections) {
      if (x.type == IntersectionType::Note) continue;
      const Cause* c = cause_by_id(x.cause);
      const Effect* e = effect_by_id(x.effect);
      if (!c || !e || !processed(*c) || !processed(*e)) continue;
      cause_linked.insert(x.cause);
      effect_linked.insert(x.effect);
    }
    for (const auto& r : internal_references(m_))
      if (r.source.kind == Node::Kind::Cause) cause_read.insert(r.source.id);
    auto matrix_read = [&](const std::string& tag) {
      if (auto ref = parse_internal_ref(tag); ref && ref->kind == InternalRef::Kind::Cause)
        cause_read.insert(ref->id);
    };
    if (m_.secure_write) matrix_read(m_.secure_write->enable_tag);
    if (m_.group_deactivation) {
      matrix_read(m_.group_deactivation->enable_tag);
      matrix_read(m_.group_deactivation->set_tag);
    }
    for (const auto& c : m_.causes)
      if (processed(c) && !cause_linked.count(c.id) && !cause_read.count(c.id))
        add("W-CAUSE-UNUSED", at(c),
            "the cause has no intersection with an effect and no internal reference reads it");
    for (const auto& e : m_.effects)
      if (processed(e) && !effect_linked.count(e.id))
        add("W-EFFECT-UNDRIVEN", at(e), "no cause is linked to the effect: it never trips");
  }

  // ---- maintenance permissions (10.7.3.4) --------------------------------------

  // The format lets every tag be simulated unless the matrix says otherwise;
  // a matrix that restricts none was most likely never asked the question.
  void simulation() {
    std::size_t tags = 0;
    for (const auto& c : m_.causes) {
      if (!processed(c)) continue;
      for (const auto& t : c.tags) {
        if (parse_internal_ref(t.name)) continue;
        if (!t.simulation_allowed) return;
        ++tags;
      }
    }
    for (const auto& e : m_.effects) {
      if (!processed(e)) continue;
      for (const auto& t : e.tags) {
        if (!t.simulation_allowed) return;
        ++tags;
      }
    }
    if (tags == 0) return;
    add("W-SIMULATION-UNRESTRICTED", at_matrix(),
        "all " + std::to_string(tags) + " cause input and output tags may be simulated (no tag has "
        "simulation_allowed false)" + (m_.secure_write ? "" : " and no secure write gates the command") +
        ": a simulated tag overrides the plant; restrict simulation to the tags that need it");
  }
};

}  // namespace

std::vector<Diagnostic> validate(const Matrix& m) { return Validator(m).run(); }

bool has_errors(const std::vector<Diagnostic>& ds) {
  return std::any_of(ds.begin(), ds.end(),
                     [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

const std::vector<RuleInfo>& validation_rules() { return kRules; }

const char* to_string(Severity s) { return s == Severity::Error ? "error" : "warning"; }

}  // namespace cemv::model
