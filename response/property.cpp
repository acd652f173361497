#include "response/property.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include "model/text.hpp"
#include "model/vocabulary.hpp"
#include "response/plant.hpp"

namespace cemv::response {

namespace {

using model::Cause;

std::string quoted(const std::string& tag) {
  std::string s = "\"";
  for (char c : tag) {
    if (c == '"' || c == '\\') s += '\\';
    s += c;
  }
  return s + "\"";
}

// A float constant as the property language reads it (no "e+", always a
// decimal point or exponent so that it is not taken for an integer).
std::string number(float v) {
  std::string s = model::float_text(v);
  if (auto e = s.find("e+"); e != std::string::npos) s.erase(e + 1, 1);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

// Whether an input in bad quality counts toward the demand (the stated form
// of cemv defeats, docs/defeats.md): the process behind a failed
// transmitter is unobserved, and in the worst case beyond the limit.
struct Form {
  bool bad_counts = false;
};

// One input beyond its limit with good quality (C.3, with the strict limit:
// a hysteresis band only makes a trip last longer); in the stated form, or
// in bad quality.
std::string beyond(const Cause& c, const model::CauseTag& t, Form f) {
  const std::string name = quoted(t.name);
  std::string value;
  if (c.input == model::InputKind::Analog && c.analog)
    value = name + (c.analog->limit_type == model::LimitType::High ? " >= " : " <= ") + number(c.analog->limit);
  else
    value = t.ett ? name : "not " + name;
  if (f.bad_counts) return "(bad(" + name + ") or (good(" + name + ") and " + value + "))";
  return "(good(" + name + ") and " + value + ")";
}

std::string at_least(const std::vector<std::string>& terms, int n) {
  if (n <= 0) return "true";
  std::string s = "count(";
  for (std::size_t i = 0; i < terms.size(); ++i) s += (i ? ", " : "") + terms[i];
  return s + ") >= " + std::to_string(n);
}

std::string normal_trigger(const Cause& c, Form f) {
  std::vector<std::string> terms;
  for (const auto* t : external_tags(c)) terms.push_back(beyond(c, *t, f));
  return at_least(terms, votes_needed(c));
}

// One input in bad quality, and as many of the others beyond their limits as
// the voting then needs (C.3, C.4): "trip" counts the bad input as tripped,
// "degrade" votes X' = max(1, X - 1) of the rest, "ignore" takes the bad
// input's value as not tripping, so X of the rest (at most all of them).
std::string degraded_trigger(const Cause& c) {
  const auto tags = external_tags(c);
  const int x = votes_needed(c);
  const int others = static_cast<int>(tags.size()) - 1;
  int need = 0;
  switch (c.bad_quality) {
    case model::BadQuality::Trip: need = std::max(0, x - 1); break;
    case model::BadQuality::Degrade: need = std::max(1, x - 1); break;
    case model::BadQuality::Ignore: need = std::min(x, others); break;
  }
  need = std::min(need, others);
  std::string s;
  for (std::size_t i = 0; i < tags.size(); ++i) {
    std::vector<std::string> rest;
    for (std::size_t j = 0; j < tags.size(); ++j)
      if (j != i) rest.push_back(beyond(c, *tags[j], Form{}));
    s += (i ? " or " : "") + std::string("(bad(") + quoted(tags[i]->name) + ")" +
         (need > 0 ? " and " + at_least(rest, need) : "") + ")";
  }
  return "(" + s + ")";
}

std::string cause_ref(int id) { return "cause[" + std::to_string(id) + "]"; }
std::string effect_ref(int id) { return "effect[" + std::to_string(id) + "]"; }

// "`condition` has held, since a fresh rise (cause `id` had not requested
// its trip in the cycle before), for the last `cycles` cycles".
std::string held_since_fresh_rise(const std::string& condition, int id, long long cycles) {
  return "held(since(" + condition + ", rose(" + condition + ") and not prev(" + cause_ref(id) +
         ".trip_requested)), " + std::to_string(cycles) + " cycles)";
}

// Cause `c`'s normal or degraded condition held since a fresh rise for
// `cycles` cycles: the one text of that term for an XooN bound and for its
// member lemmas, so that the bound's monitor and the lemmas it assumes read
// one `held` counter (member_lemmas).
std::string member_held(const Cause& c, bool degraded, long long cycles, Form f = {}) {
  return held_since_fresh_rise(degraded ? degraded_trigger(c) : "(" + normal_trigger(c, f) + ")", c.id, cycles);
}

// Its first cycle: the demand of the set that holds it has lasted exactly
// `cycles` cycles after its rise.
std::string first_cycle(const std::string& held) { return "(" + held + " and not prev(" + held + "))"; }

std::string any_of(const std::vector<std::string>& terms) {
  std::string s;
  for (const auto& t : terms) s += (s.empty() ? "" : " or ") + t;
  return "(" + s + ")";
}

// The violation of an XooN path's bound (docs/response-time.md, "XooN"): a
// fixed set of X trigger causes, each of which rose freshly and has held
// since, the set complete for `cycles` cycles after its last member rose, and
// no response in those cycles. A set whose members take turns is no demand:
// each member's own timers restart with it, so a rotating set would hold any
// XooN with delays off for ever without X conditions ever holding together.
std::string xoon_violation(const model::Matrix& m, const Path& p, Mode mode, long long cycles,
                           const std::string& response, Form f) {
  std::vector<std::string> held;
  for (int id : p.causes) held.push_back(member_held(*m.find_cause(id), false, cycles, f));
  std::string set;
  if (mode == Mode::Normal) {
    std::vector<std::string> first;
    for (const auto& h : held) first.push_back(first_cycle(h));
    set = at_least(held, p.needed) + " and " + any_of(first);
  } else {
    // The degraded cause v is one of the set, with X - 1 of the rest.
    std::vector<std::string> terms;
    for (int v : p.voted) {
      const std::string degraded = member_held(*m.find_cause(v), true, cycles);
      std::vector<std::string> rest, first{first_cycle(degraded)};
      for (std::size_t i = 0; i < p.causes.size(); ++i)
        if (p.causes[i] != v) {
          rest.push_back(held[i]);
          if (p.needed > 1) first.push_back(first_cycle(held[i]));
        }
      terms.push_back("(" + degraded + " and " + at_least(rest, p.needed - 1) + " and " + any_of(first) + ")");
    }
    set = any_of(terms);
  }
  return "(" + set + ") and not within(" + response + ", " + std::to_string(cycles) + " cycles)";
}

const char* kHeader =
    "# Generated by cemv response (docs/response-time.md).\n"
    "# No maintenance operation: simulation and soft bypasses are never commanded.\n"
    "assume not issued(simulate_tag)\n"
    "assume not issued(soft_bypass_cause)\n"
    "assume not issued(soft_bypass_tag)\n"
    "assume not issued(soft_bypass_effect)\n";

std::string cause_assumption(int id) {
  return "  assume not " + cause_ref(id) + ".bypassed and not " + cause_ref(id) + ".inhibited\n";
}

}  // namespace

namespace {

// The bound's property; `stated`: the maintenance assumptions left to the
// caller's `assumed` terms, and a bad input counted toward the demand.
std::string bound_property_text(const model::Matrix& m, const Path& p, Mode mode, long long cycles,
                                const std::string& name, const std::vector<std::string>& assumed, bool stated) {
  const Form form{stated};
  // The response: every output tag of the effect at its safe value (E.9).
  const model::Effect& e = *m.find_effect(p.effect);
  std::string response;
  for (std::size_t k = 0; k < e.tags.size(); ++k) {
    std::string tag = effect_ref(e.id) + ".tag[" + std::to_string(k + 1) + "]";
    response += (k ? " and " : "") + (e.tags[k].ett ? tag : "not " + tag);
  }
  response = "(" + response + ")";
  // The trigger of a single cause: its condition (normal or degraded).
  const int first = p.causes.front();
  const std::string trigger =
      "(" + (mode == Mode::Normal ? normal_trigger(*m.find_cause(first), form) : degraded_trigger(*m.find_cause(first))) +
      ")";

  std::string s = stated ? "# Generated by cemv defeats (docs/defeats.md).\n" : kHeader;
  s += "property " + name + " {\n";
  for (const auto& n : stated ? std::vector<model::Node>{} : p.elements) {
    if (n.kind == model::Node::Kind::Cause)
      s += cause_assumption(n.id);
    else
      s += "  assume not " + effect_ref(n.id) + ".bypassed and not " + effect_ref(n.id) + ".override_active\n";
    // A mask switched by an operator is maintenance (the manual's messages
    // class "Mask active" as preventive maintenance); a mask the logic
    // drives (an internal reference) is not, and may hold the outputs off.
    if (n.kind == model::Node::Kind::Effect) {
      const model::Effect& x = *m.find_effect(n.id);
      if (x.process_data && x.process_data->tag && x.process_data->mask_tag &&
          !model::parse_internal_ref(*x.process_data->mask_tag))
        s += "  assume not " + quoted(*x.process_data->mask_tag) + "\n";
    }
  }
  // An override of an effect whose state holds a path cause off is an
  // operation on the path too: it lifts a hold of the logic for at most its
  // maximum time, and a figure that counts it measures that time, not the
  // logic (docs/response-time.md, "Assumptions").
  const Holders holders = holders_of(m, p);
  const std::set<int> on_path = effects_on(p);  // assumed not overridden above
  std::set<int> held_by(holders.effects);
  held_by.insert(holders.inactive_effects.begin(), holders.inactive_effects.end());
  for (int id : stated ? std::set<int>{} : held_by)
    if (!on_path.count(id) && m.find_effect(id)->override_time)
      s += "  assume not " + effect_ref(id) + ".override_active\n";
  for (const auto& t : assumed) s += "  assume not " + t + "\n";
  if (p.causes.size() > 1) {
    s += "  never " + xoon_violation(m, p, mode, cycles, response, form) + "\n";
  } else {
    // A fresh demand: the cause had not requested its trip in the cycle before.
    s += "  whenever rose" + trigger + " and not prev(" + cause_ref(first) + ".trip_requested)\n";
    s += "  then " + response + " or fell" + trigger + "\n";
    s += "  within " + std::to_string(cycles) + " cycles\n";
  }
  s += "}\n";
  return s;
}

}  // namespace

std::string response_property_text(const model::Matrix& m, const Path& p, Mode mode, long long cycles,
                                   const std::string& name, const std::vector<std::string>& assumed) {
  return bound_property_text(m, p, mode, cycles, name, assumed, false);
}

std::string requirement_property_text(const model::Matrix& m, const Path& p, long long cycles,
                                      const std::string& name, const std::vector<std::string>& excluded) {
  return bound_property_text(m, p, Mode::Normal, cycles, name, excluded, true);
}

std::optional<MemberLemmas> member_lemmas(const model::Matrix& m, const Path& p, Mode mode, long long cycles,
                                          const std::string& name) {
  if (p.causes.size() < 2) return std::nullopt;
  MemberLemmas out;
  out.property_text = kHeader;
  for (int id : p.causes) {
    const Cause& c = *m.find_cause(id);
    // A timed cause is active for its pulse only, however long its
    // condition holds: no lemma (the bound's proof goes without it).
    if (c.time.mode == model::TimeMode::Timed) continue;
    const long long delay = c.time.mode == model::TimeMode::OnDelay ? cycles_of(c.time.ms, m.cycle_ms) : 0;
    if (delay > cycles) continue;
    // Each condition as xoon_violation writes it (member_held); one property
    // each, since a lemma may fail for one condition only (an `and` whose
    // bad input is ignored never trips in degraded mode).
    std::vector<std::pair<std::string, std::string>> conditions{
        {".c" + std::to_string(id), member_held(c, false, cycles)}};
    if (mode == Mode::Degraded && std::count(p.voted.begin(), p.voted.end(), id))
      conditions.push_back({".c" + std::to_string(id) + ".degraded", member_held(c, true, cycles)});
    for (const auto& [suffix, held] : conditions) {
      const std::string term = "(" + held + " and not held(" + cause_ref(id) + ".active, " +
                               std::to_string(cycles - delay) + " cycles))";
      out.names.push_back(name + suffix);
      out.terms.push_back(term);
      out.delays.push_back(delay);
      out.property_text += "property " + out.names.back() + " {\n" + cause_assumption(id) + "  never " + term + "\n}\n";
    }
  }
  if (out.names.empty()) return std::nullopt;
  return out;
}

}  // namespace cemv::response
