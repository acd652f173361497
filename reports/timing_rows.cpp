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

// A row's label, kind and note; its values come cycle by cycle.
Row observable_row(const model::Matrix& m, const model::Observable& o) {
  Row r;
  r.label = observable_label(m, o);
  r.kind = o.type != model::FieldType::Bool ? RowKind::Bus : is_timer(m, o) ? RowKind::Timer : RowKind::Digital;
  if (r.kind == RowKind::Timer) {
    r.duration_ms = timer_duration(m, o);
    if (r.duration_ms > 0) r.note = "time " + time_text(r.duration_ms);
  }
  if (o.field == "tag") r.note = "output " + output_name(m, o);
  return r;
}

std::string bus_text(const model::Observable& o, int v) {
  return o.type == model::FieldType::Voting ? model::to_string(static_cast<model::Voting>(v)) : std::to_string(v);
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

void Row::append(double value, std::string text, bool bad) {
  const std::size_t k = cycles();
  if (!segments.empty()) {
    Segment& last = segments.back();
    if (last.value == value && last.bad == bad && last.text == text) {
      last.to = k;
      return;
    }
    changes = true;
  }
  segments.push_back({value, std::move(text), bad, k, k});
}

const Segment& Row::at(std::size_t cycle) const {
  auto it = std::upper_bound(segments.begin(), segments.end(), cycle,
                             [](std::size_t c, const Segment& s) { return c < s.from; });
  return *(it - 1);
}

bool Row::any_bad() const {
  for (const auto& s : segments)
    if (s.bad) return true;
  return false;
}

std::size_t Row::running_for(std::size_t cycle) const {
  auto it = std::upper_bound(segments.begin(), segments.end(), cycle,
                             [](std::size_t c, const Segment& s) { return c < s.from; });
  std::size_t n = 0, end = cycle;
  while (it != segments.begin()) {
    --it;
    if (it->value == 0) break;
    n += end - it->from + 1;
    if (it->from == 0) break;
    end = it->from - 1;
  }
  return n;
}

RowBuilder::RowBuilder(const model::Matrix& m, const TimingDiagram& d) : m_(m), d_(d), all_(model::observables(m)) {
  model::InputTable table(m);
  for (const auto& tag : table.tags()) {
    Row r;
    r.label = tag.name;
    r.kind = tag.kind == model::TagKind::Analog ? RowKind::Analog : RowKind::Digital;
    inputs_.push_back(std::move(r));
  }
  commands_.kind = RowKind::Commands;
  commands_.label = "operator commands";
  for (const auto& o : all_) observables_.push_back(observable_row(m, o));
}

void RowBuilder::add(const model::CycleInput& in, const std::vector<int>& snapshot) {
  for (std::size_t i = 0; i < inputs_.size(); ++i) inputs_[i].append(in.tags[i].value, {}, in.tags[i].bad_quality);
  std::string s;
  for (const auto& c : in.commands) s += (s.empty() ? "" : "; ") + command_label(c);
  commands_.append(double(in.commands.size()), std::move(s), false);
  if (!snapshot.empty())
    for (std::size_t i = 0; i < observables_.size(); ++i) {
      Row& r = observables_[i];
      const int v = snapshot[i];
      r.append(v, r.kind == RowKind::Bus ? bus_text(all_[i], v) : std::string(), false);
    }
  ++cycles_;
}

std::vector<Row> RowBuilder::rows() const {
  std::vector<Row> rows;
  model::InputTable table(m_);
  for (std::size_t i = 0; i < inputs_.size(); ++i) {
    const auto& tag = table.tags()[i];
    const bool shown = std::find(d_.inputs_shown.begin(), d_.inputs_shown.end(), tag.name) != d_.inputs_shown.end();
    if (!inputs_[i].changes && !shown) continue;
    rows.push_back(inputs_[i]);
    if (rows.back().kind == RowKind::Analog) add_levels(m_, tag, rows.back());
  }
  bool commands = false;
  for (const auto& s : commands_.segments) commands |= !s.text.empty();
  if (commands) rows.push_back(commands_);

  std::vector<bool> taken(all_.size(), false);
  const bool observed = !observables_.empty() && observables_.front().cycles() > 0;
  for (const auto& key : d_.shown)
    for (std::size_t i = 0; i < all_.size(); ++i)
      if (all_[i].key == key && !taken[i] && observed) {
        taken[i] = true;
        rows.push_back(observables_[i]);
      }
  if (d_.all_changing)
    for (std::size_t i = 0; i < all_.size(); ++i)
      if (!taken[i] && observed && observables_[i].changes) rows.push_back(observables_[i]);
  return rows;
}

std::vector<Row> rows_of(const model::Matrix& m, const checker::ConcreteTrace& t, const TimingDiagram& d) {
  RowBuilder b(m, d);
  static const std::vector<int> none;
  for (std::size_t k = 0; k < t.inputs.size(); ++k) b.add(t.inputs[k], t.observables.empty() ? none : t.observables[k]);
  return b.rows();
}

std::vector<Column> columns_of(const std::vector<Row>& rows, std::size_t cycles,
                               const std::vector<TimingMark>& marks) {
  std::vector<bool> event(cycles, false);
  if (cycles) event[0] = event[cycles - 1] = true;
  for (const auto& mk : marks)
    if (mk.cycle < cycles) event[mk.cycle] = true;
  for (const auto& r : rows)
    for (const auto& seg : r.segments) {
      if (r.kind != RowKind::Commands) {
        if (seg.from > 0) event[seg.from] = true;
      } else if (!seg.text.empty()) {
        for (std::size_t k = std::max<std::size_t>(seg.from, 1); k <= seg.to; ++k) event[k] = true;
      }
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
