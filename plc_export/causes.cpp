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

}  // namespace

void Generator::cause(const model::Cause& c) {
  const std::string N = cause_var.at(c.id);
  const std::string label = element_label(c);
  std::vector<Statement> out;
  const bool analog = c.input == model::InputKind::Analog && c.analog.has_value();
  const int n = static_cast<int>(c.tags.size());
  const int x = configured_x(c);

  // C.2, C.3: each tag's trip against the threshold in use (C.4 hysteresis:
  // the relaxed one while the previous scan requested the trip).
  const std::string req = local(N + "_REQ", Type::Bool, "trip request of " + label + " (C.4), kept for the next scan");
  const bool timed = c.time.mode == model::TimeMode::Timed && c.time.ms > 0;
  std::string req_prev;
  if (timed) {
    req_prev = local(N + "_REQ_PREV", Type::Bool, "the trip request of the previous scan (C.6 edges)");
    out.push_back(st::assign(req_prev, st::var(req)));
  }
  Expr threshold;
  std::string threshold_text;
  if (analog) {
    const model::AnalogParams& a = *c.analog;
    const bool high = a.limit_type == model::LimitType::High;
    const float relaxed = high ? a.limit - a.hysteresis : a.limit + a.hysteresis;
    threshold = relaxed == a.limit ? st::real(a.limit) : st::sel(st::var(req), st::real(a.limit), st::real(relaxed), Type::Real);
    threshold_text = std::string(high ? "high" : "low") + " limit " + model::float_text(a.limit) +
                     (relaxed == a.limit ? std::string()
                                         : ", hysteresis " + model::float_text(a.hysteresis) + ": " +
                                               model::float_text(relaxed) + " while the trip is requested");
  }
  std::vector<Expr> compare, bad;
  for (const auto& t : c.tags) {
    Expr cmp;
    if (analog)
      cmp = st::binary(c.analog->limit_type == model::LimitType::High ? BinaryOp::Ge : BinaryOp::Le, tag_real(t.name),
                       threshold, Type::Bool);
    else
      cmp = t.ett ? tag_bool(t.name) : st::not_(tag_bool(t.name));
    compare.push_back(std::move(cmp));
    bad.push_back(c.bad_quality == model::BadQuality::Ignore ? st::boolean(false) : tag_bad(t.name));
  }
  std::string tags_text;
  for (const auto& t : c.tags) tags_text += (tags_text.empty() ? "" : ", ") + t.name + (analog ? "" : t.ett ? " (ETT)" : " (DTT)");
  const std::string vote_comment =
      "Cause " + std::to_string(c.id) + " " + c.name + (c.description.empty() ? "" : " (" + c.description + ")") + ": " +
      function_text(c) + " of " + tags_text + (analog ? ", " + threshold_text : std::string()) + "; " +
      quality_text(c.bad_quality) + " [6.3.1, 6.3.4, 6.3.5, 6.3.6]. Trip request by C.2-C.4.";
  const bool degrade = c.bad_quality == model::BadQuality::Degrade &&
                       std::any_of(bad.begin(), bad.end(), [](const Expr& e) { return !st::is_false(e); });
  if (!degrade) {
    std::vector<Expr> tripped;
    for (int i = 0; i < n; ++i)
      tripped.push_back(c.bad_quality == model::BadQuality::Trip ? st::or_(bad[i], compare[i]) : compare[i]);
    out.push_back(st::assign(req, at_least(x, tripped), vote_comment));
  } else {
    // C.4 degraded voting: X oo N less the k tags taken out is max(1, X - k)
    // oo N - k; every tag taken out requests the trip (appendix B "(1oo1)").
    const std::string voting = local(N + "_VOTING", Type::Int, "tags of good quality (C.3)");
    const std::string tripped = local(N + "_TRIPPED", Type::Int, "of those, tripped (C.3)");
    out.push_back(st::assign(voting, st::integer(0, Type::Int), vote_comment));
    out.push_back(st::assign(tripped, st::integer(0, Type::Int)));
    for (int i = 0; i < n; ++i) {
      std::vector<Statement> counted;
      counted.push_back(st::assign(voting, st::binary(BinaryOp::Add, st::var(voting, Type::Int),
                                                      st::integer(1, Type::Int), Type::Int)));
      counted.push_back(st::if_(compare[i], {st::assign(tripped, st::binary(BinaryOp::Add, st::var(tripped, Type::Int),
                                                                            st::integer(1, Type::Int), Type::Int))}));
      if (st::is_false(bad[i])) {
        for (auto& s : counted) out.push_back(std::move(s));
      } else {
        out.push_back(st::if_(st::not_(bad[i]), std::move(counted)));
      }
    }
    plc::Statement sw;
    sw.kind = Statement::Kind::Case;
    sw.value = st::var(voting, Type::Int);
    for (int m_ = n; m_ >= 1; --m_) {
      const int needed = std::max(1, x - (n - m_));
      auto arm = std::find_if(sw.arms.begin(), sw.arms.end(), [&](const plc::CaseArm& a) {
        return a.body.front().value.args[1].literal.integer == needed;
      });
      if (arm == sw.arms.end()) {
        plc::CaseArm a;
        a.body.push_back(st::assign(req, st::binary(BinaryOp::Ge, st::var(tripped, Type::Int),
                                                    st::integer(needed, Type::Int), Type::Bool)));
        sw.arms.push_back(std::move(a));
        arm = sw.arms.end() - 1;
      }
      arm->labels.push_back({m_, m_});
    }
    sw.has_else = true;
    sw.else_body.push_back(st::assign(req, st::boolean(true)));
    sw.comment = "C.4: the resulting logic by the number of tags of good quality; none: the trip is requested.";
    out.push_back(std::move(sw));
  }

  // C.6 time function.
  Expr tm = st::var(req);
  const std::string element = label;
  switch (c.time.mode) {
    case model::TimeMode::None: break;
    case model::TimeMode::OnDelay:
      if (c.time.ms == 0) break;
      {
        const std::string t = timer(N + "_ON_DELAY", plc::StandardBlock::Ton, "C.6 on-delay");
        out.push_back(st::call(t, {{plc::Pin::In, st::var(req)}, {plc::Pin::Pt, preset(c.time.ms, element)}},
                               "C.6 on-delay [6.3.6, 13.1.1]: active once the request has held for " +
                                   std::to_string(scans(c.time.ms, element)) + " scans (P.6.8)."));
        tm = st::member(t, plc::Pin::Q);
      }
      break;
    case model::TimeMode::OffDelay:
      if (c.time.ms == 0) break;
      {
        const std::string t = timer(N + "_OFF_DELAY", plc::StandardBlock::Tof, "C.6 off-delay");
        out.push_back(st::call(t, {{plc::Pin::In, st::var(req)}, {plc::Pin::Pt, preset(c.time.ms, element)}},
                               "C.6 off-delay [6.3.6, 13.1.1]: stays active " +
                                   std::to_string(scans(c.time.ms, element)) + " scans after the request ends."));
        tm = st::member(t, plc::Pin::Q);
      }
      break;
    case model::TimeMode::Timed:
      if (c.time.ms == 0) {
        tm = st::boolean(false);  // C.6: a zero period is never TRUE
        break;
      }
      {
        const std::int64_t d = scans(c.time.ms, element);
        const std::string pulse = local(N + "_PULSE", Type::Bool, "C.6 timed: the period runs");
        const std::string count = local(N + "_PULSE_SCANS", Type::Dint, "scans since the period started");
        out.push_back(st::if_(
            st::var(pulse),
            {st::assign(count, st::binary(BinaryOp::Add, st::var(count, Type::Dint), st::integer(1), Type::Dint)),
             st::if_(st::binary(BinaryOp::Ge, st::var(count, Type::Dint), st::integer(d), Type::Bool),
                     {st::assign(pulse, st::boolean(false))})},
            "C.6 timed [6.3.6, 13.1.1]: a rising edge of the request starts a period of " + std::to_string(d) +
                " scans, not retriggered while it runs; it ends in its expiry scan, where a new edge may start "
                "the next."));
        out.push_back(st::if_(st::all({st::var(req), st::not_(st::var(req_prev)), st::not_(st::var(pulse))}),
                              {st::assign(pulse, st::boolean(true)), st::assign(count, st::integer(0))}));
        tm = st::var(pulse);
      }
      break;
  }

  // C.7, C.8.
  Expr bypass = c.bypass_tag && !c.bypass_tag->empty() ? tag_bool(*c.bypass_tag) : st::boolean(false);
  Expr inhibit = c.inhibit_tag && !c.inhibit_tag->empty() ? tag_bool(*c.inhibit_tag) : st::boolean(false);
  Expr latched = st::boolean(false);
  if (auto it = ack_var.find(c.id); it != ack_var.end()) {
    const std::string latch = local(N + "_ACK_LATCH", Type::Bool, "C.7 acknowledgement latch");
    out.push_back(st::if_(st::and_(command(it->second), st::not_(st::var(req))), {st::assign(latch, st::boolean(false))},
                          "C.7 acknowledgement latch [13.1.2-13.1.4]: cleared by ack_cause once the trip is no "
                          "longer requested, set while the timed result holds and the cause is neither bypassed "
                          "nor inhibited."));
    out.push_back(st::if_(st::all({tm, st::not_(bypass), st::not_(inhibit)}), {st::assign(latch, st::boolean(true))}));
    latched = st::var(latch);
  }
  std::string c8 = "C.8 active [3.4, 6.3.6]";
  if (!st::is_false(bypass)) c8 += ", bypassed by " + *c.bypass_tag;
  if (!st::is_false(inhibit)) c8 += ", inhibited by " + *c.inhibit_tag;
  out.push_back(st::assign(N, st::all({st::or_(tm, latched), st::not_(bypass), st::not_(inhibit)}), c8 + "."));
  for (auto& s : out) body.push_back(std::move(s));
}

}  // namespace cemv::plc_export
