#include "encoder/product.hpp"

#include <stdexcept>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "encoder/term_memo.hpp"

namespace cemv::encoder {

namespace {

// Copies one encoding into the product under `prefix`: state variables
// renamed, everything else rewritten over the renamed variables.
class Copier {
 public:
  Copier(TransitionSystem& out, const TransitionSystem& in, const std::string& prefix)
      : out_(out), in_(in), prefix_(prefix), from_(in.ctx()), to_(in.ctx()) {}

  void run() {
    for (const auto& s : in_.statevars()) {
      z3::expr v = out_.make_statevar(prefix_ + s.name, s.var.get_sort());
      renamed_.emplace(s.var.id(), static_cast<std::size_t>(to_.size()));
      from_.push_back(s.var);
      to_.push_back(v);
    }
    for (const auto& i : in_.inputvars()) {
      if (out_.is_inputvar(i.var)) continue;
      // One name, two sorts: a tag analog in one matrix and discrete in the
      // other. The copies cannot share it, and sharing by name is the
      // product's premise.
      if (out_.inputvar(i.name))
        throw std::invalid_argument("input " + i.name + " has a different type in the two matrices");
      out_.make_inputvar(i.name, i.var.get_sort());
    }
    const auto& states = in_.statevars();
    for (std::size_t k = 0; k < states.size(); ++k) {
      if (states[k].has_init) out_.set_init(to_[static_cast<int>(k)], copy(states[k].init));
      if (states[k].has_next) out_.assign_next(to_[static_cast<int>(k)], copy(states[k].next));
    }
    for (const auto& c : in_.constraints()) out_.add_constraint(prefix_ + c.name, copy(c.term));
    for (const auto& t : in_.named_terms()) out_.name_term(prefix_ + t.name, copy(t.term));
    for (const auto& l : in_.lemmas()) out_.add_lemma(prefix_ + l.name, copy(l.term));
  }

 private:
  z3::expr copy(const z3::expr& e) {
    register_floats(e);
    return rewrite(e);
  }
  // e over the renamed state variables. One memo for every term of the copy:
  // the next-state functions, named terms and lemmas of an encoding share
  // most of their subterms, and a substitution per term walked the shared
  // part again for each (a 128 x 128 cone: minutes; docs/performance.md).
  z3::expr rewrite(const z3::expr& e) {
    if (const z3::expr* known = memo_.find(e)) return *known;
    z3::expr r = e;
    if (auto v = renamed_.find(e.id()); v != renamed_.end()) {
      r = to_[static_cast<int>(v->second)];
    } else if (!e.is_app()) {
      r = z3::expr(e).substitute(from_, to_);  // a quantifier (none in encodings today): Z3's own substitution
    } else if (e.num_args() > 0) {
      z3::expr_vector args(e.ctx());
      std::vector<Z3_ast> raw;
      bool changed = false;
      for (unsigned i = 0; i < e.num_args(); ++i) {
        z3::expr a = rewrite(e.arg(i));
        changed |= !z3::eq(a, e.arg(i));
        args.push_back(a);
        raw.push_back(a);
      }
      if (changed) {
        Z3_ast u = Z3_update_term(e.ctx(), e, static_cast<unsigned>(raw.size()), raw.data());
        e.ctx().check_error();
        r = z3::expr(e.ctx(), u);
      }
    }
    return memo_.emplace(e, r);
  }
  // The Evaluator (and every engine that samples runs) reads float constants
  // through TransitionSystem::float_value: the product must know them too.
  void register_floats(const z3::expr& e) {
    if (!seen_.insert(e.id()).second) return;
    if (e.is_app()) {
      if (auto f = in_.float_value(e.id())) {
        out_.float_const(*f);
        return;
      }
      for (unsigned i = 0; i < e.num_args(); ++i) register_floats(e.arg(i));
    }
  }

  TransitionSystem& out_;
  const TransitionSystem& in_;
  std::string prefix_;
  z3::expr_vector from_, to_;
  std::unordered_map<unsigned, std::size_t> renamed_;  // state variable id -> index in to_
  TermMemo<z3::expr> memo_;
  std::unordered_set<unsigned> seen_;
};

}  // namespace

std::unique_ptr<Product> product(z3::context& ctx, const model::Matrix& a, const model::Matrix& b,
                                 const std::vector<model::Node>& roots_a,
                                 const std::vector<model::Node>& roots_b) {
  auto p = std::make_unique<Product>(ctx);
  p->a = encode(ctx, a, roots_a);
  p->b = encode(ctx, b, roots_b);
  Copier(p->ts, p->a->ts, "a.").run();
  Copier(p->ts, p->b->ts, "b.").run();
  // Relational lemmas between the two copies (header comment).
  // (Copies keep the state order: copy a's variable k is product variable k,
  // copy b's variable k is product variable |a| + k.)
  const auto& all = p->ts.statevars();
  const std::size_t na = p->a->ts.statevars().size();
  std::unordered_map<std::string, std::size_t> in_b;
  for (std::size_t k = 0; k < p->b->ts.statevars().size(); ++k) in_b.emplace(p->b->ts.statevars()[k].name, k);
  for (std::size_t k = 0; k < na; ++k) {
    const auto& s = p->a->ts.statevars()[k];
    auto it = in_b.find(s.name);
    if (it == in_b.end()) continue;
    const z3::expr& va = all[k].var;
    const z3::expr& vb = all[na + it->second].var;
    if (!z3::eq(va.get_sort(), vb.get_sort())) continue;
    p->ts.add_lemma("eq." + s.name, va == vb);
  }
  p->ts.check_complete();
  return p;
}

}  // namespace cemv::encoder
