// Section C of docs/semantics.md as statements: one block of the body per
// processed cause, in the evaluation order. Soft bypasses are not in the
// program (the map declares them unused), so a tag is taken out of the voting
// only for bad quality (C.3).
#include <algorithm>

#include "model/text.hpp"
#include "plc_export/export.hpp"
#include "plc_export/generator.hpp"
#include "plc_export/st_build.hpp"

namespace cemv::plc_export {

namespace {

using plc::BinaryOp;
using plc::Expr;
using plc::Statement;
using plc::Type;

int configured_x(const model::Cause& c) {
  switch (c.function) {
    case model::CauseFunction::And: return static_cast<int>(c.tags.size());
    case model::CauseFunction::TwoOoThree: return 2;
    default: return 1;
  }
}

const char* function_text(const model::Cause& c) {
  switch (c.function) {
    case model::CauseFunction::And: return "AND";
    case model::CauseFunction::Or: return "OR";
    case model::CauseFunction::TwoOoThree: return "2oo3";
    default: return "normal";
  }
}

// At least x of the terms TRUE, as Boolean operators.
Expr at_least(int x, const std::vector<Expr>& terms) {
  const int n = static_cast<int>(terms.size());
  if (x <= 1) return st::any(terms);
  if (x >= n) return st::all(terms);
  // 2 of 3, the only other case of C.4
  return st::any({st::and_(terms[0], terms[1]), st::and_(terms[0], terms[2]), st::and_(terms[1], terms[2])});
}


std::string quality_text(model::BadQuality q) {
  switch (q) {
    case model::BadQuality::Trip: return "a tag of bad quality trips";
    case model::BadQuality::Degrade: return "a tag of bad quality is taken out of the voting (degraded voting, 6.1.6)";
    default: return "quality is ignored";
  }
}

// Writes one cause's block of the body, step by step of section C; the order
// of the steps is the order of the statements and declarations.
class CauseWriter {
 public:
  CauseWriter(Generator& g, const model::Cause& c)
      : g_(g), c_(c), N_(g.cause_var.at(c.id)), label_(element_label(c)),
        analog_(c.input == model::InputKind::Analog && c.analog.has_value()) {}

  void write() {
    declare_request();
    compare_tags();
    if (degrade_)
      vote_degraded();
    else
      emit(st::assign(req_, at_least(configured_x(c_), tripped_tags()), vote_comment()));
    run_time_function();
    assign_active();
  }

 private:
  void emit(Statement s) { g_.body.push_back(std::move(s)); }
  int tag_count() const { return static_cast<int>(c_.tags.size()); }

  // C.4: the trip request, kept for the next scan (hysteresis, C.6 edges).
  void declare_request() {
    req_ = g_.local(N_ + "_REQ", Type::Bool, "trip request of " + label_ + " (C.4), kept for the next scan");
    if (c_.time.mode == model::TimeMode::Timed && c_.time.ms > 0) {
      req_prev_ = g_.local(N_ + "_REQ_PREV", Type::Bool, "the trip request of the previous scan (C.6 edges)");
      emit(st::assign(req_prev_, st::var(req_)));
    }
  }

  // C.2, C.3: each tag's trip against the threshold in use (C.4 hysteresis:
  // the relaxed one while the previous scan requested the trip), and its bad
  // quality where the cause reads it.
  void compare_tags() {
    Expr threshold;
    if (analog_) {
      const model::AnalogParams& a = *c_.analog;
      const bool high = a.limit_type == model::LimitType::High;
      const float relaxed = high ? a.limit - a.hysteresis : a.limit + a.hysteresis;
      threshold = relaxed == a.limit ? st::real(a.limit)
                                     : st::sel(st::var(req_), st::real(a.limit), st::real(relaxed), Type::Real);
      threshold_text_ = std::string(high ? "high" : "low") + " limit " + model::float_text(a.limit) +
                        (relaxed == a.limit ? std::string()
                                            : ", hysteresis " + model::float_text(a.hysteresis) + ": " +
                                                  model::float_text(relaxed) + " while the trip is requested");
    }
    for (const auto& t : c_.tags) {
      if (analog_)
        compare_.push_back(st::binary(c_.analog->limit_type == model::LimitType::High ? BinaryOp::Ge : BinaryOp::Le,
                                      g_.tag_real(t.name), threshold, Type::Bool));
      else
        compare_.push_back(t.ett ? g_.tag_bool(t.name) : st::not_(g_.tag_bool(t.name)));
      bad_.push_back(c_.bad_quality == model::BadQuality::Ignore ? st::boolean(false) : g_.tag_bad(t.name));
    }
    degrade_ = c_.bad_quality == model::BadQuality::Degrade &&
               std::any_of(bad_.begin(), bad_.end(), [](const Expr& e) { return !st::is_false(e); });
  }

  std::vector<Expr> tripped_tags() const {
    std::vector<Expr> tripped;
    for (int i = 0; i < tag_count(); ++i)
      tripped.push_back(c_.bad_quality == model::BadQuality::Trip ? st::or_(bad_[i], compare_[i]) : compare_[i]);
    return tripped;
  }

  std::string vote_comment() const {
    std::string tags_text;
    for (const auto& t : c_.tags)
      tags_text += (tags_text.empty() ? "" : ", ") + t.name + (analog_ ? "" : t.ett ? " (ETT)" : " (DTT)");
    return "Cause " + std::to_string(c_.id) + " " + c_.name + (c_.description.empty() ? "" : " (" + c_.description + ")") +
           ": " + function_text(c_) + " of " + tags_text + (analog_ ? ", " + threshold_text_ : std::string()) + "; " +
           quality_text(c_.bad_quality) + " [6.3.1, 6.3.4, 6.3.5, 6.3.6]. Trip request by C.2-C.4.";
  }

  // C.4 degraded voting: X oo N less the k tags taken out is max(1, X - k)
  // oo N - k; every tag taken out requests the trip (appendix B "(1oo1)").
  void vote_degraded() {
    const std::string voting = g_.local(N_ + "_VOTING", Type::Int, "tags of good quality (C.3)");
    const std::string tripped = g_.local(N_ + "_TRIPPED", Type::Int, "of those, tripped (C.3)");
    emit(st::assign(voting, st::integer(0, Type::Int), vote_comment()));
    emit(st::assign(tripped, st::integer(0, Type::Int)));
    auto increment = [](const std::string& v) {
      return st::assign(v, st::binary(BinaryOp::Add, st::var(v, Type::Int), st::integer(1, Type::Int), Type::Int));
    };
    for (int i = 0; i < tag_count(); ++i) {
      std::vector<Statement> counted;
      counted.push_back(increment(voting));
      counted.push_back(st::if_(compare_[i], {increment(tripped)}));
      if (st::is_false(bad_[i])) {
        for (auto& s : counted) emit(std::move(s));
      } else {
        emit(st::if_(st::not_(bad_[i]), std::move(counted)));
      }
    }
    emit(logic_by_good_tags(voting, tripped));
  }

  // C.4: a CASE over the number of tags of good quality, one arm per resulting X.
  Statement logic_by_good_tags(const std::string& voting, const std::string& tripped) const {
    const int n = tag_count(), x = configured_x(c_);
    Statement sw;
    sw.kind = Statement::Kind::Case;
    sw.value = st::var(voting, Type::Int);
    for (int good = n; good >= 1; --good) {
      const int needed = std::max(1, x - (n - good));
      auto arm = std::find_if(sw.arms.begin(), sw.arms.end(), [&](const plc::CaseArm& a) {
        return a.body.front().value.args[1].literal.integer == needed;
      });
      if (arm == sw.arms.end()) {
        plc::CaseArm a;
        a.body.push_back(st::assign(req_, st::binary(BinaryOp::Ge, st::var(tripped, Type::Int),
                                                     st::integer(needed, Type::Int), Type::Bool)));
        sw.arms.push_back(std::move(a));
        arm = sw.arms.end() - 1;
      }
      arm->labels.push_back({good, good});
    }
    sw.has_else = true;
    sw.else_body.push_back(st::assign(req_, st::boolean(true)));
    sw.comment = "C.4: the resulting logic by the number of tags of good quality; none: the trip is requested.";
    return sw;
  }

  // C.6 time function: timed_ is the request after it.
  void run_time_function() {
    timed_ = st::var(req_);
    if (c_.time.mode == model::TimeMode::None) return;
    if (c_.time.ms == 0) {
      if (c_.time.mode == model::TimeMode::Timed) timed_ = st::boolean(false);  // C.6: a zero period is never TRUE
      return;
    }
    if (c_.time.mode == model::TimeMode::OnDelay)
      run_delay(plc::StandardBlock::Ton, "_ON_DELAY", "C.6 on-delay",
                "C.6 on-delay [6.3.6, 13.1.1]: active once the request has held for " +
                    std::to_string(g_.scans(c_.time.ms, label_)) + " scans (P.6.8).");
    else if (c_.time.mode == model::TimeMode::OffDelay)
      run_delay(plc::StandardBlock::Tof, "_OFF_DELAY", "C.6 off-delay",
                "C.6 off-delay [6.3.6, 13.1.1]: stays active " + std::to_string(g_.scans(c_.time.ms, label_)) +
                    " scans after the request ends.");
    else
      run_period();
  }

  void run_delay(plc::StandardBlock block, const char* suffix, const char* declared, const std::string& comment) {
    const std::string t = g_.timer(N_ + suffix, block, declared);
    emit(st::call(t, {{plc::Pin::In, st::var(req_)}, {plc::Pin::Pt, g_.preset(c_.time.ms, label_)}}, comment));
    timed_ = st::member(t, plc::Pin::Q);
  }

  void run_period() {
    const std::int64_t d = g_.scans(c_.time.ms, label_);
    const std::string pulse = g_.local(N_ + "_PULSE", Type::Bool, "C.6 timed: the period runs");
    const std::string count = g_.local(N_ + "_PULSE_SCANS", Type::Dint, "scans since the period started");
    emit(st::if_(
        st::var(pulse),
        {st::assign(count, st::binary(BinaryOp::Add, st::var(count, Type::Dint), st::integer(1), Type::Dint)),
         st::if_(st::binary(BinaryOp::Ge, st::var(count, Type::Dint), st::integer(d), Type::Bool),
                 {st::assign(pulse, st::boolean(false))})},
        "C.6 timed [6.3.6, 13.1.1]: a rising edge of the request starts a period of " + std::to_string(d) +
            " scans, not retriggered while it runs; it ends in its expiry scan, where a new edge may start "
            "the next."));
    emit(st::if_(st::all({st::var(req_), st::not_(st::var(req_prev_)), st::not_(st::var(pulse))}),
                 {st::assign(pulse, st::boolean(true)), st::assign(count, st::integer(0))}));
    timed_ = st::var(pulse);
  }

  // C.7 acknowledgement latch, C.8 active.
  void assign_active() {
    const Expr bypass = c_.bypass_tag && !c_.bypass_tag->empty() ? g_.tag_bool(*c_.bypass_tag) : st::boolean(false);
    const Expr inhibit = c_.inhibit_tag && !c_.inhibit_tag->empty() ? g_.tag_bool(*c_.inhibit_tag) : st::boolean(false);
    Expr latched = st::boolean(false);
    if (auto it = g_.ack_var.find(c_.id); it != g_.ack_var.end()) {
      const std::string latch = g_.local(N_ + "_ACK_LATCH", Type::Bool, "C.7 acknowledgement latch");
      emit(st::if_(st::and_(g_.command(it->second), st::not_(st::var(req_))), {st::assign(latch, st::boolean(false))},
                   "C.7 acknowledgement latch [13.1.2-13.1.4]: cleared by ack_cause once the trip is no "
                   "longer requested, set while the timed result holds and the cause is neither bypassed "
                   "nor inhibited."));
      emit(st::if_(st::all({timed_, st::not_(bypass), st::not_(inhibit)}), {st::assign(latch, st::boolean(true))}));
      latched = st::var(latch);
    }
    std::string c8 = "C.8 active [3.4, 6.3.6]";
    if (!st::is_false(bypass)) c8 += ", bypassed by " + *c_.bypass_tag;
    if (!st::is_false(inhibit)) c8 += ", inhibited by " + *c_.inhibit_tag;
    emit(st::assign(N_, st::all({st::or_(timed_, latched), st::not_(bypass), st::not_(inhibit)}), c8 + "."));
  }

  Generator& g_;
  const model::Cause& c_;
  const std::string N_, label_;
  const bool analog_;
  std::string req_, req_prev_, threshold_text_;
  std::vector<Expr> compare_, bad_;
  bool degrade_ = false;
  Expr timed_;
};

}  // namespace

void Generator::cause(const model::Cause& c) { CauseWriter(*this, c).write(); }

}  // namespace cemv::plc_export
