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

using CF = CauseField;

int configured_x(const Cause& c) {
  const int n = static_cast<int>(c.tags.size());
  switch (c.function) {
    case model::CauseFunction::And: return n;
    case model::CauseFunction::TwoOoThree: return 2;
    default: return 1;
  }
}

model::Voting voting_of(int x, int m) {
  using V = model::Voting;
  if (m == 1) return V::OneOoOne;
  if (m == 2) return x == 1 ? V::OneOoTwo : V::TwoOoTwo;
  return x == 1 ? V::OneOoThree : x == 2 ? V::TwoOoThree : V::ThreeOoThree;
}

// Tag i tripped under the strict threshold, as C.3 reads a good-quality value.
Expr tripped(const ObjectiveBuilder& b, const Cause& c, std::size_t i) {
  const auto& t = c.tags[i];
  if (c.input == model::InputKind::Analog && c.analog && !is_ref(t.name))
    return Builder::compare(c.analog->limit_type == model::LimitType::High ? properties::CompareOp::Ge
                                                                           : properties::CompareOp::Le,
                            b.tag(t.name), Expr::real(c.analog->limit));
  return t.ett ? b.tag(t.name) : Builder::negate(b.tag(t.name));
}

All all_good(const ObjectiveBuilder& b, const Cause& c) {
  All parts;
  for (const auto& t : c.tags)
    if (!is_ref(t.name)) parts << b.good(t.name);
  return parts.empty() ? All{Expr::boolean(true)} : parts;
}

// TM of C.6 in terms of the status fields (timer_running is C.9's).
Expr timed_result(const ObjectiveBuilder& b, const Cause& c) {
  const Expr tr = b.cause(c, CF::TripRequested), run = b.cause(c, CF::TimerRunning);
  switch (c.time.mode) {
    case model::TimeMode::OnDelay: return Builder::all({tr, Builder::negate(run)});
    case model::TimeMode::OffDelay: return Builder::any({tr, run});
    case model::TimeMode::Timed: return run;
    case model::TimeMode::None: break;
  }
  return tr;
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
  using V = model::Voting;
  std::set<std::tuple<V, int, bool>> rows;
  std::vector<std::tuple<V, int, bool, int>> ordered;  // voting, tripped, requested, taken out
  for (int out = 0; out <= takeable; ++out) {
    const int m = n - out;
    if (m >= 1) {
      const int xr = std::max(1, x - out);
      for (int k = 0; k <= m; ++k)
        if (rows.insert({voting_of(xr, m), k, k >= xr}).second) ordered.push_back({voting_of(xr, m), k, k >= xr, out});
    } else {
      if (bq_takeable > 0 && rows.insert({V::OneOoOne, 0, true}).second) ordered.push_back({V::OneOoOne, 0, true, out});
      if (sb_takeable == n && rows.insert({V::Bypass, 0, false}).second) ordered.push_back({V::Bypass, 0, false, out});
    }
  }
  const Expr tr = b.cause(c, CF::TripRequested);
  for (const auto& [v, k, req, out] : ordered) {
    const std::string vs = model::to_string(v);
    Expr expr = Builder::all({Builder::equals(b.cause(c, CF::Voting), v),
                              Builder::equals(b.cause(c, CF::TrippedTags), std::int64_t{k}),
                              req ? tr : Builder::negate(tr)});
    std::string text = "Voting row of " + label(c) + ": resulting logic " + vs +
                       (out > 0 ? " (" + std::to_string(out) + " tag(s) taken out)" : "") + ", " + std::to_string(k) +
                       " voting tag(s) tripped: trip " + (req ? "requested" : "not requested");
    b.add(id + ".vote." + vs + ".k" + std::to_string(k) + (req ? ".trip" : ".no_trip"), "voting-row", text,
          {model::Node::Kind::Cause, c.id}, sif, std::move(expr), 1,
          {ck(c, CF::Voting), ck(c, CF::TrippedTags), ck(c, CF::TripRequested), ck(c, CF::Degraded)});
  }
}

void tag_objectives(ObjectiveBuilder& b, const Cause& c, const std::string& id, int sif) {
  const std::size_t n = c.tags.size();
  const model::Node node{model::Node::Kind::Cause, c.id};
  const int x = configured_x(c);
  const Expr tr = b.cause(c, CF::TripRequested), tt = b.cause(c, CF::TrippedTags), deg = b.cause(c, CF::Degraded);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& t = c.tags[i];
    const std::string ti = id + ".tag" + std::to_string(i + 1);
    // MC/DC: this tag alone flips the trip request (the others keep their state).
    All parts{Builder::rose(tr), Builder::rose(tripped(b, c, i)), Builder::negate(deg)};
    parts << all_good(b, c);
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) parts << Builder::iff(tripped(b, c, j), Builder::prev(tripped(b, c, j)));
    b.add(ti + ".mcdc", is_ref(t.name) ? "reference" : "mcdc",
          (is_ref(t.name) ? "Internal reference " : "MC/DC: ") + tag_label(c, i) + " alone trips " + label(c),
          node, sif, parts.expr(), 2, {ck(c, CF::TripRequested), ck(c, CF::TrippedTags)});
    if (is_ref(t.name)) continue;
    // Bad quality, as the cause's bad_quality option says (C.3).
    const Expr healthy = Builder::negate(tripped(b, c, i));
    All others;
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) {  // a reference always has good quality (I.3): the language has no quality for it
        if (!is_ref(c.tags[j].name)) others << b.good(c.tags[j].name);
        others << Builder::negate(tripped(b, c, j));
      }
    switch (c.bad_quality) {
      case model::BadQuality::Trip:
        b.add(ti + ".bad_quality", "bad-quality",
              "Bad quality of " + tag_label(c, i) + " counts as tripped (" + label(c) + ", bad quality: trip)", node,
              sif,
              (All{b.bad(t.name), healthy} << others << Builder::negate(Builder::prev(tr))
                                            << Builder::equals(tt, std::int64_t{1}))
                  .expr(),
              1, {ck(c, CF::TrippedTags), ck(c, CF::TripRequested)});
        break;
      case model::BadQuality::Degrade:
        b.add(ti + ".bad_quality", "bad-quality",
              "Bad quality of " + tag_label(c, i) + " takes it out of the vote (" + label(c) + ", degraded voting)",
              node, sif, (All{b.bad(t.name), deg} << others).expr(), 1,
              {ck(c, CF::Degraded), ck(c, CF::Voting), ck(c, CF::TripRequested)});
        break;
      case model::BadQuality::Ignore:
        b.add(ti + ".bad_quality", "bad-quality",
              "Bad quality of " + tag_label(c, i) + " is ignored: its value decides (" + label(c) + ")", node, sif,
              (All{b.bad(t.name), healthy} << others << Builder::negate(tr) << Builder::negate(deg)).expr(), 1,
              {ck(c, CF::TrippedTags), ck(c, CF::TripRequested)});
        break;
    }
    if (c.input != model::InputKind::Analog || !c.analog) continue;
    const auto& a = *c.analog;
    const bool high = a.limit_type == model::LimitType::High;
    const float inf = std::numeric_limits<float>::infinity();
    const float safe_dir = high ? -inf : inf;
    const std::string unit = a.unit.empty() ? "" : " " + a.unit;
    const Expr tv = b.tag(t.name);
    const Expr xs = Builder::equals(tt, std::int64_t{x}), xm1 = Builder::equals(tt, std::int64_t{x - 1});
    All base{Builder::negate(deg)};
    base << all_good(b, c);
    b.add(ti + ".limit.trip", "limit",
          "Analog limit: " + tag_label(c, i) + " at exactly " + num(a.limit) + unit + " trips " + label(c), node, sif,
          (All{Builder::rose(tr), Builder::rose(tripped(b, c, i)), Builder::equals(tv, a.limit), xs} << base).expr(),
          2, {ck(c, CF::TripRequested), ck(c, CF::TrippedTags)});
    const float next = std::nextafter(a.limit, safe_dir);
    b.add(ti + ".limit.safe", "limit",
          "Analog limit: " + tag_label(c, i) + " at " + num(next) + unit +
              " (the next single-precision value on the safe side) does not trip " + label(c),
          node, sif,
          (All{Builder::equals(tv, next), Builder::negate(tr), Builder::negate(Builder::prev(tr)), xm1} << base).expr(),
          1, {ck(c, CF::TripRequested), ck(c, CF::TrippedTags)});
    if (a.hysteresis > 0.0f) {
      const float thr = high ? a.limit - a.hysteresis : a.limit + a.hysteresis;
      const float below = std::nextafter(thr, safe_dir);
      b.add(ti + ".hysteresis.hold", "hysteresis",
            "Hysteresis: " + label(c) + " stays tripped with " + tag_label(c, i) + " at exactly " + num(thr) + unit +
                " (limit " + (high ? "- " : "+ ") + "hysteresis)",
            node, sif, (All{Builder::prev(tr), tr, Builder::equals(tv, thr), xs} << base).expr(), 2,
            {ck(c, CF::TripRequested), ck(c, CF::HysteresisActive)});
      b.add(ti + ".hysteresis.release", "hysteresis",
            "Hysteresis: " + label(c) + " releases with " + tag_label(c, i) + " at " + num(below) + unit +
                " (just beyond limit " + (high ? "- " : "+ ") + "hysteresis)",
            node, sif, (All{Builder::fell(tr), Builder::equals(tv, below), xm1} << base).expr(), 2,
            {ck(c, CF::TripRequested), ck(c, CF::HysteresisActive)});
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
          sif, Builder::rose(b.cause(c, CF::Prewarning)), 1, {ck(c, CF::Prewarning)});
    b.add(id + ".prewarning.clear", "prewarning", "Prewarning of " + label(c) + " cleared", node, sif,
          Builder::fell(b.cause(c, CF::Prewarning)), 2, {ck(c, CF::Prewarning)});
  }
  if (a.delta > 0.0f && c.tags.size() >= 2) {
    b.add(id + ".delta.set", "delta-alarm", "Delta (discrepancy) alarm of " + label(c) + " set", node, sif,
          Builder::rose(b.cause(c, CF::DeltaAlarm)), 1, {ck(c, CF::DeltaAlarm)});
    b.add(id + ".delta.clear", "delta-alarm", "Delta (discrepancy) alarm of " + label(c) + " cleared", node, sif,
          Builder::fell(b.cause(c, CF::DeltaAlarm)), 2, {ck(c, CF::DeltaAlarm)});
  }
}

void time_objectives(ObjectiveBuilder& b, const Cause& c, const std::string& id, int sif) {
  if (c.time.mode == model::TimeMode::None) return;
  const int d = b.cycles(c.time.ms);
  if (d < 1) return;
  const model::Node node{model::Node::Kind::Cause, c.id};
  const Expr tr = b.cause(c, CF::TripRequested), run = b.cause(c, CF::TimerRunning);
  const std::vector<std::string> seen{ck(c, CF::TimerRunning), ck(c, CF::Active)};
  const std::string dur = std::to_string(c.time.ms) + " ms";
  Expr expiry, before;
  std::string what;
  switch (c.time.mode) {
    case model::TimeMode::OnDelay:
      what = "on-delay";
      expiry = Builder::all({Builder::prev(run), Builder::negate(run), tr});
      before = Builder::all({run, held(tr, d - 1), Builder::negate(held(tr, d))});
      b.add(id + ".timer.cancel", "timer", "On-delay of " + label(c) + " cancelled when the trip request goes before " + dur,
            node, sif, Builder::all({Builder::fell(run), Builder::negate(tr)}), 2, seen);
      break;
    case model::TimeMode::OffDelay:
      what = "off-delay";
      expiry = Builder::all({Builder::prev(run), Builder::negate(run), Builder::negate(tr)});
      before = Builder::all({run, held(Builder::negate(tr), d - 1), Builder::negate(held(Builder::negate(tr), d))});
      break;
    case model::TimeMode::Timed:
      what = "timed pulse";
      expiry = Builder::all({Builder::prev(run), Builder::negate(run)});
      before = Builder::all({run, held(run, d - 1), Builder::negate(held(run, d))});
      break;
    case model::TimeMode::None: return;
  }
  b.add(id + ".timer.before", "timer",
        "Time function (" + what + " " + dur + ") of " + label(c) + ": one cycle before expiry", node, sif, before, d + 1,
        seen);
  b.add(id + ".timer.expiry", "timer",
        "Time function (" + what + " " + dur + ") of " + label(c) + ": expiry cycle", node, sif, expiry, d + 2, seen);
}

void suppression(ObjectiveBuilder& b, const Cause& c, const std::string& id, int sif) {
  const model::Node node{model::Node::Kind::Cause, c.id};
  const Expr tm = timed_result(b, c), act = b.cause(c, CF::Active);
  int h = c.time.mode == model::TimeMode::OnDelay ? b.cycles(c.time.ms) + 1 : 1;
  if (c.bypass_tag)
    b.add(id + ".bypass.hard", "bypass", "Bypass tag " + *c.bypass_tag + " suppresses " + label(c), node, sif,
          Builder::all({b.tag(*c.bypass_tag), Builder::negate(b.cause(c, CF::SoftBypassed)), tm, Builder::negate(act)}),
          h, {ck(c, CF::Bypassed), ck(c, CF::Active)});
  if (c.soft_bypass.allowed)
    b.add(id + ".bypass.soft", "bypass", "Soft bypass of " + label(c) + " suppresses it", node, sif,
          Builder::all({b.cause(c, CF::SoftBypassed), tm, Builder::negate(act)}), h,
          {ck(c, CF::SoftBypassed), ck(c, CF::Active)});
  // The timed soft bypass (C.1, T.2): switched on in cycle s it is on in
  // cycles s .. s+D-1 and removed with the timeout alarm in s+D; the prealarm
  // shows from s+P. Each boundary and the cycle before it, so that a timeout
  // or prealarm moved either way shows at one of the checkpoints.
  if (c.soft_bypass.allowed && c.soft_bypass.max_s > 0) {
    const Expr sb = b.cause(c, CF::SoftBypassed), pre = b.cause(c, CF::BypassPrealarm),
               to = b.cause(c, CF::BypassTimeout);
    auto on_for = [&](int n) { return All{sb, held(sb, n - 1), Builder::negate(held(sb, n))}; };  // the n-th cycle on
    const int d = b.cycles(c.soft_bypass.max_s * 1000ULL);
    const std::vector<std::string> seen{ck(c, CF::SoftBypassed), ck(c, CF::BypassPrealarm), ck(c, CF::BypassTimeout),
                                        ck(c, CF::Bypassed)};
    if (c.soft_bypass.prealarm_s > 0 && c.soft_bypass.prealarm_s < c.soft_bypass.max_s) {
      const int p = b.cycles(c.soft_bypass.prealarm_s * 1000ULL);
      b.add(id + ".bypass.prealarm.before", "bypass",
            "Soft bypass of " + label(c) + ": one cycle before its prealarm (" +
                std::to_string(c.soft_bypass.prealarm_s) + " s)",
            node, sif, (on_for(p) << Builder::negate(pre)).expr(), p + 1, seen);
      b.add(id + ".bypass.prealarm", "bypass",
            "Soft bypass of " + label(c) + ": prealarm after " + std::to_string(c.soft_bypass.prealarm_s) + " s",
            node, sif, (on_for(p + 1) << pre).expr(), p + 2, seen);
    }
    b.add(id + ".bypass.timeout.before", "bypass",
          "Soft bypass of " + label(c) + ": still on one cycle before its timeout (" +
              std::to_string(c.soft_bypass.max_s) + " s)",
          node, sif, on_for(d).expr(), d + 1, seen);
    b.add(id + ".bypass.timeout", "bypass",
          "Soft bypass of " + label(c) + " removed after " + std::to_string(c.soft_bypass.max_s) +
              " s with the timeout alarm",
          node, sif, Builder::all({Builder::rose(to), Builder::prev(held(sb, d - 1)), Builder::negate(sb)}), d + 2,
          seen);
  }
  if (c.inhibit_tag)
    b.add(id + ".inhibit", "inhibit", "Inhibit tag " + *c.inhibit_tag + " suppresses " + label(c), node, sif,
          Builder::all({b.tag(*c.inhibit_tag), tm, Builder::negate(act)}), h,
          {ck(c, CF::Inhibited), ck(c, CF::Active)});
}

void acknowledgement(ObjectiveBuilder& b, const Cause& c, const std::string& id, int sif) {
  const bool can_latch = c.time.mode == model::TimeMode::None || c.time.mode == model::TimeMode::OnDelay;
  const model::Node node{model::Node::Kind::Cause, c.id};
  const Expr act = b.cause(c, CF::Active), req = b.cause(c, CF::AckRequired), tr = b.cause(c, CF::TripRequested);
  const std::vector<std::string> seen{ck(c, CF::AckRequired), ck(c, CF::Active)};
  // Automatic acknowledgement (C.7): the cause goes inactive in the cycle its
  // trip request clears, no acknowledgement required; with a latch it would
  // stay active.
  if (c.auto_ack && can_latch)
    b.add(id + ".ack.auto", "acknowledgement",
          label(c) + " goes inactive by itself when its trip clears (automatic acknowledgement)", node, sif,
          Builder::all({Builder::fell(tr), Builder::fell(act), Builder::negate(req)}),
          c.time.mode == model::TimeMode::OnDelay ? b.cycles(c.time.ms) + 2 : 2,
          {ck(c, CF::Active), ck(c, CF::AckRequired)});
  const bool latch = !c.auto_ack && can_latch;
  if (!latch) return;
  All ack{Builder::issued(model::CommandOp::AckCause, c.id)};
  All with_sw = ack;
  if (b.matrix().secure_write) with_sw << b.tag(b.matrix().secure_write->enable_tag);
  const int h = c.time.mode == model::TimeMode::OnDelay ? b.cycles(c.time.ms) + 1 : 1;
  b.add(id + ".ack.required", "acknowledgement", "Acknowledgement of " + label(c) + " required after a trip", node, sif,
        Builder::rose(req), h, seen);
  b.add(id + ".ack.held", "acknowledgement",
        label(c) + " stays active after the trip condition clears until acknowledged", node, sif,
        Builder::all({Builder::negate(tr), req, act}), h + 1, seen);
  b.add(id + ".ack.refused", "acknowledgement",
        "Acknowledgement of " + label(c) + " refused while the trip is still requested", node, sif,
        (with_sw << tr << req).expr(), h, seen);
  b.add(id + ".ack.accepted", "acknowledgement",
        "Acknowledgement of " + label(c) + " accepted once the trip request has cleared", node, sif,
        (ack << Builder::prev(req) << Builder::negate(req)).expr(), h + 1, seen);
}

void first_out(ObjectiveBuilder& b, const Cause& c, const std::string& id, int sif) {
  if (c.first_out_group <= 0) return;
  const model::Node node{model::Node::Kind::Cause, c.id};
  const std::string g = std::to_string(c.first_out_group);
  const Expr fo = b.cause(c, CF::FirstOut);
  b.add(id + ".first_out.set", "first-out", label(c) + " is first out of group " + g, node, sif, Builder::rose(fo), 1,
        {ck(c, CF::FirstOut)});
  std::vector<Expr> others;
  for (const auto& o : b.matrix().causes)
    if (o.id != c.id && o.first_out_group == c.first_out_group && o.function != model::CauseFunction::Comment)
      others.push_back(b.cause(o, CF::FirstOut));
  if (!others.empty())
    b.add(id + ".first_out.second", "first-out",
          label(c) + " becomes active after another cause of group " + g + ": not first out", node, sif,
          Builder::all({Builder::rose(b.cause(c, CF::Active)), Builder::negate(fo), any_of(std::move(others))}), 2,
          {ck(c, CF::FirstOut)});
  b.add(id + ".first_out.clear", "first-out", "First out of " + label(c) + " cleared by the operator", node, sif,
        Builder::fell(fo), 2, {ck(c, CF::FirstOut)});
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
