// The objectives of one cause (docs/testgen.md, "Causes"): voting rows with
// degraded voting (docs/semantics.md C.3, C.4, appendix B of the manual),
// MC/DC of every tag, analog limits at the single-precision boundary and the
// hysteresis release (C.3, C.4), prewarning and delta alarm (C.5), the time
// function at its expiry cycle and one cycle before (C.6), acknowledgement
// (C.7), bypass and inhibit (C.8), first out (C.11).
#include <cmath>
#include <limits>
#include <set>
#include <tuple>

#include "testgen/objective_builder.hpp"

namespace cemv::testgen::detail {

namespace {

using model::Cause;

bool is_ref(const std::string& tag) { return model::parse_internal_ref(tag).has_value(); }

int configured_x(const Cause& c) {
  const int n = static_cast<int>(c.tags.size());
  switch (c.function) {
    case model::CauseFunction::And: return n;
    case model::CauseFunction::TwoOoThree: return 2;
    default: return 1;
  }
}

const char* voting_name(int x, int m) {
  if (m == 1) return "1oo1";
  if (m == 2) return x == 1 ? "1oo2" : "2oo2";
  return x == 1 ? "1oo3" : x == 2 ? "2oo3" : "3oo3";
}

// Tag i tripped under the strict threshold, as C.3 reads a good-quality value.
std::string tripped(const Cause& c, std::size_t i) {
  const auto& t = c.tags[i];
  if (c.input == model::InputKind::Analog && c.analog && !is_ref(t.name))
    return tag_atom(t.name) + (c.analog->limit_type == model::LimitType::High ? " >= " : " <= ") +
           num(c.analog->limit);
  return t.ett ? tag_atom(t.name) : "not " + tag_atom(t.name);
}

std::string all_good(const Cause& c) {
  std::vector<std::string> parts;
  for (const auto& t : c.tags)
    if (!is_ref(t.name)) parts.push_back("good(" + tag_atom(t.name) + ")");
  return parts.empty() ? "true" : join(parts, " and ");
}

// TM of C.6 in terms of the status fields (timer_running is C.9's).
std::string timed_result(const Cause& c) {
  switch (c.time.mode) {
    case model::TimeMode::OnDelay: return "(" + ck(c, "trip_requested") + " and not " + ck(c, "timer_running") + ")";
    case model::TimeMode::OffDelay: return "(" + ck(c, "trip_requested") + " or " + ck(c, "timer_running") + ")";
    case model::TimeMode::Timed: return ck(c, "timer_running");
    case model::TimeMode::None: break;
  }
  return ck(c, "trip_requested");
}

std::string tag_label(const Cause& c, std::size_t i) {
  return "tag " + std::to_string(i + 1) + " " + c.tags[i].name;
}

void voting_rows(ObjectiveBuilder& b, const Cause& c, const std::string& id, int sif) {
  const int n = static_cast<int>(c.tags.size());
  const int x = configured_x(c);
  const bool degrade = c.bad_quality == model::BadQuality::Degrade;
  int takeable = 0, bq_takeable = 0, sb_takeable = 0;
  for (const auto& t : c.tags) {
    bool bq = degrade && !is_ref(t.name);
    bq_takeable += bq;
    sb_takeable += t.soft_bypass_allowed;
    takeable += bq || t.soft_bypass_allowed;
  }
  if (c.mutually_locked_maintenance) sb_takeable = std::min(sb_takeable, 1);
  takeable = std::min(takeable, bq_takeable + sb_takeable);
  std::set<std::tuple<std::string, int, bool>> rows;
  std::vector<std::tuple<std::string, int, bool, int>> ordered;  // voting, tripped, requested, taken out
  for (int out = 0; out <= takeable; ++out) {
    const int m = n - out;
    if (m >= 1) {
      const int xr = std::max(1, x - out);
      for (int k = 0; k <= m; ++k)
        if (rows.insert({voting_name(xr, m), k, k >= xr}).second) ordered.push_back({voting_name(xr, m), k, k >= xr, out});
    } else {
      if (bq_takeable > 0 && rows.insert({"1oo1", 0, true}).second) ordered.push_back({"1oo1", 0, true, out});
      if (sb_takeable == n && rows.insert({"bypass", 0, false}).second) ordered.push_back({"bypass", 0, false, out});
    }
  }
  for (const auto& [v, k, req, out] : ordered) {
    std::string expr = ck(c, "voting") + " == " + v + " and " + ck(c, "tripped_tags") + " == " + std::to_string(k) +
                       " and " + (req ? "" : "not ") + ck(c, "trip_requested");
    std::string text = "Voting row of " + label(c) + ": resulting logic " + v +
                       (out > 0 ? " (" + std::to_string(out) + " tag(s) taken out)" : "") + ", " + std::to_string(k) +
                       " voting tag(s) tripped: trip " + (req ? "requested" : "not requested");
    b.add(id + ".vote." + v + ".k" + std::to_string(k) + (req ? ".trip" : ".no_trip"), "voting-row", text,
          {model::Node::Kind::Cause, c.id}, sif, expr, 1,
          {ck(c, "voting"), ck(c, "tripped_tags"), ck(c, "trip_requested"), ck(c, "degraded")});
  }
}

void tag_objectives(ObjectiveBuilder& b, const Cause& c, const std::string& id, int sif) {
  const std::size_t n = c.tags.size();
  const model::Node node{model::Node::Kind::Cause, c.id};
  const int x = configured_x(c);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& t = c.tags[i];
    const std::string ti = id + ".tag" + std::to_string(i + 1);
    // MC/DC: this tag alone flips the trip request (the others keep their state).
    std::vector<std::string> parts{"rose(" + ck(c, "trip_requested") + ")", "rose(" + tripped(c, i) + ")",
                                   "not " + ck(c, "degraded"), all_good(c)};
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) parts.push_back("(" + tripped(c, j) + " iff prev(" + tripped(c, j) + "))");
    b.add(ti + ".mcdc", is_ref(t.name) ? "reference" : "mcdc",
          (is_ref(t.name) ? "Internal reference " : "MC/DC: ") + tag_label(c, i) + " alone trips " + label(c),
          node, sif, join(parts, " and "), 2, {ck(c, "trip_requested"), ck(c, "tripped_tags")});
    if (is_ref(t.name)) continue;
    // Bad quality, as the cause's bad_quality option says (C.3).
    const std::string healthy = "not (" + tripped(c, i) + ")";
    std::string others;
    for (std::size_t j = 0; j < n; ++j)
      if (j != i)  // a reference always has good quality (I.3): the language has no quality for it
        others += (is_ref(c.tags[j].name) ? std::string() : " and good(" + tag_atom(c.tags[j].name) + ")") +
                  " and not (" + tripped(c, j) + ")";
    switch (c.bad_quality) {
      case model::BadQuality::Trip:
        b.add(ti + ".bad_quality", "bad-quality",
              "Bad quality of " + tag_label(c, i) + " counts as tripped (" + label(c) + ", bad quality: trip)", node,
              sif, "bad(" + tag_atom(t.name) + ") and " + healthy + others + " and not prev(" + ck(c, "trip_requested") +
                       ") and " + ck(c, "tripped_tags") + " == 1",
              1, {ck(c, "tripped_tags"), ck(c, "trip_requested")});
        break;
      case model::BadQuality::Degrade:
        b.add(ti + ".bad_quality", "bad-quality",
              "Bad quality of " + tag_label(c, i) + " takes it out of the vote (" + label(c) + ", degraded voting)",
              node, sif, "bad(" + tag_atom(t.name) + ") and " + ck(c, "degraded") + others, 1,
              {ck(c, "degraded"), ck(c, "voting"), ck(c, "trip_requested")});
        break;
      case model::BadQuality::Ignore:
        b.add(ti + ".bad_quality", "bad-quality",
              "Bad quality of " + tag_label(c, i) + " is ignored: its value decides (" + label(c) + ")", node, sif,
              "bad(" + tag_atom(t.name) + ") and " + healthy + others + " and not " + ck(c, "trip_requested") +
                  " and not " + ck(c, "degraded"),
              1, {ck(c, "tripped_tags"), ck(c, "trip_requested")});
        break;
    }
    if (c.input != model::InputKind::Analog || !c.analog) continue;
    const auto& a = *c.analog;
    const bool high = a.limit_type == model::LimitType::High;
    const float inf = std::numeric_limits<float>::infinity();
    const float safe_dir = high ? -inf : inf;
    const std::string unit = a.unit.empty() ? "" : " " + a.unit;
    const std::string tv = tag_atom(t.name);
    const std::string xs = std::to_string(x), xm1 = std::to_string(x - 1);
    const std::string base = " and not " + ck(c, "degraded") + " and " + all_good(c);
    b.add(ti + ".limit.trip", "limit",
          "Analog limit: " + tag_label(c, i) + " at exactly " + num(a.limit) + unit + " trips " + label(c), node, sif,
          "rose(" + ck(c, "trip_requested") + ") and rose(" + tripped(c, i) + ") and " + tv + " == " + num(a.limit) +
              " and " + ck(c, "tripped_tags") + " == " + xs + base,
          2, {ck(c, "trip_requested"), ck(c, "tripped_tags")});
    const float next = std::nextafter(a.limit, safe_dir);
    b.add(ti + ".limit.safe", "limit",
          "Analog limit: " + tag_label(c, i) + " at " + num(next) + unit +
              " (the next single-precision value on the safe side) does not trip " + label(c),
          node, sif,
          tv + " == " + num(next) + " and not " + ck(c, "trip_requested") + " and not prev(" + ck(c, "trip_requested") +
              ") and " + ck(c, "tripped_tags") + " == " + xm1 + base,
          1, {ck(c, "trip_requested"), ck(c, "tripped_tags")});
    if (a.hysteresis > 0.0f) {
      const float thr = high ? a.limit - a.hysteresis : a.limit + a.hysteresis;
      const float below = std::nextafter(thr, safe_dir);
      b.add(ti + ".hysteresis.hold", "hysteresis",
            "Hysteresis: " + label(c) + " stays tripped with " + tag_label(c, i) + " at exactly " + num(thr) + unit +
                " (limit " + (high ? "- " : "+ ") + "hysteresis)",
            node, sif,
            "prev(" + ck(c, "trip_requested") + ") and " + ck(c, "trip_requested") + " and " + tv + " == " + num(thr) +
                " and " + ck(c, "tripped_tags") + " == " + xs + base,
            2, {ck(c, "trip_requested"), ck(c, "hysteresis_active")});
      b.add(ti + ".hysteresis.release", "hysteresis",
            "Hysteresis: " + label(c) + " releases with " + tag_label(c, i) + " at " + num(below) + unit +
                " (just beyond limit " + (high ? "- " : "+ ") + "hysteresis)",
            node, sif,
            "fell(" + ck(c, "trip_requested") + ") and " + tv + " == " + num(below) + " and " + ck(c, "tripped_tags") +
                " == " + xm1 + base,
            2, {ck(c, "trip_requested"), ck(c, "hysteresis_active")});
    }
  }
}

void analog_alarms(ObjectiveBuilder& b, const Cause& c, const std::string& id, int sif) {
  if (c.input != model::InputKind::Analog || !c.analog) return;
  const auto& a = *c.analog;
  const model::Node node{model::Node::Kind::Cause, c.id};
  const bool high = a.limit_type == model::LimitType::High;
  if (a.prewarning && (high ? *a.prewarning < a.limit : *a.prewarning > a.limit)) {
    b.add(id + ".prewarning.set", "prewarning", "Prewarning of " + label(c) + " set at " + num(*a.prewarning), node,
          sif, "rose(" + ck(c, "prewarning") + ")", 1, {ck(c, "prewarning")});
    b.add(id + ".prewarning.clear", "prewarning", "Prewarning of " + label(c) + " cleared", node, sif,
          "fell(" + ck(c, "prewarning") + ")", 2, {ck(c, "prewarning")});
  }
  if (a.delta > 0.0f && c.tags.size() >= 2) {
    b.add(id + ".delta.set", "delta-alarm", "Delta (discrepancy) alarm of " + label(c) + " set", node, sif,
          "rose(" + ck(c, "delta_alarm") + ")", 1, {ck(c, "delta_alarm")});
    b.add(id + ".delta.clear", "delta-alarm", "Delta (discrepancy) alarm of " + label(c) + " cleared", node, sif,
          "fell(" + ck(c, "delta_alarm") + ")", 2, {ck(c, "delta_alarm")});
  }
}

void time_objectives(ObjectiveBuilder& b, const Cause& c, const std::string& id, int sif) {
  if (c.time.mode == model::TimeMode::None) return;
  const int d = b.cycles(c.time.ms);
  if (d < 1) return;
  const model::Node node{model::Node::Kind::Cause, c.id};
  const std::string tr = ck(c, "trip_requested"), run = ck(c, "timer_running");
  const std::string dur = std::to_string(c.time.ms) + " ms";
  auto held = [](const std::string& e, int n) { return n == 0 ? e : "held(" + e + ", " + std::to_string(n) + " cycles)"; };
  std::string expiry, before, what;
  switch (c.time.mode) {
    case model::TimeMode::OnDelay:
      what = "on-delay";
      expiry = "prev(" + run + ") and not " + run + " and " + tr;
      before = run + " and " + held(tr, d - 1) + " and not " + held(tr, d);
      b.add(id + ".timer.cancel", "timer", "On-delay of " + label(c) + " cancelled when the trip request goes before " + dur,
            node, sif, "fell(" + run + ") and not " + tr, 2, {run, ck(c, "active")});
      break;
    case model::TimeMode::OffDelay:
      what = "off-delay";
      expiry = "prev(" + run + ") and not " + run + " and not " + tr;
      before = run + " and " + held("not " + tr, d - 1) + " and not " + held("not " + tr, d);
      break;
    case model::TimeMode::Timed:
      what = "timed pulse";
      expiry = "prev(" + run + ") and not " + run;
      before = run + " and " + held(run, d - 1) + " and not " + held(run, d);
      break;
    case model::TimeMode::None: return;
  }
  b.add(id + ".timer.before", "timer",
        "Time function (" + what + " " + dur + ") of " + label(c) + ": one cycle before expiry", node, sif, before, d + 1,
        {run, ck(c, "active")});
  b.add(id + ".timer.expiry", "timer",
        "Time function (" + what + " " + dur + ") of " + label(c) + ": expiry cycle", node, sif, expiry, d + 2,
        {run, ck(c, "active")});
}

void suppression(ObjectiveBuilder& b, const Cause& c, const std::string& id, int sif) {
  const model::Node node{model::Node::Kind::Cause, c.id};
  const std::string tm = timed_result(c), act = ck(c, "active");
  int h = c.time.mode == model::TimeMode::OnDelay ? b.cycles(c.time.ms) + 1 : 1;
  if (c.bypass_tag)
    b.add(id + ".bypass.hard", "bypass", "Bypass tag " + *c.bypass_tag + " suppresses " + label(c), node, sif,
          tag_atom(*c.bypass_tag) + " and not " + ck(c, "soft_bypassed") + " and " + tm + " and not " + act, h,
          {ck(c, "bypassed"), act});
  if (c.soft_bypass.allowed)
    b.add(id + ".bypass.soft", "bypass", "Soft bypass of " + label(c) + " suppresses it", node, sif,
          ck(c, "soft_bypassed") + " and " + tm + " and not " + act, h, {ck(c, "soft_bypassed"), act});
  // The timed soft bypass (C.1, T.2): switched on in cycle s it is on in
  // cycles s .. s+D-1 and removed with the timeout alarm in s+D; the prealarm
  // shows from s+P. Each boundary and the cycle before it, so that a timeout
  // or prealarm moved either way shows at one of the checkpoints.
  if (c.soft_bypass.allowed && c.soft_bypass.max_s > 0) {
    const std::string sb = ck(c, "soft_bypassed"), pre = ck(c, "bypass_prealarm"), to = ck(c, "bypass_timeout");
    auto held = [&](int n) { return n <= 0 ? sb : "held(" + sb + ", " + std::to_string(n) + " cycles)"; };
    auto on_for = [&](int n) { return sb + " and " + held(n - 1) + " and not " + held(n); };  // the n-th cycle on
    const int d = b.cycles(c.soft_bypass.max_s * 1000ULL);
    const std::vector<std::string> seen{sb, pre, to, ck(c, "bypassed")};
    if (c.soft_bypass.prealarm_s > 0 && c.soft_bypass.prealarm_s < c.soft_bypass.max_s) {
      const int p = b.cycles(c.soft_bypass.prealarm_s * 1000ULL);
      b.add(id + ".bypass.prealarm.before", "bypass",
            "Soft bypass of " + label(c) + ": one cycle before its prealarm (" +
                std::to_string(c.soft_bypass.prealarm_s) + " s)",
            node, sif, on_for(p) + " and not " + pre, p + 1, seen);
      b.add(id + ".bypass.prealarm", "bypass",
            "Soft bypass of " + label(c) + ": prealarm after " + std::to_string(c.soft_bypass.prealarm_s) + " s",
            node, sif, on_for(p + 1) + " and " + pre, p + 2, seen);
    }
    b.add(id + ".bypass.timeout.before", "bypass",
          "Soft bypass of " + label(c) + ": still on one cycle before its timeout (" +
              std::to_string(c.soft_bypass.max_s) + " s)",
          node, sif, on_for(d), d + 1, seen);
    b.add(id + ".bypass.timeout", "bypass",
          "Soft bypass of " + label(c) + " removed after " + std::to_string(c.soft_bypass.max_s) +
              " s with the timeout alarm",
          node, sif, "rose(" + to + ") and prev(" + held(d - 1) + ") and not " + sb, d + 2, seen);
  }
  if (c.inhibit_tag)
    b.add(id + ".inhibit", "inhibit", "Inhibit tag " + *c.inhibit_tag + " suppresses " + label(c), node, sif,
          tag_atom(*c.inhibit_tag) + " and " + tm + " and not " + act, h, {ck(c, "inhibited"), act});
}

void acknowledgement(ObjectiveBuilder& b, const Cause& c, const std::string& id, int sif) {
  const bool can_latch = c.time.mode == model::TimeMode::None || c.time.mode == model::TimeMode::OnDelay;
  const model::Node node{model::Node::Kind::Cause, c.id};
  // Automatic acknowledgement (C.7): the cause goes inactive in the cycle its
  // trip request clears, no acknowledgement required; with a latch it would
  // stay active.
  if (c.auto_ack && can_latch)
    b.add(id + ".ack.auto", "acknowledgement",
          label(c) + " goes inactive by itself when its trip clears (automatic acknowledgement)", node, sif,
          "fell(" + ck(c, "trip_requested") + ") and fell(" + ck(c, "active") + ") and not " +
              ck(c, "ack_required"),
          c.time.mode == model::TimeMode::OnDelay ? b.cycles(c.time.ms) + 2 : 2,
          {ck(c, "active"), ck(c, "ack_required")});
  const bool latch = !c.auto_ack && can_latch;
  if (!latch) return;
  const std::string ack = "issued(ack_cause, cause = " + std::to_string(c.id) + ")";
  const std::string sw = b.matrix().secure_write ? " and " + tag_atom(b.matrix().secure_write->enable_tag) : "";
  const std::string req = ck(c, "ack_required"), tr = ck(c, "trip_requested");
  const int h = c.time.mode == model::TimeMode::OnDelay ? b.cycles(c.time.ms) + 1 : 1;
  b.add(id + ".ack.required", "acknowledgement", "Acknowledgement of " + label(c) + " required after a trip", node, sif,
        "rose(" + req + ")", h, {req, ck(c, "active")});
  b.add(id + ".ack.held", "acknowledgement",
        label(c) + " stays active after the trip condition clears until acknowledged", node, sif,
        "not " + tr + " and " + req + " and " + ck(c, "active"), h + 1, {req, ck(c, "active")});
  b.add(id + ".ack.refused", "acknowledgement",
        "Acknowledgement of " + label(c) + " refused while the trip is still requested", node, sif,
        ack + sw + " and " + tr + " and " + req, h, {req, ck(c, "active")});
  b.add(id + ".ack.accepted", "acknowledgement",
        "Acknowledgement of " + label(c) + " accepted once the trip request has cleared", node, sif,
        ack + " and prev(" + req + ") and not " + req, h + 1, {req, ck(c, "active")});
}

void first_out(ObjectiveBuilder& b, const Cause& c, const std::string& id, int sif) {
  if (c.first_out_group <= 0) return;
  const model::Node node{model::Node::Kind::Cause, c.id};
  const std::string g = std::to_string(c.first_out_group);
  b.add(id + ".first_out.set", "first-out", label(c) + " is first out of group " + g, node, sif,
        "rose(" + ck(c, "first_out") + ")", 1, {ck(c, "first_out")});
  std::vector<std::string> others;
  for (const auto& o : b.matrix().causes)
    if (o.id != c.id && o.first_out_group == c.first_out_group && o.function != model::CauseFunction::Comment)
      others.push_back(ck(o, "first_out"));
  if (!others.empty())
    b.add(id + ".first_out.second", "first-out",
          label(c) + " becomes active after another cause of group " + g + ": not first out", node, sif,
          "rose(" + ck(c, "active") + ") and not " + ck(c, "first_out") + " and (" + join(others, " or ") + ")", 2,
          {ck(c, "first_out")});
  b.add(id + ".first_out.clear", "first-out", "First out of " + label(c) + " cleared by the operator", node, sif,
        "fell(" + ck(c, "first_out") + ")", 2, {ck(c, "first_out")});
}

}  // namespace

void cause_objectives(ObjectiveBuilder& b, const model::Cause& c) {
  const std::string id = "cause." + std::to_string(c.id);
  const int sif = first_sif(c.sif);
  voting_rows(b, c, id, sif);
  tag_objectives(b, c, id, sif);
  analog_alarms(b, c, id, sif);
  time_objectives(b, c, id, sif);
  suppression(b, c, id, sif);
  acknowledgement(b, c, id, sif);
  first_out(b, c, id, sif);
}

}  // namespace cemv::testgen::detail
