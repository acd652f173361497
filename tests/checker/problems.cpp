#include "tests/checker/problems.hpp"

#include "formats/matrix_json.hpp"

namespace cemv::checker::fixtures {

namespace {

template <class T>
OwnedProblem own(std::shared_ptr<T> owner, const encoder::TransitionSystem& ts, z3::expr good) {
  return OwnedProblem{owner, SafetyProblem{&ts, good, ts.ctx().bool_val(true)}};
}

}  // namespace

NamedProblem saturating_counter(int limit, int bound) {
  NamedProblem p;
  p.name = "counter_" + std::to_string(limit) + "_le_" + std::to_string(bound);
  p.expected = bound >= limit ? Verdict::Proved : Verdict::Falsified;
  p.cex_length = bound + 2;  // x reaches bound + 1 at the start of cycle bound + 1
  p.make = [limit, bound](z3::context& ctx) {
    auto ts = std::make_shared<encoder::TransitionSystem>(ctx);
    z3::expr x = ts->make_statevar("x", ctx.int_sort());
    z3::expr go = ts->make_inputvar("go", ctx.bool_sort());
    ts->set_init(x, ctx.int_val(0));
    ts->assign_next(x, z3::ite(go, z3::ite(x >= limit, ctx.int_val(limit), x + 1), ctx.int_val(0)));
    ts->add_lemma("x.range", x >= 0 && x <= limit);
    return own(ts, *ts, x <= bound);
  };
  return p;
}

NamedProblem twin_counters() {
  NamedProblem p;
  p.name = "twin_counters";
  p.expected = Verdict::Proved;
  p.make = [](z3::context& ctx) {
    auto ts = std::make_shared<encoder::TransitionSystem>(ctx);
    z3::expr x = ts->make_statevar("x", ctx.int_sort());
    z3::expr y = ts->make_statevar("y", ctx.int_sort());
    z3::expr go = ts->make_inputvar("go", ctx.bool_sort());
    ts->set_init(x, ctx.int_val(0));
    ts->set_init(y, ctx.int_val(5));
    ts->assign_next(x, z3::ite(go, x + 1, x));
    ts->assign_next(y, z3::ite(go, y + 1, y));
    return own(ts, *ts, y - x >= 5);
  };
  return p;
}

NamedProblem guarded_counter(int bound) {
  NamedProblem p;
  p.name = "guarded_counter_le_" + std::to_string(bound);
  p.expected = bound >= 3 ? Verdict::Proved : Verdict::Falsified;
  p.cex_length = bound + 2;
  p.make = [](z3::context& ctx) {
    auto ts = std::make_shared<encoder::TransitionSystem>(ctx);
    z3::expr flag = ts->make_statevar("flag", ctx.bool_sort());
    z3::expr x = ts->make_statevar("x", ctx.int_sort());
    z3::expr start = ts->make_inputvar("start", ctx.bool_sort());
    ts->set_init(flag, ctx.bool_val(false));
    ts->set_init(x, ctx.int_val(0));
    // Starting (when not running) sets the flag; at x = 3 the flag clears.
    z3::expr running = z3::ite(flag, x < 3, start);
    ts->assign_next(flag, running);
    ts->assign_next(x, z3::ite(running, x + 1, ctx.int_val(0)));
    return own(ts, *ts, x <= 3);
  };
  if (bound != 3) {
    p.make = [inner = p.make, bound](z3::context& ctx) {
      OwnedProblem o = inner(ctx);
      z3::expr x = *o.problem.ts->statevar("x");
      o.problem.good = x <= bound;
      return o;
    };
  }
  return p;
}

NamedProblem lasso() {
  NamedProblem p;
  p.name = "lasso";
  p.expected = Verdict::Proved;
  p.make = [](z3::context& ctx) {
    auto ts = std::make_shared<encoder::TransitionSystem>(ctx);
    z3::expr s = ts->make_statevar("s", ctx.int_sort());
    z3::expr go = ts->make_inputvar("go", ctx.bool_sort());
    ts->set_init(s, ctx.int_val(0));
    z3::expr from3 = z3::ite(go, ctx.int_val(4), ctx.int_val(3));
    ts->assign_next(s, z3::ite(s == 0, ctx.int_val(1), z3::ite(s == 3, from3, s)));
    return own(ts, *ts, s != 4);
  };
  return p;
}

NamedProblem edge_counter() {
  NamedProblem p;
  p.name = "edge_counter";
  p.expected = Verdict::Falsified;
  p.cex_length = 10002;
  p.make = [](z3::context& ctx) {
    auto ts = std::make_shared<encoder::TransitionSystem>(ctx);
    z3::expr x = ts->make_statevar("x", ctx.int_sort());
    z3::expr prev = ts->make_statevar("prev", ctx.bool_sort());
    z3::expr go = ts->make_inputvar("go", ctx.bool_sort());
    ts->set_init(x, ctx.int_val(0));
    ts->set_init(prev, ctx.bool_val(false));
    ts->assign_next(x, z3::ite(go && !prev, x + 1, x));
    ts->assign_next(prev, go);
    return own(ts, *ts, x <= 5000);
  };
  return p;
}

std::unique_ptr<encoder::Encoding> encode_example(z3::context& ctx, const std::string& example,
                                                  const std::vector<model::Node>& roots) {
  model::Matrix m = formats::load_matrix(std::string(CEMV_SOURCE_DIR) + "/examples/" + example + "/matrix.json");
  return encoder::encode(ctx, m, roots);
}

NamedProblem example_term(const std::string& example, const std::vector<model::Node>& roots,
                          const std::string& key, bool negate, Verdict expected, int cex_length) {
  NamedProblem p;
  p.name = example + "_" + (negate ? "not_" : "") + key;
  for (char& c : p.name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  p.expected = expected;
  p.cex_length = cex_length;
  p.make = [=](z3::context& ctx) {
    std::shared_ptr<encoder::Encoding> enc = encode_example(ctx, example, roots);
    z3::expr t = *enc->ts.term(key);
    return own(enc, enc->ts, negate ? !t : t);
  };
  return p;
}

NamedProblem override_monitor(int bound, Verdict expected, int cex_length) {
  NamedProblem p;
  p.name = "hipps_override_monitor_le_" + std::to_string(bound);
  p.deep = true;
  p.expected = expected;
  p.cex_length = cex_length;
  p.make = [bound](z3::context& ctx) {
    std::shared_ptr<encoder::Encoding> enc =
        encode_example(ctx, "pipeline-hipps", {model::Node{model::Node::Kind::Effect, 4}});
    auto& ts = enc->ts;
    z3::expr m = ts.make_statevar("monitor.override_held", ctx.int_sort());
    ts.set_init(m, ctx.int_val(0));
    ts.assign_next(m, z3::ite(*ts.term("effect[4].override_active"), m + 1, ctx.int_val(0)));
    return own(enc, ts, m <= bound);
  };
  return p;
}

NamedProblem override_instance_monitor(int bound, Verdict expected, int cex_length) {
  NamedProblem p;
  p.name = "hipps_override_instance_monitor_le_" + std::to_string(bound);
  p.deep = true;
  p.expected = expected;
  p.cex_length = cex_length;
  p.make = [bound](z3::context& ctx) {
    std::shared_ptr<encoder::Encoding> enc =
        encode_example(ctx, "pipeline-hipps", {model::Node{model::Node::Kind::Effect, 4}});
    auto& ts = enc->ts;
    z3::expr toggle = *ts.inputvar("input.HS_310_OVR") && !*ts.statevar("prev.effect[4].reset_tag") &&
                      !*ts.statevar("first_cycle");
    z3::expr m = ts.make_statevar("monitor.override_held", ctx.int_sort());
    ts.set_init(m, ctx.int_val(0));
    z3::expr active = *ts.term("effect[4].override_active");
    ts.assign_next(m, z3::ite(active, z3::ite(toggle, ctx.int_val(1), m + 1), ctx.int_val(0)));
    return own(enc, ts, m <= bound);
  };
  return p;
}

}  // namespace cemv::checker::fixtures
