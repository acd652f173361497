// The standard function blocks (docs/plc.md "Standard blocks"): edges,
// bistables and the timers TON, TOF, TP as the state machines of the IEC
// 61131-3 reference code, with the elapsed time counted on the scan's time
// base: a timer started in scan s has elapsed n * scan_ms in scan s + n.
#include <string>

#include "plc_encoder/symbolic.hpp"

namespace cemv::plc_encoder {

namespace {

// env[k] := ite(c, v, env[k])
void set_if(Env& env, const z3::expr& c, const std::string& k, const z3::expr& v) {
  z3::expr& old = env.at(k);
  old = z3::ite(c, v, old);
}

}  // namespace

void Scan::standard_block(plc::StandardBlock b, const std::string& k, plc::Position at_pos, Env& env) {
  auto pin = [&](const char* p) -> z3::expr& { return at(env, k + "." + p, at_pos); };
  switch (b) {
    case plc::StandardBlock::RTrig: {
      const z3::expr clk = pin("CLK");
      pin("Q") = clk && !pin("#M");
      pin("#M") = clk;
      return;
    }
    case plc::StandardBlock::FTrig: {
      const z3::expr clk = pin("CLK");
      pin("Q") = !clk && !pin("#M");
      pin("#M") = !clk;
      return;
    }
    case plc::StandardBlock::Sr: pin("Q1") = pin("S1") || (!pin("R") && pin("Q1")); return;
    case plc::StandardBlock::Rs: pin("Q1") = !pin("R1") && (pin("S") || pin("Q1")); return;
    case plc::StandardBlock::Ton:
    case plc::StandardBlock::Tof:
    case plc::StandardBlock::Tp:
      if (conditional_ > 0)
        throw Unsupported(at_pos, "timer " + k + " called inside IF, CASE or FOR: the encoding counts a timer's "
                                  "time once per scan, so a timer is called exactly once in every scan, outside "
                                  "any branch or loop");
      if (++timer_calls_[k] > 1)
        throw Unsupported(at_pos, "timer " + k + " called twice in one scan: a timer is called exactly once in every scan");
      timer(b, k, env);
      return;
  }
}

// The states of the reference code: idle (neither flag), running, done.
void Scan::timer(plc::StandardBlock b, const std::string& k, Env& env) {
  auto pin = [&](const char* p) -> z3::expr& { return env.at(k + "." + p); };
  const z3::expr in = pin("IN");
  const z3::expr pt = pin("PT");
  const z3::expr prev = pin("#PREV");
  const z3::expr run = pin("#RUN");
  const z3::expr done = pin("#DONE");
  const z3::expr e = pin("#E");
  const z3::expr f = ctx_.bool_val(false), t = ctx_.bool_val(true);
  const z3::expr zero = ctx_.bv_val(0, 32);
  // Elapsed after this scan, compared in 64 bits so that no sum wraps.
  const z3::expr e_next = e + ctx_.bv_val(static_cast<std::int64_t>(scan_ms_), 32);
  const z3::expr expired = z3::sle(z3::sext(pt, 32), z3::sext(e, 32) + ctx_.bv_val(static_cast<std::int64_t>(scan_ms_), 64));
  const z3::expr idle = !run && !done;
  switch (b) {
    case plc::StandardBlock::Ton: {
      const z3::expr start = idle && !prev && in;
      const z3::expr stop = !start && !in;
      const z3::expr tick = !start && in && run;
      set_if(env, start, k + ".#RUN", t);
      set_if(env, start, k + ".#DONE", f);
      set_if(env, start, k + ".Q", f);
      set_if(env, start, k + ".#E", zero);
      set_if(env, stop, k + ".ET", zero);
      set_if(env, stop, k + ".Q", f);
      set_if(env, stop, k + ".#RUN", f);
      set_if(env, stop, k + ".#DONE", f);
      set_if(env, tick, k + ".#E", e_next);
      set_if(env, tick && expired, k + ".#RUN", f);
      set_if(env, tick && expired, k + ".#DONE", t);
      set_if(env, tick && expired, k + ".Q", t);
      set_if(env, tick, k + ".ET", z3::ite(expired, pt, e_next));
      break;
    }
    case plc::StandardBlock::Tof: {
      const z3::expr start = idle && prev && !in;
      const z3::expr stop = !start && in;
      const z3::expr tick = !start && !in && run;
      set_if(env, start, k + ".#RUN", t);
      set_if(env, start, k + ".#E", zero);
      set_if(env, stop, k + ".ET", zero);
      set_if(env, stop, k + ".#RUN", f);
      set_if(env, stop, k + ".#DONE", f);
      set_if(env, tick, k + ".#E", e_next);
      set_if(env, tick && expired, k + ".#RUN", f);
      set_if(env, tick && expired, k + ".#DONE", t);
      set_if(env, tick, k + ".ET", z3::ite(expired, pt, e_next));
      pin("Q") = in || pin("#RUN");
      break;
    }
    case plc::StandardBlock::Tp: {
      const z3::expr start = idle && !prev && in;
      const z3::expr tick = !start && run;
      set_if(env, start, k + ".#RUN", t);
      set_if(env, start, k + ".Q", t);
      set_if(env, start, k + ".#E", zero);
      set_if(env, tick, k + ".#E", e_next);
      set_if(env, tick && expired, k + ".#RUN", f);
      set_if(env, tick && expired, k + ".#DONE", t);
      set_if(env, tick && expired, k + ".Q", f);
      set_if(env, tick, k + ".ET", z3::ite(expired, pt, e_next));
      const z3::expr rearm = pin("#DONE") && !in;
      set_if(env, rearm, k + ".ET", zero);
      set_if(env, rearm, k + ".#DONE", f);
      break;
    }
    default: break;
  }
  pin("#PREV") = in;
}

}  // namespace cemv::plc_encoder
