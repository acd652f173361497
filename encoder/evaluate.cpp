#include "encoder/evaluate.hpp"

#include <cmath>
#include <stdexcept>

namespace cemv::encoder {

namespace {
constexpr int kVar = -1;
constexpr int kConst = -2;
}  // namespace

Evaluator::Evaluator(const Encoding& enc) : enc_(enc) {
  const auto& ts = enc.ts;
  for (const auto& s : ts.statevars()) {
    int slot = static_cast<int>(program_.size());
    program_.push_back(Instr{kVar, {}, {}});
    memo_.emplace(s.var.id(), slot);
    state_slot_.push_back(slot);
  }
  for (const auto& i : ts.inputvars()) {
    input_index_.emplace(i.var.id(), input_slot_.size());
    int slot = static_cast<int>(program_.size());
    program_.push_back(Instr{kVar, {}, {}});
    memo_.emplace(i.var.id(), slot);
    input_slot_.push_back(slot);
  }
  for (const auto& s : ts.statevars()) init_slot_.push_back(compile(s.init));
  for (const auto& s : ts.statevars()) next_slot_.push_back(compile(s.next));
  for (const auto& t : ts.named_terms()) term_slot_.push_back(compile(t.term));
  for (const auto& o : enc.observables) observable_slot_.push_back(compile(*ts.term(o.key)));
  slots_.resize(program_.size());
  for (std::size_t i = 0; i < program_.size(); ++i)
    if (program_[i].op == kConst) slots_[i] = program_[i].constant;
  flatten();
  reset();
}

void Evaluator::flatten() {
  for (std::size_t i = 0; i < program_.size(); ++i) {
    const Instr& ins = program_[i];
    if (ins.op == kVar || ins.op == kConst) continue;
    ops_.push_back(Op{ins.op, static_cast<int>(i), static_cast<int>(op_args_.size()), static_cast<int>(ins.args.size())});
    op_args_.insert(op_args_.end(), ins.args.begin(), ins.args.end());
  }
}

int Evaluator::compile(const z3::expr& e) {
  auto it = memo_.find(e.id());
  if (it != memo_.end()) return it->second;
  Instr ins;
  if (!e.is_app()) throw std::logic_error("evaluator: not an application: " + e.to_string());
  z3::func_decl d = e.decl();
  Z3_decl_kind k = d.decl_kind();
  if (auto f = enc_.ts.float_value(e.id())) {
    ins.op = kConst;
    ins.constant.f = *f;
  } else if (k == Z3_OP_TRUE || k == Z3_OP_FALSE) {
    ins.op = kConst;
    ins.constant.i = k == Z3_OP_TRUE ? 1 : 0;
  } else if (k == Z3_OP_ANUM) {
    ins.op = kConst;
    ins.constant.i = e.get_numeral_int64();
  } else if (k == Z3_OP_FPA_RM_NEAREST_TIES_TO_EVEN) {
    ins.op = kConst;
  } else {
    switch (k) {
      case Z3_OP_AND: case Z3_OP_OR: case Z3_OP_NOT: case Z3_OP_ITE: case Z3_OP_EQ:
      case Z3_OP_IMPLIES: case Z3_OP_XOR: case Z3_OP_ADD: case Z3_OP_SUB: case Z3_OP_UMINUS:
      case Z3_OP_GE: case Z3_OP_LE: case Z3_OP_GT: case Z3_OP_LT:
      case Z3_OP_FPA_GE: case Z3_OP_FPA_LE: case Z3_OP_FPA_GT: case Z3_OP_FPA_LT:
      case Z3_OP_FPA_EQ: case Z3_OP_FPA_SUB: case Z3_OP_FPA_ABS: case Z3_OP_FPA_IS_NAN:
        break;
      default:
        throw std::logic_error("evaluator: unsupported operator in " + e.to_string());
    }
    ins.op = k;
    for (unsigned a = 0; a < e.num_args(); ++a) ins.args.push_back(compile(e.arg(a)));
  }
  int slot = static_cast<int>(program_.size());
  program_.push_back(std::move(ins));
  memo_.emplace(e.id(), slot);
  return slot;
}

void Evaluator::reset() {
  // Initial values are constants: evaluate them with arbitrary variable values.
  run();
  state_.resize(state_slot_.size());
  for (std::size_t i = 0; i < state_slot_.size(); ++i) state_[i] = slots_[init_slot_[i]];
  cycles_ = 0;
}

void Evaluator::run() {
  Value* s = slots_.data();
  for (const Op& o : ops_) {
    Value& r = s[o.slot];
    const int* a = op_args_.data() + o.first;
    switch (o.op) {
      case Z3_OP_AND: {
        std::int64_t v = 1;
        for (int j = 0; j < o.count; ++j) v &= s[a[j]].i;
        r.i = v;
        break;
      }
      case Z3_OP_OR: {
        std::int64_t v = 0;
        for (int j = 0; j < o.count; ++j) v |= s[a[j]].i;
        r.i = v;
        break;
      }
      case Z3_OP_NOT: r.i = !s[a[0]].i; break;
      case Z3_OP_IMPLIES: r.i = !s[a[0]].i || s[a[1]].i; break;
      case Z3_OP_XOR: r.i = s[a[0]].i != s[a[1]].i; break;
      case Z3_OP_ITE: r = s[a[0]].i ? s[a[1]] : s[a[2]]; break;
      case Z3_OP_EQ: {
        // Bool and Int compare the integer; Float32 compares bit patterns
        // (SMT-LIB '=' on FP is structural: -0 != +0). NaN never occurs.
        const Value& x = s[a[0]];
        const Value& y = s[a[1]];
        r.i = x.i == y.i && std::signbit(x.f) == std::signbit(y.f) && (x.f == y.f);
        break;
      }
      case Z3_OP_ADD: {
        std::int64_t v = 0;
        for (int j = 0; j < o.count; ++j) v += s[a[j]].i;
        r.i = v;
        break;
      }
      case Z3_OP_SUB: {
        std::int64_t v = s[a[0]].i;
        for (int j = 1; j < o.count; ++j) v -= s[a[j]].i;
        r.i = v;
        break;
      }
      case Z3_OP_UMINUS: r.i = -s[a[0]].i; break;
      case Z3_OP_GE: r.i = s[a[0]].i >= s[a[1]].i; break;
      case Z3_OP_LE: r.i = s[a[0]].i <= s[a[1]].i; break;
      case Z3_OP_GT: r.i = s[a[0]].i > s[a[1]].i; break;
      case Z3_OP_LT: r.i = s[a[0]].i < s[a[1]].i; break;
      case Z3_OP_FPA_GE: r.i = s[a[0]].f >= s[a[1]].f; break;
      case Z3_OP_FPA_LE: r.i = s[a[0]].f <= s[a[1]].f; break;
      case Z3_OP_FPA_GT: r.i = s[a[0]].f > s[a[1]].f; break;
      case Z3_OP_FPA_LT: r.i = s[a[0]].f < s[a[1]].f; break;
      case Z3_OP_FPA_EQ: r.i = s[a[0]].f == s[a[1]].f; break;
      // args: rounding mode, x, y. The default floating-point environment
      // rounds to nearest even, and float arithmetic is single precision.
      case Z3_OP_FPA_SUB: {
        volatile float x = s[a[1]].f;
        volatile float y = s[a[2]].f;
        r.f = x - y;
        break;
      }
      case Z3_OP_FPA_ABS: r.f = std::fabs(s[a[0]].f); break;
      case Z3_OP_FPA_IS_NAN: r.i = std::isnan(s[a[0]].f); break;
      default:
        throw std::logic_error("evaluator: unsupported operator");
    }
  }
}

std::vector<Evaluator::Value> Evaluator::input_values(const model::CycleInput& in) const {
  const auto& ts = enc_.ts;
  std::vector<Value> v(ts.inputvars().size());
  auto set_var = [&](const z3::expr& var, Value val) {
    auto it = input_index_.find(var.id());
    if (it != input_index_.end()) v[it->second] = val;
  };
  for (std::size_t t = 0; t < enc_.tag_value.size() && t < in.tags.size(); ++t) {
    const auto& tv = in.tags[t];
    if (enc_.tag_value[t]) {
      Value val;
      if (enc_.tag_value[t]->is_fpa()) val.f = tv.value;
      else val.i = tv.value != 0.0f;
      set_var(*enc_.tag_value[t], val);
    }
    if (enc_.tag_bad[t]) set_var(*enc_.tag_bad[t], Value{tv.bad_quality ? 1 : 0, 0.0f});
  }
  for (const auto& c : in.commands) {
    const CommandInput* ci = enc_.find_command(c);
    if (!ci) continue;
    set_var(ci->var, Value{1, 0.0f});
    if (ci->value) {
      Value val;
      if (ci->value->is_fpa()) val.f = c.value;
      else val.i = c.value != 0.0f;
      set_var(*ci->value, val);
    }
  }
  return v;
}

void Evaluator::step(const model::CycleInput& in) { step_raw(input_values(in)); }

void Evaluator::step_raw(const std::vector<Value>& inputs) {
  for (std::size_t i = 0; i < state_slot_.size(); ++i) slots_[state_slot_[i]] = state_[i];
  for (std::size_t i = 0; i < input_slot_.size() && i < inputs.size(); ++i)
    slots_[input_slot_[i]] = inputs[i];
  run();
  for (std::size_t i = 0; i < state_slot_.size(); ++i) state_[i] = slots_[next_slot_[i]];
  ++cycles_;
}

int Evaluator::value(const std::string& key) const {
  const auto& terms = enc_.ts.named_terms();
  for (std::size_t i = 0; i < terms.size(); ++i)
    if (terms[i].name == key) return static_cast<int>(slots_[term_slot_[i]].i);
  throw std::out_of_range("no named term " + key);
}

void Evaluator::snapshot(std::vector<int>& out) const {
  out.resize(observable_slot_.size());
  for (std::size_t i = 0; i < observable_slot_.size(); ++i)
    out[i] = static_cast<int>(slots_[observable_slot_[i]].i);
}

}  // namespace cemv::encoder
