#include "reports/timing_rows.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::reports::timing {

namespace {

// A command as a short label: "ack cause 1", "simulate LT_101 = 90".
std::string command_label(const model::Command& c) {
  std::string s = model::to_string(c.op);
  if (c.cause) s += " C" + std::to_string(c.cause);
  if (c.effect) s += " E" + std::to_string(c.effect);
  if (c.group) s += " group " + std::to_string(c.group);
  if (c.tag) s += " tag " + std::to_string(c.tag);
  if (!c.tag_name.empty()) s += " " + c.tag_name;
  if (c.op == model::CommandOp::SimulateTag) s += " = " + model::float_text(c.value);
  if (c.op == model::CommandOp::SoftBypassCause || c.op == model::CommandOp::SoftBypassTag ||
      c.op == model::CommandOp::SoftBypassEffect)
    s += c.on ? " on" : " off";
  return s;
}

std::string number_text(double v) { return model::float_text(static_cast<float>(v)); }

// The reference lines of an analog tag: limit, prewarning and the level at
// which the hysteresis releases the trip (6.3.5), for every cause reading it.
void add_levels(const model::Matrix& m, const model::InputTag& tag, Row& row) {
  std::string key = model::tag_key(tag.name);
  for (const auto& c : m.causes) {
    if (c.input != model::InputKind::Analog || !c.analog) continue;
    bool reads = false;
    for (const auto& t : c.tags) reads |= model::tag_key(t.name) == key;
    if (!reads) continue;
    const auto& a = *c.analog;
    bool high = a.limit_type == model::LimitType::High;
    std::string who = "C" + std::to_string(c.id) + " ";
    row.levels.push_back({a.limit, who + (high ? "high" : "low") + " limit " + number_text(a.limit), "limit"});
    if (a.prewarning)
      row.levels.push_back({*a.prewarning, who + "prewarning " + number_text(*a.prewarning), "prewarning"});
    if (a.hysteresis > 0) {
      double release = high ? double(a.limit) - a.hysteresis : double(a.limit) + a.hysteresis;
      row.levels.push_back({release, who + "release " + number_text(release), "hysteresis"});
    }
    if (!a.unit.empty() && row.note.empty()) row.note = a.unit;
  }
}

// The configured time of a timer observable, in ms (0 when it has none).
double timer_duration(const model::Matrix& m, const model::Observable& o) {
  if (o.kind == model::Node::Kind::Cause) {
    const auto* c = m.find_cause(o.id);
    if (!c) return 0;
    if (o.field == "timer_running") return c->time.ms;
    if (o.field == "soft_bypassed") return c->soft_bypass.max_s * 1000.0;
    return 0;
  }
  const auto* e = m.find_effect(o.id);
  if (!e) return 0;
  if (o.field == "output_delay_running") return e->output_delay_ms;
  if (o.field == "override_active" && e->override_time) return e->override_time->max_s * 1000.0;
  return 0;
}

bool is_timer(const model::Matrix& m, const model::Observable& o) {
  if (o.field == "timer_running" || o.field == "output_delay_running") return true;
  return (o.field == "soft_bypassed" || o.field == "override_active") && timer_duration(m, o) > 0;
}

std::string output_name(const model::Matrix& m, const model::Observable& o) {
  const auto* e = m.find_effect(o.id);
  if (!e || o.tag < 1 || o.tag > static_cast<int>(e->tags.size())) return "";
  return e->tags[static_cast<std::size_t>(o.tag - 1)].name;
}

// A row as a reader names it: "cause 1 LT100_HH active", "effect 2 TRIP_PUMP
// tag[1]" (the key alone when the element has no name).
std::string observable_label(const model::Matrix& m, const model::Observable& o) {
  const bool cause = o.kind == model::Node::Kind::Cause;
  std::string name;
  if (cause) {
    if (const auto* c = m.find_cause(o.id)) name = c->name;
  } else if (const auto* e = m.find_effect(o.id)) {
    name = e->name;
  }
  std::string field = o.field == "tag" ? "tag[" + std::to_string(o.tag) + "]" : o.field;
  return std::string(cause ? "cause " : "effect ") + std::to_string(o.id) + (name.empty() ? "" : " " + name) + " " +
         field;
}

Row observable_row(const model::Matrix& m, const checker::ConcreteTrace& t, const model::Observable& o,
                   std::size_t index) {
  Row r;
  r.label = observable_label(m, o);
  r.kind = o.type != model::FieldType::Bool ? RowKind::Bus : is_timer(m, o) ? RowKind::Timer : RowKind::Digital;
  if (r.kind == RowKind::Timer) {
    r.duration_ms = timer_duration(m, o);
    if (r.duration_ms > 0) r.note = "time " + time_text(r.duration_ms);
  }
  if (o.field == "tag") r.note = "output " + output_name(m, o);
  for (const auto& snap : t.observables) {
    int v = snap[index];
    r.value.push_back(v);
    if (r.kind == RowKind::Bus)
      r.text.push_back(o.type == model::FieldType::Voting ? model::to_string(static_cast<model::Voting>(v))
                                                          : std::to_string(v));
  }
  return r;
}

}  // namespace

std::string time_text(double ms) {
  char buf[48];
  if (ms < 1000) {
    std::snprintf(buf, sizeof buf, "%.0f ms", ms);
  } else if (ms < 600000) {
    std::snprintf(buf, sizeof buf, "%.3f", ms / 1000);
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s + " s";
  } else {
    std::snprintf(buf, sizeof buf, "%.0f min %.0f s", std::floor(ms / 60000), std::fmod(ms / 1000, 60.0));
  }
  return buf;
}

std::vector<Row> rows_of(const model::Matrix& m, const checker::ConcreteTrace& t, const TimingDiagram& d) {
  std::vector<Row> rows;
  const std::size_t n = t.inputs.size();
  model::InputTable table(m);
  for (std::size_t i = 0; i < table.size(); ++i) {
    const auto& tag = table.tags()[i];
    Row r;
    r.label = tag.name;
    r.kind = tag.kind == model::TagKind::Analog ? RowKind::Analog : RowKind::Digital;
    for (std::size_t k = 0; k < n; ++k) {
      r.value.push_back(t.inputs[k].tags[i].value);
      r.bad.push_back(t.inputs[k].tags[i].bad_quality);
      r.changes |= r.value[k] != r.value[0] || r.bad[k] != r.bad[0];
    }
    const bool shown = std::find(d.inputs_shown.begin(), d.inputs_shown.end(), tag.name) != d.inputs_shown.end();
    if (!r.changes && !shown) continue;
    if (r.kind == RowKind::Analog) add_levels(m, tag, r);
    rows.push_back(std::move(r));
  }
  Row commands;
  commands.kind = RowKind::Commands;
  commands.label = "operator commands";
  for (std::size_t k = 0; k < n; ++k) {
    std::string s;
    for (const auto& c : t.inputs[k].commands) s += (s.empty() ? "" : "; ") + command_label(c);
    commands.changes |= !s.empty();
    commands.text.push_back(s);
    commands.value.push_back(t.inputs[k].commands.size());
  }
  if (commands.changes) rows.push_back(std::move(commands));

  const auto all = model::observables(m);
  std::vector<bool> taken(all.size(), false);
  for (const auto& key : d.shown)
    for (std::size_t i = 0; i < all.size(); ++i)
      if (all[i].key == key && !taken[i] && !t.observables.empty()) {
        taken[i] = true;
        rows.push_back(observable_row(m, t, all[i], i));
      }
  if (d.all_changing)
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (taken[i] || t.observables.empty()) continue;
      Row r = observable_row(m, t, all[i], i);
      for (double v : r.value) r.changes |= v != r.value[0];
      if (r.changes) rows.push_back(std::move(r));
    }
  return rows;
}

std::vector<Column> columns_of(const std::vector<Row>& rows, std::size_t cycles,
                               const std::vector<TimingMark>& marks) {
  std::vector<bool> event(cycles, false);
  if (cycles) event[0] = event[cycles - 1] = true;
  for (const auto& mk : marks)
    if (mk.cycle < cycles) event[mk.cycle] = true;
  for (const auto& r : rows)
    for (std::size_t k = 1; k < cycles; ++k) {
      bool differs = r.value[k] != r.value[k - 1] || (!r.bad.empty() && r.bad[k] != r.bad[k - 1]);
      if (r.kind == RowKind::Commands) differs = !r.text[k].empty();
      event[k] = event[k] || differs;
    }
  // Context: a cycle before each event and two after it stay visible.
  std::vector<bool> keep(cycles, false);
  for (std::size_t k = 0; k < cycles; ++k)
    if (event[k])
      for (std::size_t j = k == 0 ? 0 : k - 1; j <= k + 2 && j < cycles; ++j) keep[j] = true;
  constexpr std::size_t kMinFold = 4;  // a shorter stretch is drawn cycle by cycle
  std::vector<Column> cols;
  for (std::size_t k = 0; k < cycles;) {
    if (keep[k]) {
      cols.push_back({k, k, false});
      ++k;
      continue;
    }
    std::size_t end = k;
    while (end + 1 < cycles && !keep[end + 1]) ++end;
    if (end - k + 1 >= kMinFold) {
      cols.push_back({k, end, true});
    } else {
      for (std::size_t j = k; j <= end; ++j) cols.push_back({j, j, false});
    }
    k = end + 1;
  }
  return cols;
}

}  // namespace cemv::reports::timing
