#include "tests/encoder/diff_support.hpp"

#include <sstream>

#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"
#include "formats/matrix_json.hpp"
#include "model/text.hpp"
#include "model/validate.hpp"
#include "runtime/runtime.hpp"

namespace cemv::encoder_test {

std::optional<Disagreement> compare(const model::Matrix& m,
                                    const std::vector<model::CycleInput>& inputs) {
  z3::context ctx;
  auto enc = encoder::encode(ctx, m);
  encoder::Evaluator ev(*enc);
  runtime::Runtime rt(m);
  const auto obs = model::observables(m);
  std::vector<int> a, b;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    model::CycleInput in = inputs[k];
    in.commands = enc->canonical_commands(in.commands);
    rt.step(in);
    ev.step(in);
    rt.snapshot(a);
    ev.snapshot(b);
    if (a.size() != obs.size() || b.size() != obs.size())
      return Disagreement{k, "(observable count)", static_cast<int>(a.size()),
                          static_cast<int>(b.size())};
    for (std::size_t i = 0; i < obs.size(); ++i)
      if (a[i] != b[i]) return Disagreement{k, obs[i].key, a[i], b[i]};
  }
  return std::nullopt;
}

namespace {

// Inputs re-indexed for a smaller matrix (tags matched by name).
std::vector<model::CycleInput> reindex(const model::Matrix& from, const model::Matrix& to,
                                       const std::vector<model::CycleInput>& in) {
  model::InputTable a(from), b(to);
  std::vector<model::CycleInput> out;
  for (const auto& c : in) {
    model::CycleInput n;
    n.tags.resize(b.size());
    for (std::size_t i = 0; i < b.size(); ++i)
      if (auto j = a.find(b.tags()[i].name); j && *j < c.tags.size()) n.tags[i] = c.tags[*j];
    n.commands = c.commands;
    out.push_back(std::move(n));
  }
  return out;
}

bool still_fails(const model::Matrix& m, const std::vector<model::CycleInput>& in) {
  if (model::has_errors(model::validate(m))) return false;
  try {
    return compare(m, in).has_value();
  } catch (...) {
    return false;
  }
}

std::string input_text(const model::Matrix& m, const std::vector<model::CycleInput>& in) {
  model::InputTable t(m);
  std::ostringstream o;
  for (std::size_t k = 0; k < in.size(); ++k) {
    o << "cycle " << k << ":";
    for (std::size_t i = 0; i < in[k].tags.size() && i < t.size(); ++i) {
      o << " " << t.tags()[i].name << "=" << model::float_text(in[k].tags[i].value);
      if (in[k].tags[i].bad_quality) o << "(bad)";
    }
    for (const auto& c : in[k].commands) {
      o << " [" << model::to_string(c.op);
      if (c.cause) o << " cause=" << c.cause;
      if (c.effect) o << " effect=" << c.effect;
      if (c.tag) o << " tag=" << c.tag;
      if (c.group) o << " group=" << c.group;
      if (!c.tag_name.empty()) o << " name=" << c.tag_name;
      if (c.op == model::CommandOp::SimulateTag) o << " value=" << model::float_text(c.value);
      if (c.op == model::CommandOp::SoftBypassCause || c.op == model::CommandOp::SoftBypassTag ||
          c.op == model::CommandOp::SoftBypassEffect)
        o << " on=" << (c.on ? "true" : "false");
      o << "]";
    }
    o << "\n";
  }
  return o.str();
}

}  // namespace

std::string report(std::uint64_t seed, const model::Matrix& m0,
                   const std::vector<model::CycleInput>& in0, const Disagreement& d0) {
  model::Matrix m = m0;
  std::vector<model::CycleInput> in(in0.begin(), in0.begin() + static_cast<long>(d0.cycle + 1));
  // Shrink: drop elements one at a time while the disagreement remains.
  bool progress = true;
  for (int round = 0; progress && round < 4; ++round) {
    progress = false;
    // Removes list element i (via `without`) whenever the disagreement survives it.
    auto shrink = [&](auto size_of, auto without) {
      for (std::size_t i = 0; i < size_of(m);) {
        model::Matrix t = without(m, i);
        auto t_in = reindex(m, t, in);
        if (still_fails(t, t_in)) {
          in = std::move(t_in);
          m = std::move(t);
          progress = true;
        } else {
          ++i;
        }
      }
    };
    shrink([](const model::Matrix& x) { return x.intersections.size(); },
           [](model::Matrix t, std::size_t i) {
             t.intersections.erase(t.intersections.begin() + static_cast<long>(i));
             return t;
           });
    shrink([](const model::Matrix& x) { return x.effects.size(); },
           [](model::Matrix t, std::size_t i) {
             int id = t.effects[i].id;
             t.effects.erase(t.effects.begin() + static_cast<long>(i));
             std::erase_if(t.intersections, [&](const auto& x) { return x.effect == id; });
             return t;
           });
    shrink([](const model::Matrix& x) { return x.causes.size(); },
           [](model::Matrix t, std::size_t i) {
             int id = t.causes[i].id;
             t.causes.erase(t.causes.begin() + static_cast<long>(i));
             std::erase_if(t.intersections, [&](const auto& x) { return x.cause == id; });
             return t;
           });
    // Drop leading cycles is not sound (state); drop commands instead.
    for (std::size_t k = 0; k < in.size(); ++k)
      for (std::size_t j = 0; j < in[k].commands.size();) {
        auto t = in;
        t[k].commands.erase(t[k].commands.begin() + static_cast<long>(j));
        if (still_fails(m, t)) {
          in = std::move(t);
          progress = true;
        } else {
          ++j;
        }
      }
  }
  auto d = compare(m, in).value_or(d0);
  std::ostringstream o;
  o << "runtime and encoder disagree: seed " << seed << ", first difference at cycle " << d.cycle
    << " (0-based): " << d.key << " runtime=" << d.runtime << " encoder=" << d.encoder << "\n"
    << "(original: cycle " << d0.cycle << ", " << d0.key << ")\n"
    << "minimized matrix:\n"
    << formats::to_canonical_json(m) << "inputs:\n"
    << input_text(m, in);
  return o.str();
}

}  // namespace cemv::encoder_test
