// Validation of the matrix's own fields, ids and names, each cause and effect
// (6.1.3-6.1.7, 6.3, 6.4, 13).
#include "model/validate_checks.hpp"

#include <cmath>
#include <cstdint>
#include <charconv>
#include <map>
#include <string>

#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::model::validation {

namespace {

class ElementChecks : public Checks {
 public:
  using Checks::Checks;

  void run() {
    matrix_level();
    ids_and_names();
    for (const auto& c : m_.causes) cause(c);
    for (const auto& e : m_.effects) effect(e);
  }

 private:
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
};

}  // namespace

void check_elements(const Matrix& m, std::vector<Finding>& out) { ElementChecks(m, out).run(); }

}  // namespace cemv::model::validation
