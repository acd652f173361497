#include "checker/replay.hpp"

#include <climits>
#include <sstream>
#include <unordered_map>

#include "encoder/evaluate.hpp"
#include "formats/scenario.hpp"
#include "runtime/runtime.hpp"

namespace cemv::checker {

namespace {

constexpr int kNotEncoded = INT_MIN;

std::string name_of(const z3::expr& var) { return var.decl().name().str(); }

float number_of(const Value& v) { return v.is_float ? v.f : static_cast<float>(v.i); }

}  // namespace

std::vector<model::CycleInput> cycle_inputs(const Trace& trace, const encoder::Encoding& enc,
                                            const model::Matrix& m) {
  const model::CycleInput defaults = model::default_cycle_input(m);
  const model::CommandOrder order(m);
  std::vector<model::CycleInput> out;
  out.reserve(trace.length());
  for (std::size_t k = 0; k < trace.length(); ++k) {
    model::CycleInput in;
    in.tags = defaults.tags;
    for (std::size_t i = 0; i < enc.tag_value.size() && i < in.tags.size(); ++i) {
      if (enc.tag_value[i]) in.tags[i].value = number_of(trace.input(k, name_of(*enc.tag_value[i])));
      if (enc.tag_bad[i]) in.tags[i].bad_quality = trace.input(k, name_of(*enc.tag_bad[i])).i != 0;
    }
    for (const auto& ci : enc.commands) {
      if (trace.input(k, name_of(ci.var)).i == 0) continue;
      model::Command c = ci.command();
      if (ci.value) c.value = number_of(trace.input(k, name_of(*ci.value)));
      in.commands.push_back(c);
    }
    // The runtime processes commands in the order given (M.1); the encoding
    // processes them as a set in the matrix's fixed order, and so must the
    // runtime to reproduce the run.
    in.commands = order.canonical(in.commands);
    out.push_back(std::move(in));
  }
  return out;
}

std::optional<Trace> encoded_trace(const std::vector<model::CycleInput>& inputs, const encoder::Encoding& enc,
                                   const encoder::TransitionSystem& ts, std::size_t* dropped) {
  // What each input variable of the system reads from a cycle's inputs.
  enum class Source { Value, Bad, Command, CommandValue };
  struct Column {
    Source source;
    std::size_t tag = 0;  // Value, Bad: the tag; Command, CommandValue: the command input
    bool is_float = false;
  };
  std::unordered_map<std::string, Column> meaning;
  for (std::size_t i = 0; i < enc.tag_value.size(); ++i) {
    if (enc.tag_value[i]) meaning[name_of(*enc.tag_value[i])] = {Source::Value, i, enc.tag_value[i]->is_fpa()};
    if (enc.tag_bad[i]) meaning[name_of(*enc.tag_bad[i])] = {Source::Bad, i, false};
  }
  for (std::size_t k = 0; k < enc.commands.size(); ++k) {
    const auto& c = enc.commands[k];
    meaning[name_of(c.var)] = {Source::Command, k, false};
    if (c.value) meaning[name_of(*c.value)] = {Source::CommandValue, k, c.value->is_fpa()};
  }
  // The command input that stands for an issued command, by its targets.
  auto same = [](const encoder::CommandInput& in, const model::Command& c) {
    return in.op == c.op && in.cause == c.cause && in.effect == c.effect && in.tag == c.tag && in.group == c.group &&
           in.on == c.on && in.tag_name == c.tag_name;
  };
  Trace t;
  std::vector<Column> columns;
  for (const auto& in : ts.inputvars()) {
    auto it = meaning.find(in.name);
    if (it == meaning.end()) return std::nullopt;
    t.input_names.push_back(in.name);
    columns.push_back(it->second);
  }
  for (const auto& cycle : inputs) {
    // Every issued command must be one of the encoding's command inputs.
    std::vector<const model::Command*> issued(enc.commands.size(), nullptr);
    for (const auto& command : cycle.commands) {
      std::size_t k = 0;
      while (k < enc.commands.size() && !same(enc.commands[k], command)) ++k;
      if (k == enc.commands.size()) {
        if (!dropped) return std::nullopt;
        ++*dropped;
        continue;
      }
      issued[k] = &command;
    }
    Trace::Cycle c;
    for (const auto& col : columns) {
      Value v;
      if (col.source == Source::Value) {
        const float x = cycle.tags.at(col.tag).value;
        if (col.is_float) {
          v.is_float = true;
          v.f = x;
        } else {
          v.i = x != 0.0f ? 1 : 0;
        }
      } else if (col.source == Source::Bad) {
        v.i = cycle.tags.at(col.tag).bad_quality ? 1 : 0;
      } else if (col.source == Source::Command) {
        v.i = issued[col.tag] ? 1 : 0;
      } else {
        v.is_float = col.is_float;  // not issued: value 0
        if (const model::Command* command = issued[col.tag]) {
          if (col.is_float) v.f = command->value;
          else v.i = command->value != 0.0f ? 1 : 0;
        }
      }
      c.inputs.push_back(v);
    }
    t.cycles.push_back(std::move(c));
  }
  return t;
}

ConcreteTrace run_on_runtime(const model::Matrix& m, const std::vector<model::CycleInput>& inputs) {
  runtime::Runtime rt(m);
  ConcreteTrace t;
  t.inputs = inputs;
  std::vector<int> snap;
  for (const auto& in : inputs) {
    rt.step(in);
    rt.snapshot(snap);
    t.observables.push_back(snap);
  }
  return t;
}

ConcreteTrace run_on_encoding(const encoder::Encoding& enc, const model::Matrix& m,
                              const std::vector<model::CycleInput>& inputs) {
  const auto all = model::observables(m);
  std::unordered_map<std::string, std::size_t> position;
  for (std::size_t i = 0; i < all.size(); ++i) position[all[i].key] = i;
  encoder::Evaluator ev(enc);
  ConcreteTrace t;
  t.inputs = inputs;
  std::vector<int> cone;
  for (const auto& in : inputs) {
    ev.step(in);
    ev.snapshot(cone);
    std::vector<int> row(all.size(), kNotEncoded);
    for (std::size_t i = 0; i < enc.observables.size(); ++i) row[position.at(enc.observables[i].key)] = cone[i];
    t.observables.push_back(std::move(row));
  }
  return t;
}

std::string describe_disagreement(const model::Matrix& m, const ConcreteTrace& runtime,
                                  const ConcreteTrace& encoding) {
  const auto all = model::observables(m);
  std::ostringstream out;
  std::size_t cycles = std::min(runtime.observables.size(), encoding.observables.size());
  int shown = 0;
  for (std::size_t k = 0; k < cycles && shown < 20; ++k)
    for (std::size_t i = 0; i < all.size() && shown < 20; ++i) {
      int e = encoding.observables[k][i];
      if (e == kNotEncoded || e == runtime.observables[k][i]) continue;
      out << "cycle " << k + 1 << ": " << all[i].key << " runtime " << runtime.observables[k][i]
          << ", encoding " << e << "\n";
      ++shown;
    }
  if (shown == 0) out << "runtime and encoding agree on every encoded observable in all " << cycles << " cycles\n";
  return out.str();
}

}  // namespace cemv::checker
