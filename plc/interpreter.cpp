#include "plc/interpreter.hpp"

#include <stdexcept>

#include "model/text.hpp"
#include "plc/blocks.hpp"
#include "plc/check.hpp"
#include "plc/values.hpp"

namespace cemv::plc {

Value default_value(Type t) { return Value{t, 0, 0}; }

namespace {

// Where each variable of a POU lives in its frame: by declared name (the
// checked AST spells every reference so).
struct Layout {
  std::map<std::string, std::size_t, std::less<>> index;
};

// One instance of a POU: its variables, the state of its block instances.
struct Frame {
  const Pou* pou = nullptr;
  const Layout* layout = nullptr;
  std::vector<Value> values;  // elementary variables (unused slots for instances)
  std::vector<BlockState> blocks;                 // standard block instances
  std::vector<std::unique_ptr<Frame>> children;   // user block instances
  std::vector<std::optional<Position>> assigned;  // in the latest scan
};

}  // namespace

struct Interpreter::Impl {
  const Program* program = nullptr;
  const Pou* main = nullptr;
  std::map<const Pou*, Layout> layouts;
  std::unique_ptr<Frame> frame;
  std::size_t scans = 0;
  std::int64_t now = 0;

  const Layout& layout(const Pou& pou) {
    auto [it, fresh] = layouts.try_emplace(&pou);
    if (fresh)
      for (std::size_t i = 0; i < pou.variables.size(); ++i) it->second.index.emplace(pou.variables[i].name, i);
    return it->second;
  }

  std::unique_ptr<Frame> make_frame(const Pou& pou) {
    auto f = std::make_unique<Frame>();
    f->pou = &pou;
    f->layout = &layout(pou);
    const std::size_t n = pou.variables.size();
    f->values.resize(n);
    f->blocks.resize(n);
    f->children.resize(n);
    f->assigned.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Variable& v = pou.variables[i];
      switch (v.type.kind) {
        case VarType::Kind::Elementary: f->values[i] = v.initial ? *v.initial : default_value(v.type.type); break;
        case VarType::Kind::Standard: f->blocks[i].kind = v.type.block; break;
        case VarType::Kind::User: f->children[i] = make_frame(*find_pou(*program, v.type.user)); break;
      }
    }
    return f;
  }

  static std::size_t slot(const Frame& f, std::string_view name) {
    auto it = f.layout->index.find(name);
    if (it == f.layout->index.end()) throw std::logic_error("plc interpreter: unresolved name " + std::string(name));
    return it->second;
  }

  // --- expressions

  Value eval(const Expr& e, Frame& f) {
    switch (e.kind) {
      case Expr::Kind::Literal: return e.literal;
      case Expr::Kind::Variable: return f.values[slot(f, e.name)];
      case Expr::Kind::Member: {
        const std::size_t i = slot(f, e.name);
        if (e.pin) return pin_value(f.blocks[i], *e.pin);
        Frame& child = *f.children[i];
        return child.values[slot(child, e.member)];
      }
      case Expr::Kind::Unary: {
        const Value a = eval(e.args[0], f);
        return e.unary == UnaryOp::Not ? Value{Type::Bool, a.integer ? 0 : 1, 0} : negate(a);
      }
      case Expr::Kind::Binary: return binary(e.binary, eval(e.args[0], f), eval(e.args[1], f));
      case Expr::Kind::Call: {
        std::vector<Value> args;
        args.reserve(e.args.size());
        for (const Expr& a : e.args) args.push_back(eval(a, f));
        return call(e.function, args);
      }
    }
    return {};
  }

  // --- statements

  void run(const std::vector<Statement>& body, Frame& f) {
    for (const Statement& s : body) run(s, f);
  }

  void assign(Frame& f, std::size_t i, const Value& v, Position at) {
    f.values[i] = v;
    f.assigned[i] = at;
  }

  void run(const Statement& s, Frame& f) {
    switch (s.kind) {
      case Statement::Kind::Assign: return assign(f, slot(f, s.target), eval(s.value, f), s.position);
      case Statement::Kind::If:
        for (const Branch& b : s.branches)
          if (eval(b.condition, f).integer) return run(b.body, f);
        return run(s.else_body, f);
      case Statement::Kind::Case: {
        const std::int64_t v = eval(s.value, f).integer;
        for (const CaseArm& arm : s.arms)
          for (const CaseRange& r : arm.labels)
            if (r.low <= v && v <= r.high) return run(arm.body, f);
        return run(s.else_body, f);
      }
      case Statement::Kind::For: {  // P.4.4
        const std::size_t i = slot(f, s.target);
        const Type t = f.pou->variables[i].type.type;
        const std::int64_t n = for_iterations(s);
        for (std::int64_t k = 0; k < n; ++k) {
          assign(f, i, Value{t, s.from + k * s.by, 0}, s.position);
          run(s.body, f);
        }
        return assign(f, i, Value{t, s.from + n * s.by, 0}, s.position);
      }
      case Statement::Kind::Call: return call_block(s, f);
    }
  }

  void call_block(const Statement& s, Frame& f) {  // P.4.5
    const std::size_t i = slot(f, s.target);
    if (f.pou->variables[i].type.kind == VarType::Kind::Standard) {
      BlockState& b = f.blocks[i];
      for (const CallArg& a : s.args)
        if (!a.output) set_pin(b, *a.pin, eval(a.value, f));
      execute(b, now);
      for (const CallArg& a : s.args)
        if (a.output) assign(f, slot(f, a.value.name), pin_value(b, *a.pin), a.position);
      return;
    }
    Frame& child = *f.children[i];
    std::vector<std::pair<std::size_t, std::size_t>> in_out;  // child slot, caller slot
    for (const CallArg& a : s.args) {
      if (a.output) continue;
      const std::size_t c = slot(child, a.name);
      child.values[c] = eval(a.value, f);
      if (child.pou->variables[c].section == Section::InOut) in_out.emplace_back(c, slot(f, a.value.name));
    }
    for (auto& at : child.assigned) at.reset();
    run(child.pou->body, child);
    for (auto [c, caller] : in_out)
      if (child.assigned[c]) assign(f, caller, child.values[c], s.position);
    for (const CallArg& a : s.args)
      if (a.output) assign(f, slot(f, a.value.name), child.values[slot(child, a.name)], a.position);
  }
};

Interpreter::Interpreter(const Program& program, std::string_view pou) : impl_(std::make_unique<Impl>()) {
  impl_->program = &program;
  for (const Pou& p : program.pous) {
    if (p.kind != PouKind::Program) continue;
    if (pou.empty() ? impl_->main != nullptr : !same_name(p.name, pou)) {
      if (pou.empty()) throw std::invalid_argument("the program has several PROGRAMs; name one");
      continue;
    }
    impl_->main = &p;
  }
  if (!impl_->main)
    throw std::invalid_argument(pou.empty() ? "the program has no PROGRAM" : "no PROGRAM " + model::in_quotes(pou));
  reset();
}

Interpreter::~Interpreter() = default;
Interpreter::Interpreter(Interpreter&&) noexcept = default;
Interpreter& Interpreter::operator=(Interpreter&&) noexcept = default;

const Pou& Interpreter::pou() const { return *impl_->main; }
std::size_t Interpreter::scans() const { return impl_->scans; }
std::int64_t Interpreter::now_ms() const { return impl_->now; }

void Interpreter::reset() {
  impl_->frame = impl_->make_frame(*impl_->main);
  impl_->scans = 0;
  impl_->now = 0;
}

void Interpreter::step(const std::map<std::string, Value>& inputs, std::int64_t scan_time_ms) {
  if (scan_time_ms <= 0) throw std::invalid_argument("the scan time must be positive");
  Frame& f = *impl_->frame;
  std::vector<std::pair<std::size_t, Value>> image;
  for (const auto& [name, v] : inputs) {
    const Variable* var = find_variable(*f.pou, name);
    if (!var) throw std::invalid_argument("no variable " + model::in_quotes(name) + " in " + model::in_quotes(f.pou->name));
    if (var->section != Section::Input && var->section != Section::InOut)
      throw std::invalid_argument(model::in_quotes(var->name) + " is not an input of " + model::in_quotes(f.pou->name));
    if (var->type.type != v.type)
      throw std::invalid_argument("a " + std::string(type_name(v.type)) + " given for " + model::in_quotes(var->name) +
                                  " of type " + std::string(type_name(var->type.type)));
    image.emplace_back(Impl::slot(f, var->name), v);
  }
  ++impl_->scans;
  impl_->now += scan_time_ms;
  for (auto& at : f.assigned) at.reset();
  for (auto& [i, v] : image) f.values[i] = v;
  impl_->run(f.pou->body, f);
}

Value Interpreter::value(std::string_view name) const {
  const Frame* f = impl_->frame.get();
  for (;;) {
    const std::size_t dot = name.find('.');
    const std::string_view head = name.substr(0, dot);
    const Variable* v = find_variable(*f->pou, head);
    if (!v) throw std::invalid_argument("no variable " + model::in_quotes(head) + " in " + model::in_quotes(f->pou->name));
    const std::size_t i = Impl::slot(*f, v->name);
    if (dot == std::string_view::npos) {
      if (v->type.kind != VarType::Kind::Elementary)
        throw std::invalid_argument(model::in_quotes(v->name) + " is a block instance");
      return f->values[i];
    }
    const std::string_view rest = name.substr(dot + 1);
    if (v->type.kind == VarType::Kind::Standard) {
      for (const PinInfo& p : block_pins(v->type.block))
        if (same_name(pin_name(p.pin), rest)) return pin_value(f->blocks[i], p.pin);
      throw std::invalid_argument("no pin " + model::in_quotes(rest) + " of " + model::in_quotes(v->name));
    }
    if (v->type.kind != VarType::Kind::User) throw std::invalid_argument(model::in_quotes(v->name) + " is not a block instance");
    f = f->children[i].get();
    name = rest;
  }
}

std::optional<Position> Interpreter::last_assignment(std::string_view name) const {
  const Frame& f = *impl_->frame;
  const Variable* v = find_variable(*f.pou, name);
  if (!v) throw std::invalid_argument("no variable " + model::in_quotes(name) + " in " + model::in_quotes(f.pou->name));
  return f.assigned[Impl::slot(f, v->name)];
}

}  // namespace cemv::plc
