// The scan cycle of a whole matrix (docs/semantics.md section M). The matrix
// is laid out for it once (scan_layout.cpp); the per-element logic lives in
// cause_block.cpp and effect_block.cpp, the operator commands (section O) in
// operator_commands.cpp.
#include "runtime/runtime.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "model/vocabulary.hpp"
#include "runtime/cause_block.hpp"
#include "runtime/effect_block.hpp"
#include "runtime/explain_rules.hpp"
#include "runtime/operator_commands.hpp"
#include "runtime/scan_layout.hpp"
#include "runtime/signals.hpp"

namespace cemv::runtime {

namespace {

// A compiled observable: which block, which field.
struct CompiledObservable {
  bool is_cause = true;
  int slot = 0;
  int field = 0;   // CauseField / EffectField, or -1 for an output tag
  int tag = 0;     // 0-based output tag
};

}  // namespace

struct Runtime::Impl {
  model::Matrix matrix;
  model::InputTable inputs;
  ScanLayout layout;
  std::vector<CauseBlock> causes;  // by slot
  std::vector<EffectBlock> effects;
  Signals signals;
  std::vector<CompiledObservable> observables;

  bool gdm_set_before = false;
  std::uint64_t cycle = 0;
  int refused = 0;
  bool group_deactivated = false;  // M.2 fired in the last cycle

  // Explanations (explain.hpp), only while explaining.
  bool explaining = false;
  std::vector<int> before;
  std::vector<std::uint8_t> accepted;  // per command of the cycle
  std::vector<Explanation> explanations;

  explicit Impl(const model::Matrix& m);
  bool compile(const model::Observable& o, CompiledObservable& out) const;
  int read(const CompiledObservable& c) const;
  void step(const model::CycleInput& in);
  void group_deactivation();
  void explain_cycle(const model::CycleInput& in);
};

Runtime::Impl::Impl(const model::Matrix& m) : matrix(m), inputs(matrix), layout(lay_out(matrix, inputs)) {
  for (const CauseConfig& cfg : layout.causes) causes.emplace_back(cfg);
  for (const EffectConfig& cfg : layout.effects) effects.emplace_back(cfg);
  signals.input_simulated.assign(inputs.size(), 0);
  signals.input_simulated_value.assign(inputs.size(), 0.0f);
  signals.cause_active.assign(causes.size(), 0);
  signals.effect_active.assign(effects.size(), 0);
  signals.effect_output.assign(effects.size(), {});

  for (const model::Observable& o : model::observables(matrix)) {
    CompiledObservable c;
    if (!compile(o, c)) throw std::logic_error("runtime: unknown observable " + o.key);
    observables.push_back(c);
  }
}

bool Runtime::Impl::compile(const model::Observable& o, CompiledObservable& out) const {
  out.is_cause = o.kind == model::Node::Kind::Cause;
  out.slot = out.is_cause ? layout.cause_slot(o.id) : layout.effect_slot(o.id);
  if (out.slot < 0) return false;
  if (out.is_cause) {
    CauseField f;
    if (!cause_field_from_name(o.field, f)) return false;
    out.field = static_cast<int>(f);
    return true;
  }
  if (o.field == "tag") {
    out.field = -1;
    out.tag = o.tag - 1;
    return out.tag >= 0 && out.tag < effects[out.slot].config().tag_count;
  }
  EffectField f;
  if (!effect_field_from_name(o.field, f)) return false;
  out.field = static_cast<int>(f);
  return true;
}

int Runtime::Impl::read(const CompiledObservable& c) const {
  if (c.is_cause) return causes[c.slot].field(static_cast<CauseField>(c.field));
  if (c.field < 0) return effects[c.slot].output(c.tag);
  return effects[c.slot].field(static_cast<EffectField>(c.field));
}

// ---- the cycle (M.1) --------------------------------------------------------

void Runtime::Impl::step(const model::CycleInput& in) {
  if (in.tags.size() != inputs.size())
    throw std::invalid_argument("runtime: the cycle input has " + std::to_string(in.tags.size()) +
                                " tag values, the matrix reads " + std::to_string(inputs.size()));
  ++cycle;
  const std::uint64_t k = cycle;
  signals.input = &in;
  refused = 0;
  group_deactivated = false;
  if (explaining) {
    before.resize(observables.size());
    for (std::size_t i = 0; i < observables.size(); ++i) before[i] = read(observables[i]);
    accepted.clear();
  }

  // Phase 1: group deactivation (M.2).
  if (layout.group_deactivation) {
    const bool enable = signals.read_bool(layout.group_deactivation->enable);
    const bool set = signals.read_bool(layout.group_deactivation->set);
    const bool edge = k > 1 && set && !gdm_set_before;
    gdm_set_before = set;
    group_deactivated = enable && edge;
    if (group_deactivated) group_deactivation();
  }

  // Phase 2: operator commands, in order, gated by secure write (M.3).
  const bool secure_write_open = !layout.secure_write_enable || signals.read_bool(*layout.secure_write_enable);
  // Made here, not kept: it refers to this Impl's members, and a copied
  // runtime must not act on the original's.
  OperatorCommands commands(layout, causes, effects, signals);
  for (const model::Command& c : in.commands) {
    const bool ok = secure_write_open && commands.apply(c, cycle);
    if (!ok) ++refused;
    if (explaining) accepted.push_back(ok);
  }

  // Phase 3: every cause and effect in the evaluation order (I.4).
  for (const Step& s : layout.order) {
    if (s.is_cause) {
      causes[s.slot].evaluate(signals, k);
      signals.cause_active[s.slot] = causes[s.slot].active();
    } else {
      effects[s.slot].evaluate(signals, s.slot, k);
    }
  }

  // Phase 4: first out (C.11): the lowest id among those that became active.
  for (int g = 1; g <= model::kMaxFirstOutGroup; ++g) {
    const std::vector<int>& group = layout.first_out_groups[g];
    bool held = false;
    for (int slot : group)
      if (causes[slot].field(CauseField::FirstOut)) held = true;
    if (held) continue;
    for (int slot : group)
      if (causes[slot].became_active()) {
        causes[slot].give_first_out();
        break;
      }
  }
  if (explaining) explain_cycle(in);
  signals.input = nullptr;
}

// Every observable that changed in this cycle, with the rule that changed it
// (explain_rules.cpp reads what each block recorded in its facts).
void Runtime::Impl::explain_cycle(const model::CycleInput& in) {
  explanations.clear();
  const CycleView view{matrix, in, accepted, group_deactivated, layout.cause_ids, layout.effect_ids, causes, effects};
  for (std::size_t i = 0; i < observables.size(); ++i) {
    const CompiledObservable& o = observables[i];
    const int after = read(o);
    if (after == before[i]) {
      // An override that ended and was started again in the same cycle keeps
      // its value but is a new override: worth saying (E.3 steps 1 and 2).
      if (!o.is_cause && o.field == static_cast<int>(EffectField::OverrideActive) && after) {
        const EffectFacts& f = effects[static_cast<std::size_t>(o.slot)].facts();
        if (f.override_started && (f.end_timeout || f.end_new_cause || f.end_no_request))
          explanations.push_back({i, before[i], after, why_effect(view, o.slot, o.field, 0, 1, 0) +
                                                           "; in the same cycle a new override started (E.3 step 2)"});
      }
      continue;
    }
    std::string why = o.is_cause ? why_cause(view, o.slot, static_cast<CauseField>(o.field), before[i], after)
                                 : why_effect(view, o.slot, o.field, o.tag, before[i], after);
    explanations.push_back({i, before[i], after, std::move(why)});
  }
}

void Runtime::Impl::group_deactivation() {
  for (auto& c : causes) c.end_maintenance();
  for (auto& e : effects) e.end_maintenance();
  std::fill(signals.input_simulated.begin(), signals.input_simulated.end(), 0);
}

// ---- public API ------------------------------------------------------------------

Runtime::Runtime(const model::Matrix& m) : impl_(std::make_unique<Impl>(m)) {}
Runtime::~Runtime() = default;
Runtime::Runtime(Runtime&&) noexcept = default;
Runtime& Runtime::operator=(Runtime&&) noexcept = default;
Runtime::Runtime(const Runtime& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}
Runtime& Runtime::operator=(const Runtime& other) {
  if (this != &other) impl_ = std::make_unique<Impl>(*other.impl_);
  return *this;
}

const model::Matrix& Runtime::matrix() const { return impl_->matrix; }
const model::InputTable& Runtime::inputs() const { return impl_->inputs; }

// S.1: the scenario format's defaults. They are a convention of the input
// format, not scan-cycle semantics, so the runtime uses the model's one definition.
model::CycleInput Runtime::default_input() const { return model::default_cycle_input(impl_->matrix); }

void Runtime::step(const model::CycleInput& in) { impl_->step(in); }
std::uint64_t Runtime::cycles_run() const { return impl_->cycle; }

int Runtime::value(const model::Observable& o) const {
  CompiledObservable c;
  if (!impl_->compile(o, c)) throw std::invalid_argument("runtime: unknown observable " + o.key);
  return impl_->read(c);
}

void Runtime::snapshot(std::vector<int>& out) const {
  out.resize(impl_->observables.size());
  for (std::size_t i = 0; i < impl_->observables.size(); ++i) out[i] = impl_->read(impl_->observables[i]);
}

int Runtime::observable(std::size_t i) const { return impl_->read(impl_->observables.at(i)); }

std::optional<bool> Runtime::output(std::string_view tag) const {
  for (std::size_t slot = 0; slot < impl_->effects.size(); ++slot) {
    const EffectConfig& cfg = impl_->effects[slot].config();
    for (int j = 0; j < cfg.tag_count; ++j)
      if (same_tag(cfg.tag_key[j], tag)) return impl_->effects[slot].output(j);
  }
  return std::nullopt;
}

int Runtime::commands_refused() const { return impl_->refused; }

void Runtime::explain(bool on) {
  impl_->explaining = on;
  impl_->explanations.clear();
}

const std::vector<Explanation>& Runtime::explanations() const { return impl_->explanations; }

}  // namespace cemv::runtime
