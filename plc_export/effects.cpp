// Section E of docs/semantics.md as statements: one block of the body per
// processed effect, in the evaluation order. The effect's soft bypass and the
// simulation of its outputs are not in the program (the map declares them
// unused).
#include <algorithm>

#include "plc_export/export.hpp"
#include "plc_export/generator.hpp"
#include "plc_export/st_build.hpp"

namespace cemv::plc_export {

namespace {

using model::IntersectionType;
using plc::BinaryOp;
using plc::Expr;
using plc::Statement;
using plc::Type;

const char* type_letter(IntersectionType t) {
  switch (t) {
    case IntersectionType::N: return "N";
    case IntersectionType::S: return "S";
    case IntersectionType::V: return "V";
    case IntersectionType::R: return "R";
    default: return "?";
  }
}

struct Link {
  int cause = 0;
  IntersectionType type = IntersectionType::N;
  bool xoon = false;
};

// Writes one effect's block of the body, step by step of section E; the
// order of the steps is the order of the statements and declarations.
class EffectWriter {
 public:
  EffectWriter(Generator& g, const model::Effect& e)
      : g_(g), e_(e), E_(g.effect_var.at(e.id)), label_(element_label(e)),
        section_("Effect " + std::to_string(e.id) + " " + e.name +
                 (e.description.empty() ? "" : " (" + e.description + ")") + " [6.4, 6.5.2].") {}

  void write() {
    find_links();
    declare_delay_running();
    carry_override();
    read_reset_edge();
    form_requests();
    if (override_possible_)
      run_override();
    else
      form_reset_request();
    update_latches();
    assign_active();
    run_output_delay();
    assign_outputs();
  }

 private:
  void emit(Statement s) { g_.body.push_back(std::move(s)); }
  bool present(IntersectionType t) const {
    return std::any_of(links_.begin(), links_.end(), [&](const Link& l) { return l.type == t; });
  }
  Expr request(IntersectionType t) const { return req_.count(t) ? req_.at(t) : st::boolean(false); }
  Expr bypassed() const { return hard_bypass_ ? g_.tag_bool(*e_.bypass_tag) : st::boolean(false); }
  Expr delay_running_prev() const {
    return delay_running_.empty() ? st::boolean(false) : st::var(delay_running_);
  }

  // E.2 links: processed intersections with processed causes; the XooN
  // assignment's X is the smallest given, its type the first cause's.
  void find_links() {
    for (const auto* x : g_.m.intersections_of_effect(e_.id)) {
      if (!model::is_processed(x->type) || !g_.cause_var.count(x->cause)) continue;
      links_.push_back({x->cause, x->type, x->xoon.has_value()});
      if (x->xoon) {
        xoon_x_ = has_xoon_ ? std::min(xoon_x_, *x->xoon) : *x->xoon;
        if (!has_xoon_) xoon_type_ = x->type;
        has_xoon_ = true;
      }
    }
    has_s_ = present(IntersectionType::S);
    has_r_ = present(IntersectionType::R);
    override_possible_ = e_.override_time.has_value() && (present(IntersectionType::V) || has_r_);
    hard_bypass_ = e_.bypass_tag && !e_.bypass_tag->empty();
  }

  // E.1 reads: whether the output delay ran in the previous scan.
  void declare_delay_running() {
    if (e_.output_delay_ms > 0 && (override_possible_ || has_s_ || has_r_))
      delay_running_ =
          g_.local(E_ + "_DELAY_RUNNING", Type::Bool, "E.7 output delay running; read as the previous scan's");
  }

  // E.3: the override's state, carried from the previous scan.
  void carry_override() {
    if (!override_possible_) return;
    running_ = g_.local(E_ + "_OVERRIDE", Type::Bool, "E.3 override running");
    was_running_ = g_.local(E_ + "_OVERRIDE_WAS", Type::Bool, "E.3 override running at the end of the previous scan");
    scans_var_ = g_.local(E_ + "_OVERRIDE_SCANS", Type::Dint, "scans since the override started");
    emit(st::assign(was_running_, st::var(running_), section_ + " E.3: the override of the previous scan."));
    section_.clear();
    if (has_r_) req_r_prev_ = g_.local(E_ + "_REQ_R_PREV", Type::Bool, "the R request of the previous scan (E.5)");
    if (!g_.group_deactivation.empty())
      emit(st::if_(st::var(g_.group_deactivation), {st::assign(running_, st::boolean(false))},
                   "M.2: group deactivation ends the override."));
  }

  // E.1: the rising edge of the reset tag.
  void read_reset_edge() {
    if (!e_.reset_tag || e_.reset_tag->empty()) return;
    const std::string& tag = *e_.reset_tag;
    const std::string prev =
        g_.local(E_ + "_RESET_TAG_PREV", Type::Bool,
                 tag + " in the previous scan; TRUE at start-up: no edge in scan 1 (T.4)", plc::Literal{Type::Bool, 1, 0.0f});
    reset_edge_ = g_.local(E_ + "_RESET_EDGE", Type::Bool, "E.1 rising edge of the reset tag");
    emit(st::assign(reset_edge_, st::and_(g_.tag_bool(tag), st::not_(st::var(prev))),
                    section_ + " E.1: the rising edge of the reset tag " + tag + " (T.4)."));
    section_.clear();
    emit(st::assign(prev, g_.tag_bool(tag)));
  }

  // E.2 requests, one variable per intersection type present.
  void form_requests() {
    for (IntersectionType t : {IntersectionType::N, IntersectionType::S, IntersectionType::V, IntersectionType::R}) {
      if (!present(t)) continue;
      std::vector<Expr> terms;
      std::string causes;
      for (const Link& l : links_)
        if (l.type == t && !l.xoon) {
          terms.push_back(st::var(g_.cause_var.at(l.cause)));
          causes += (causes.empty() ? "" : ", ") + std::to_string(l.cause);
        }
      std::string text = std::string("E.2 ") + type_letter(t) + " request";
      if (!causes.empty()) text += " from causes " + causes;
      if (has_xoon_ && xoon_type_ == t) {
        terms.push_back(xoon_vote());
        text += (causes.empty() ? "" : ", or ") + xoon_text();
      }
      const std::string v =
          g_.local(E_ + "_REQ_" + type_letter(t), Type::Bool, std::string("E.2 ") + type_letter(t) + " request");
      if (t == IntersectionType::R && !req_r_prev_.empty()) emit(st::assign(req_r_prev_, st::var(v)));
      emit(st::assign(v, st::any(std::move(terms)), section_.empty() ? text + "." : section_ + " " + text + "."));
      section_.clear();
      req_[t] = st::var(v);
    }
  }

  // E.2 XooN: at least X of the XooN causes active.
  Expr xoon_vote() const {
    Expr sum;
    bool first = true;
    for (const Link& l : links_) {
      if (!l.xoon) continue;
      Expr term = st::sel(st::var(g_.cause_var.at(l.cause)), st::integer(0, Type::Int), st::integer(1, Type::Int),
                          Type::Int);
      sum = first ? std::move(term) : st::binary(BinaryOp::Add, std::move(sum), std::move(term), Type::Int);
      first = false;
    }
    return st::binary(BinaryOp::Ge, std::move(sum), st::integer(xoon_x_, Type::Int), Type::Bool);
  }
  std::string xoon_text() const {
    std::string members;
    int count = 0;
    for (const Link& l : links_) {
      if (!l.xoon) continue;
      ++count;
      members += (members.empty() ? "" : ", ") + std::to_string(l.cause);
    }
    return " " + std::to_string(xoon_x_) + "oo" + std::to_string(count) + " of causes " + members;
  }

  // E.3: the reset tag's edge and the override commands toggle the override.
  Expr toggle() const {
    Expr t = reset_edge_.empty() ? st::boolean(false) : st::var(reset_edge_);
    if (auto it = g_.override_var.find(e_.id); it != g_.override_var.end())
      t = st::or_(std::move(t), st::or_(g_.command(it->second), g_.command(g_.stop_override_var.at(e_.id))));
    return t;
  }
  Expr reset_command() const {
    auto it = g_.reset_var.find(e_.id);
    return it != g_.reset_var.end() ? g_.command(it->second) : st::boolean(false);
  }

  // E.3 steps 1 and 2, and E.4's reset request when the effect has an override block.
  void run_override() {
    end_running_override();
    if (has_s_ || has_r_) {
      reset_request_ = g_.local(E_ + "_RESET_REQUEST", Type::Bool, "E.4 reset request of this scan");
      emit(st::assign(reset_request_, reset_command()));
    }
    const Expr vr = st::or_(request(IntersectionType::V), request(IntersectionType::R));
    std::vector<plc::Branch> branches;
    branches.push_back({st::var(running_), {st::assign(running_, st::boolean(false))}});
    branches.push_back({st::all({vr, st::not_(bypassed()), st::not_(delay_running_prev())}), start_});
    std::vector<Statement> otherwise;
    if (!reset_request_.empty()) otherwise.push_back(st::assign(reset_request_, st::boolean(true)));
    const Expr t = toggle();
    if (!st::is_false(t))
      emit(st::if_(t, {st::if_chain(std::move(branches), std::move(otherwise))},
                   "E.3 step 2 [10.7.3.1, 13.2.1]: a toggle request stops a running override, else starts "
                   "one, else is a reset request."));
  }

  // E.3 step 1: a running override counts its scans and ends; the starting
  // statements (start_) remember which linked causes were active.
  void end_running_override() {
    const std::int64_t d = g_.scans(static_cast<std::uint64_t>(e_.override_time->max_s) * 1000u, label_);
    std::vector<Expr> ends = {st::binary(BinaryOp::Ge, st::var(scans_var_, Type::Dint), st::integer(d), Type::Bool)};
    start_ = {st::assign(running_, st::boolean(true)), st::assign(scans_var_, st::integer(0))};
    std::map<int, std::string> saw;
    for (const Link& l : links_) {
      const std::string c = g_.cause_var.at(l.cause);
      if (saw.count(l.cause)) continue;
      saw[l.cause] = g_.local(E_ + "_OVERRIDE_SAW_" + c, Type::Bool,
                              "cause " + std::to_string(l.cause) + " was active when the override started (E.3)");
      ends.push_back(st::and_(st::var(c), st::not_(st::var(saw[l.cause]))));
      start_.push_back(st::assign(saw[l.cause], st::var(c)));
    }
    ends.push_back(st::not_(st::or_(request(IntersectionType::V), request(IntersectionType::R))));
    emit(st::if_(
        st::var(running_),
        {st::assign(scans_var_, st::binary(BinaryOp::Add, st::var(scans_var_, Type::Dint), st::integer(1), Type::Dint)),
         st::if_(st::any(ends), {st::assign(running_, st::boolean(false))})},
        "E.3 step 1 [6.4.5, 13.2]: a running override ends after " + std::to_string(d) +
            " scans, when a linked cause that was not active at its start becomes active, or when neither V nor R "
            "is requested."));
  }

  // E.4 without an override block: a toggle is a reset.
  void form_reset_request() {
    if (!has_s_ && !has_r_) return;
    Expr any_reset = st::or_(reset_command(), toggle());
    if (st::is_false(any_reset)) return;
    reset_request_ = g_.local(E_ + "_RESET_REQUEST", Type::Bool, "E.4 reset request of this scan");
    emit(st::assign(reset_request_, any_reset,
                    "E.4: a reset request (the reset tag's edge or a command; without an override "
                    "block a toggle is a reset)."));
  }

  // E.4, E.5 latches.
  void update_latches() {
    if (has_s_) s_latch_ = g_.local(E_ + "_S_LATCH", Type::Bool, "E.5 S latch");
    if (has_r_) r_latch_ = g_.local(E_ + "_R_LATCH", Type::Bool, "E.5 R latch");
    const Expr req_s = request(IntersectionType::S), req_r = request(IntersectionType::R);
    if (!reset_request_.empty()) {
      std::vector<Statement> clear;
      if (has_s_) clear.push_back(st::if_(st::not_(req_s), {st::assign(s_latch_, st::boolean(false))}));
      if (has_r_) clear.push_back(st::if_(st::not_(req_r), {st::assign(r_latch_, st::boolean(false))}));
      emit(st::if_(st::and_(st::var(reset_request_), st::not_(delay_running_prev())), std::move(clear),
                   "E.4 [13.2.2]: a reset clears a latch only once its request is gone and no output delay "
                   "runs."));
    }
    if (has_s_) emit(st::if_(req_s, {st::assign(s_latch_, st::boolean(true))}, "E.5 latches."));
    if (has_r_)
      emit(st::if_(req_r, {st::assign(r_latch_, st::boolean(true))}, has_s_ ? std::string() : "E.5 latches."));
    if (has_r_ && override_possible_)
      emit(st::if_(st::all({st::var(was_running_), st::var(req_r_prev_), st::not_(req_r)}),
                   {st::assign(r_latch_, st::boolean(false))},
                   "E.5 [13.2.1]: no reset is needed when the R request falls during an override."));
  }

  // E.6 active.
  void assign_active() {
    const Expr latch_s = s_latch_.empty() ? st::boolean(false) : st::var(s_latch_);
    const Expr latch_r = r_latch_.empty() ? st::boolean(false) : st::var(r_latch_);
    const Expr not_overridden = running_.empty() ? st::boolean(true) : st::not_(st::var(running_));
    emit(st::assign(
        E_,
        st::and_(st::any({request(IntersectionType::N), latch_s,
                          st::and_(st::or_(request(IntersectionType::V), latch_r), not_overridden)}),
                 st::not_(bypassed())),
        section_ + (section_.empty() ? "" : " ") + "E.6 active [3.4, 6.4.4]" +
            (hard_bypass_ ? ", bypassed by " + *e_.bypass_tag : std::string()) + "."));
    section_.clear();
  }

  // E.7 output delay: the state that drives the outputs.
  void run_output_delay() {
    output_state_ = st::var(E_);
    if (e_.output_delay_ms <= 0) return;
    const std::string t = g_.timer(E_ + "_OUTPUT_DELAY", plc::StandardBlock::Ton, "E.7 output delay");
    const std::string state = g_.local(E_ + "_OUTPUT_STATE", Type::Bool, "E.7 the delayed active state driving the outputs");
    emit(st::call(t, {{plc::Pin::In, st::var(E_)}, {plc::Pin::Pt, g_.preset(e_.output_delay_ms, label_)}},
                  "E.7 output delay [6.4.5, 13.2.4]: the outputs follow once the effect has been active for " +
                      std::to_string(g_.scans(e_.output_delay_ms, label_)) +
                      " scans, at once in scan 1 after start-up."));
    emit(st::assign(state, st::and_(st::var(E_), st::any({st::var(state), st::var(g_.first_scan),
                                                           st::member(t, plc::Pin::Q)}))));
    if (!delay_running_.empty()) emit(st::assign(delay_running_, st::and_(st::var(E_), st::not_(st::var(state)))));
    output_state_ = st::var(state);
  }

  // E.8, E.9 outputs: one statement per output tag.
  void assign_outputs() {
    const auto& pd = e_.process_data;
    const bool pass = pd && pd->tag && !pd->tag->empty() && pd->pass_through;
    const bool mask = pd && pd->tag && !pd->tag->empty() && pd->mask_tag && !pd->mask_tag->empty();
    const Expr p = pass || mask ? g_.tag_bool(*pd->tag) : st::boolean(false);
    const Expr mk = mask ? g_.tag_bool(*pd->mask_tag) : st::boolean(false);
    const Expr& os = output_state_;
    for (std::size_t j = 0; j < e_.tags.size(); ++j) {
      const bool ett = e_.tags[j].ett;
      const Expr logic = ett ? os : st::not_(os);
      const Expr process = ett ? st::not_(p) : p;
      Expr value;
      std::string how;
      if (pass && mask) {
        value = ett ? st::or_(st::and_(os, st::not_(mk)), process)
                    : st::and_(st::not_(st::and_(os, st::not_(mk))), process);
        how = "pass-through of " + *pd->tag + " while not tripped, masked by " + *pd->mask_tag;
      } else if (pass) {
        value = ett ? st::or_(os, process) : st::and_(st::not_(os), process);
        how = "pass-through of " + *pd->tag + " while not tripped";
      } else if (mask) {
        value = st::or_(st::and_(mk, process), st::and_(st::not_(mk), logic));
        how = "masked by " + *pd->mask_tag + ": then the process value " + *pd->tag;
      } else {
        value = logic;
      }
      emit(st::assign(g_.output_var.at({e_.id, static_cast<int>(j + 1)}), std::move(value),
                      "E.9 output tag " + std::to_string(j + 1) + " " + e_.tags[j].name +
                          (ett ? " (ETT: TRUE when tripped)" : " (DTT: FALSE when tripped)") +
                          (how.empty() ? std::string() : ", " + how) + " [6.4.4, 6.4.5, 13.2.5]."));
    }
  }

  Generator& g_;
  const model::Effect& e_;
  const std::string E_, label_;
  std::string section_;  // the block's heading, put on its first statement

  std::vector<Link> links_;
  bool has_xoon_ = false, has_s_ = false, has_r_ = false, override_possible_ = false, hard_bypass_ = false;
  int xoon_x_ = 0;
  IntersectionType xoon_type_ = IntersectionType::N;

  std::string delay_running_, running_, was_running_, req_r_prev_, scans_var_, reset_edge_, reset_request_;
  std::string s_latch_, r_latch_;
  std::map<IntersectionType, Expr> req_;
  std::vector<Statement> start_;
  Expr output_state_;
};

}  // namespace

void Generator::effect(const model::Effect& e) { EffectWriter(*this, e).write(); }

}  // namespace cemv::plc_export
