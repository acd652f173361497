#include "mutate/mutants.hpp"

#include <algorithm>
#include <functional>
#include <cctype>

#include "model/validate.hpp"

namespace cemv::mutate {

namespace {

using model::Cause;
using model::Effect;
using model::Intersection;
using model::IntersectionType;
using model::Matrix;

const IntersectionType kProcessedTypes[] = {IntersectionType::N, IntersectionType::S, IntersectionType::V,
                                            IntersectionType::R};

std::string c_(int id) { return "c" + std::to_string(id); }
std::string e_(int id) { return "e" + std::to_string(id); }
std::string cause_el(int id) { return "cause[" + std::to_string(id) + "]"; }
std::string effect_el(int id) { return "effect[" + std::to_string(id) + "]"; }
std::string cell_el(int c, int e) { return "intersection " + cause_el(c) + "/" + effect_el(e); }
std::string yes_no(bool b) { return b ? "true" : "false"; }
std::string ms_text(std::uint32_t ms) { return std::to_string(ms) + " ms"; }
std::string s_text(std::uint32_t s) { return std::to_string(s) + " s"; }
std::string lower(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return s;
}

class Generator {
 public:
  explicit Generator(const Matrix& m) : m_(m) {}

  std::vector<Mutant> run() {
    intersections();
    for (const auto& c : m_.causes) cause(c);
    for (const auto& e : m_.effects) effect(e);
    return std::move(out_);
  }

 private:
  // One edit: a copy of the matrix changed by `edit`, which finds its element
  // again by id (the copy's vectors are the original's, same order).
  void add(std::string op, std::string id_suffix, std::string element, std::string description,
           const std::function<void(Matrix&)>& edit) {
    Mutant mu;
    mu.op = op;
    mu.id = op + "." + id_suffix;
    mu.element = std::move(element);
    mu.description = std::move(description);
    mu.matrix = m_;
    edit(mu.matrix);
    mu.matrix.sort_by_id();
    out_.push_back(std::move(mu));
  }
  static Cause& cause_of(Matrix& m, int id) {
    return *std::find_if(m.causes.begin(), m.causes.end(), [&](const Cause& c) { return c.id == id; });
  }
  static Effect& effect_of(Matrix& m, int id) {
    return *std::find_if(m.effects.begin(), m.effects.end(), [&](const Effect& e) { return e.id == id; });
  }
  static Intersection& cell_of(Matrix& m, int c, int e) {
    return *std::find_if(m.intersections.begin(), m.intersections.end(),
                         [&](const Intersection& i) { return i.cause == c && i.effect == e; });
  }

  // Each intersection removed, changed to every other processed type, and
  // added where the cell is empty (with each processed type); each XooN X of
  // an effect moved by one (all intersections of the assignment together:
  // one X per effect, 6.5.2).
  void intersections() {
    for (const auto& c : m_.causes) {
      if (c.function == model::CauseFunction::Comment) continue;
      for (const auto& e : m_.effects) {
        if (e.function == model::EffectFunction::Comment) continue;
        const Intersection* is = m_.find_intersection(c.id, e.id);
        const std::string cell = c_(c.id) + e_(e.id);
        if (!is) {
          for (auto t : kProcessedTypes) {
            std::string tn = model::to_string(t);
            add("intersection-added", tn + "." + cell, cell_el(c.id, e.id),
                "add a " + tn + " intersection where the cell is empty", [&](Matrix& m) {
                  m.intersections.push_back(Intersection{c.id, e.id, t, std::nullopt, ""});
                });
          }
          continue;
        }
        const IntersectionType was = is->type;
        if (model::is_processed(was))
          add("intersection-removed", cell, cell_el(c.id, e.id),
              std::string("remove the ") + model::to_string(was) + " intersection", [&](Matrix& m) {
                auto& v = m.intersections;
                v.erase(std::find_if(v.begin(), v.end(),
                                     [&](const Intersection& i) { return i.cause == c.id && i.effect == e.id; }));
              });
        for (auto t : kProcessedTypes) {
          if (t == was) continue;
          std::string tn = model::to_string(t);
          add("intersection-type", tn + "." + cell, cell_el(c.id, e.id),
              std::string("change the intersection from ") + model::to_string(was) + " to " + tn,
              [&](Matrix& m) { cell_of(m, c.id, e.id).type = t; });
        }
      }
    }
    for (const auto& e : m_.effects) {
      std::optional<int> x;
      for (const auto* is : m_.intersections_of_effect(e.id))
        if (is->xoon) x = is->xoon;
      if (!x) continue;
      for (int d : {+1, -1}) {
        add(d > 0 ? "xoon-plus" : "xoon-minus", e_(e.id), effect_el(e.id),
            "change the XooN assignment from " + std::to_string(*x) + "ooN to " + std::to_string(*x + d) + "ooN",
            [&](Matrix& m) {
              for (auto& is : m.intersections)
                if (is.effect == e.id && is.xoon) *is.xoon += d;
            });
      }
    }
  }

  void cause(const Cause& c) {
    const int id = c.id;
    const std::string el = cause_el(id);
    for (auto f : {model::CauseFunction::Normal, model::CauseFunction::And, model::CauseFunction::Or,
                   model::CauseFunction::TwoOoThree, model::CauseFunction::Comment}) {
      if (f == c.function) continue;
      add("cause-function", lower(model::to_string(f)) + "." + c_(id), el,
          std::string("change the function type from ") + model::to_string(c.function) + " to " + model::to_string(f),
          [&](Matrix& m) { cause_of(m, id).function = f; });
    }
    if (c.function == model::CauseFunction::Comment) return;  // not processed: nothing else matters
    for (std::size_t t = 0; t < c.tags.size(); ++t) {
      const std::string tel = el + ".tag[" + std::to_string(t + 1) + "]";
      add("tag-ett", c_(id) + "t" + std::to_string(t + 1), tel,
          "flip input " + c.tags[t].name + " from " + (c.tags[t].ett ? "ETT to DTT" : "DTT to ETT"),
          [&](Matrix& m) { cause_of(m, id).tags[t].ett = !cause_of(m, id).tags[t].ett; });
    }
    for (auto q : {model::BadQuality::Ignore, model::BadQuality::Trip, model::BadQuality::Degrade}) {
      if (q == c.bad_quality) continue;
      add("bad-quality", lower(model::to_string(q)) + "." + c_(id), el,
          std::string("change the bad-quality mode from ") + model::to_string(c.bad_quality) + " to " +
              model::to_string(q),
          [&](Matrix& m) { cause_of(m, id).bad_quality = q; });
    }
    time_function(c);
    add("auto-ack", c_(id), el, "flip auto_ack from " + yes_no(c.auto_ack) + " to " + yes_no(!c.auto_ack),
        [&](Matrix& m) { cause_of(m, id).auto_ack = !c.auto_ack; });
    seconds_pair("soft-bypass-max", c_(id), el, "the maximum soft-bypass time", c.soft_bypass.max_s,
                 [id](Matrix& m) -> std::uint32_t& { return cause_of(m, id).soft_bypass.max_s; });
    seconds_pair("soft-bypass-prealarm", c_(id), el, "the soft-bypass prealarm time", c.soft_bypass.prealarm_s,
                 [id](Matrix& m) -> std::uint32_t& { return cause_of(m, id).soft_bypass.prealarm_s; });
    if (c.bypass_tag)
      add("cause-bypass-tag-removed", c_(id), el, "remove the bypass tag " + *c.bypass_tag,
          [&](Matrix& m) { cause_of(m, id).bypass_tag.reset(); });
    if (c.inhibit_tag)
      add("cause-inhibit-tag-removed", c_(id), el, "remove the inhibit tag " + *c.inhibit_tag,
          [&](Matrix& m) { cause_of(m, id).inhibit_tag.reset(); });
  }

  // Each time mode changed (a mode that needs a duration where there was
  // none gets ten cycles, so that the edit is not refused as a zero delay),
  // and the duration moved by one cycle.
  void time_function(const Cause& c) {
    const int id = c.id;
    const std::string el = cause_el(id);
    for (auto t : {model::TimeMode::None, model::TimeMode::OnDelay, model::TimeMode::OffDelay,
                   model::TimeMode::Timed}) {
      if (t == c.time.mode) continue;
      std::uint32_t ms = c.time.ms;
      if (t != model::TimeMode::None && ms == 0) ms = 10 * m_.cycle_ms;
      if (t == model::TimeMode::None) ms = 0;
      add("time-mode", lower(model::to_string(t)) + "." + c_(id), el,
          std::string("change the time mode from ") + model::to_string(c.time.mode) + " to " + model::to_string(t) +
              (ms != c.time.ms ? " (" + ms_text(ms) + ")" : ""),
          [&](Matrix& m) { cause_of(m, id).time = model::TimeFunction{t, ms}; });
    }
    if (c.time.mode == model::TimeMode::None || c.time.ms == 0) return;
    add("time-ms-plus", c_(id), el,
        "lengthen the " + std::string(model::to_string(c.time.mode)) + " time by one cycle, " + ms_text(c.time.ms) +
            " to " + ms_text(c.time.ms + m_.cycle_ms),
        [&](Matrix& m) { cause_of(m, id).time.ms += m_.cycle_ms; });
    if (c.time.ms >= m_.cycle_ms)
      add("time-ms-minus", c_(id), el,
          "shorten the " + std::string(model::to_string(c.time.mode)) + " time by one cycle, " +
              ms_text(c.time.ms) + " to " + ms_text(c.time.ms - m_.cycle_ms),
          [&](Matrix& m) { cause_of(m, id).time.ms -= m_.cycle_ms; });
  }

  // A duration the format holds in whole seconds (override and soft-bypass
  // times): moved by its smallest step, one second (docs/mutation.md). An
  // untimed 0 stays as it is: 0 -> 1 is a different feature, not a shift.
  void seconds_pair(const std::string& op, const std::string& suffix, const std::string& el, const std::string& what,
                    std::uint32_t s, std::function<std::uint32_t&(Matrix&)> field) {
    if (s == 0) return;
    add(op + "-plus", suffix, el, "lengthen " + what + " by one second, " + s_text(s) + " to " + s_text(s + 1),
        [&](Matrix& m) { field(m) += 1; });
    add(op + "-minus", suffix, el, "shorten " + what + " by one second, " + s_text(s) + " to " + s_text(s - 1),
        [&](Matrix& m) { field(m) -= 1; });
  }

  void effect(const Effect& e) {
    const int id = e.id;
    const std::string el = effect_el(id);
    if (e.function == model::EffectFunction::Comment) return;
    for (std::size_t t = 0; t < e.tags.size(); ++t)
      add("output-ett", e_(id) + "t" + std::to_string(t + 1), el + ".tag[" + std::to_string(t + 1) + "]",
          "flip output " + e.tags[t].name + " from " + (e.tags[t].ett ? "ETT to DTT" : "DTT to ETT"),
          [&](Matrix& m) { effect_of(m, id).tags[t].ett = !effect_of(m, id).tags[t].ett; });
    add("output-delay-plus", e_(id), el,
        "lengthen the output delay by one cycle, " + ms_text(e.output_delay_ms) + " to " +
            ms_text(e.output_delay_ms + m_.cycle_ms),
        [&](Matrix& m) { effect_of(m, id).output_delay_ms += m_.cycle_ms; });
    if (e.output_delay_ms >= m_.cycle_ms)
      add("output-delay-minus", e_(id), el,
          "shorten the output delay by one cycle, " + ms_text(e.output_delay_ms) + " to " +
              ms_text(e.output_delay_ms - m_.cycle_ms),
          [&](Matrix& m) { effect_of(m, id).output_delay_ms -= m_.cycle_ms; });
    if (e.override_time) {
      seconds_pair("override-max", e_(id), el, "the maximum override time", e.override_time->max_s,
                   [id](Matrix& m) -> std::uint32_t& { return effect_of(m, id).override_time->max_s; });
      seconds_pair("override-prealarm", e_(id), el, "the override prealarm time", e.override_time->prealarm_s,
                   [id](Matrix& m) -> std::uint32_t& { return effect_of(m, id).override_time->prealarm_s; });
    }
    if (e.bypass_tag)
      add("effect-bypass-tag-removed", e_(id), el, "remove the bypass tag " + *e.bypass_tag,
          [&](Matrix& m) { effect_of(m, id).bypass_tag.reset(); });
    if (e.reset_tag)
      add("effect-reset-tag-removed", e_(id), el, "remove the reset tag " + *e.reset_tag,
          [&](Matrix& m) { effect_of(m, id).reset_tag.reset(); });
    if (e.process_data && e.process_data->tag) {
      const bool pt = e.process_data->pass_through;
      add("pass-through", e_(id), el, "turn pass-through " + std::string(pt ? "off" : "on"),
          [&](Matrix& m) { effect_of(m, id).process_data->pass_through = !pt; });
    }
    if (e.process_data && e.process_data->mask_tag)
      add("mask-tag-removed", e_(id), el, "remove the mask tag " + *e.process_data->mask_tag,
          [&](Matrix& m) { effect_of(m, id).process_data->mask_tag.reset(); });
  }

  const Matrix& m_;
  std::vector<Mutant> out_;
};

}  // namespace

std::vector<Mutant> all_edits(const model::Matrix& m) { return Generator(m).run(); }

MutantSet mutants(const model::Matrix& m) {
  MutantSet out;
  for (auto& mu : all_edits(m)) {
    std::vector<model::Diagnostic> ds = model::validate(mu.matrix);
    auto err = std::find_if(ds.begin(), ds.end(),
                            [](const model::Diagnostic& d) { return d.severity == model::Severity::Error; });
    if (err == ds.end()) {
      out.mutants.push_back(std::move(mu));
      continue;
    }
    out.refused.push_back(Refused{mu.id, mu.op, mu.element, mu.description,
                                  err->rule + " " + err->element + ": " + err->message});
  }
  return out;
}

const std::vector<OperatorInfo>& operators() {
  static const std::vector<OperatorInfo> ops{
      {"intersection-added", "an intersection of each processed type (N, S, V, R) where the cell is empty"},
      {"intersection-removed", "each processed intersection removed"},
      {"intersection-type", "each intersection changed to every other processed type"},
      {"xoon-plus", "the X of an effect's XooN assignment raised by one"},
      {"xoon-minus", "the X of an effect's XooN assignment lowered by one"},
      {"cause-function", "each cause's function type changed to every other type"},
      {"tag-ett", "each cause input tag flipped between ETT and DTT"},
      {"bad-quality", "each cause's bad-quality mode changed to every other mode"},
      {"time-mode", "each cause's time mode changed to every other mode"},
      {"time-ms-plus", "each cause's time function lengthened by one cycle"},
      {"time-ms-minus", "each cause's time function shortened by one cycle"},
      {"auto-ack", "each cause's auto_ack flipped"},
      {"soft-bypass-max-plus", "each maximum soft-bypass time lengthened by one second"},
      {"soft-bypass-max-minus", "each maximum soft-bypass time shortened by one second"},
      {"soft-bypass-prealarm-plus", "each soft-bypass prealarm lengthened by one second"},
      {"soft-bypass-prealarm-minus", "each soft-bypass prealarm shortened by one second"},
      {"cause-bypass-tag-removed", "each cause bypass tag removed"},
      {"cause-inhibit-tag-removed", "each cause inhibit tag removed"},
      {"output-ett", "each output tag flipped between ETT and DTT"},
      {"output-delay-plus", "each output delay lengthened by one cycle"},
      {"output-delay-minus", "each output delay shortened by one cycle"},
      {"override-max-plus", "each maximum override time lengthened by one second"},
      {"override-max-minus", "each maximum override time shortened by one second"},
      {"override-prealarm-plus", "each override prealarm lengthened by one second"},
      {"override-prealarm-minus", "each override prealarm shortened by one second"},
      {"effect-bypass-tag-removed", "each effect bypass tag removed"},
      {"effect-reset-tag-removed", "each effect reset tag removed"},
      {"pass-through", "each pass-through setting flipped"},
      {"mask-tag-removed", "each mask tag removed"},
  };
  return ops;
}

}  // namespace cemv::mutate
