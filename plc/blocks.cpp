#include "plc/blocks.hpp"

namespace cemv::plc {

namespace {

// P.6.1: TON. A rising edge of IN starts timing (Q stays FALSE in that call);
// in a later call with IN still TRUE, Q becomes TRUE once PT has elapsed since
// the start; IN FALSE clears Q and ET.
void on_delay(BlockState& b, std::int64_t now) {
  if (b.state == 0 && !b.prev_in && b.in) {
    b.state = 1;
    b.q = false;
    b.start = now;
  } else if (!b.in) {
    b.et = 0;
    b.q = false;
    b.state = 0;
  } else if (b.state == 1) {
    if (b.start + b.pt <= now) {
      b.state = 2;
      b.q = true;
      b.et = b.pt;
    } else {
      b.et = now - b.start;
    }
  }
  b.prev_in = b.in;
}

// P.6.2: TOF. A falling edge of IN starts timing; Q is IN or timing.
void off_delay(BlockState& b, std::int64_t now) {
  if (b.state == 0 && b.prev_in && !b.in) {
    b.state = 1;
    b.start = now;
  } else if (b.in) {
    b.et = 0;
    b.state = 0;
  } else if (b.state == 1) {
    if (b.start + b.pt <= now) {
      b.state = 2;
      b.et = b.pt;
    } else {
      b.et = now - b.start;
    }
  }
  b.q = b.in || b.state == 1;
  b.prev_in = b.in;
}

// P.6.3: TP. A rising edge of IN while idle starts a pulse of length PT that
// nothing retriggers or cuts short; it re-arms once elapsed with IN FALSE.
void pulse(BlockState& b, std::int64_t now) {
  if (b.state == 0 && !b.prev_in && b.in) {
    b.state = 1;
    b.q = true;
    b.start = now;
  } else if (b.state == 1) {
    if (b.start + b.pt <= now) {
      b.state = 2;
      b.q = false;
      b.et = b.pt;
    } else {
      b.et = now - b.start;
    }
  }
  if (b.state == 2 && !b.in) {
    b.et = 0;
    b.state = 0;
  }
  b.prev_in = b.in;
}

}  // namespace

void execute(BlockState& b, std::int64_t now) {
  switch (b.kind) {
    case StandardBlock::Ton: return on_delay(b, now);
    case StandardBlock::Tof: return off_delay(b, now);
    case StandardBlock::Tp: return pulse(b, now);
    case StandardBlock::RTrig:  // P.6.4
      b.q = b.in && !b.m;
      b.m = b.in;
      return;
    case StandardBlock::FTrig:  // P.6.5
      b.q = !b.in && !b.m;
      b.m = !b.in;
      return;
    case StandardBlock::Sr:  // P.6.6: set dominant
      b.q = b.set || (!b.reset && b.q);
      return;
    case StandardBlock::Rs:  // P.6.7: reset dominant
      b.q = !b.reset && (b.set || b.q);
      return;
  }
}

Literal pin_value(const BlockState& b, Pin p) {
  switch (p) {
    case Pin::Pt: return Literal{Type::Time, b.pt, 0};
    case Pin::Et: return Literal{Type::Time, b.et, 0};
    case Pin::In:
    case Pin::Clk: return Literal{Type::Bool, b.in, 0};
    case Pin::S1:
    case Pin::S: return Literal{Type::Bool, b.set, 0};
    case Pin::R:
    case Pin::R1: return Literal{Type::Bool, b.reset, 0};
    case Pin::Q:
    case Pin::Q1: return Literal{Type::Bool, b.q, 0};
  }
  return {};
}

void set_pin(BlockState& b, Pin p, const Literal& v) {
  switch (p) {
    case Pin::Pt: b.pt = v.integer; return;
    case Pin::In:
    case Pin::Clk: b.in = v.integer != 0; return;
    case Pin::S1:
    case Pin::S: b.set = v.integer != 0; return;
    case Pin::R:
    case Pin::R1: b.reset = v.integer != 0; return;
    default: return;  // outputs are not set from outside
  }
}

}  // namespace cemv::plc
