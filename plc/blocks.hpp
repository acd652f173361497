// The standard function blocks of the subset executed on the scan's time base
// (docs/plc.md P.6): one state per instance, one `execute` per call. The
// interpreter's own implementation; the SMT encoding writes the same rules
// again from the document.
#pragma once

#include <cstdint>

#include "plc/ast.hpp"

namespace cemv::plc {

struct BlockState {
  StandardBlock kind = StandardBlock::Ton;
  // inputs: IN, PT (timers); CLK (edges); S1/S and R/R1 (bistables: `set`, `reset`)
  bool in = false;
  std::int64_t pt = 0;  // milliseconds
  bool set = false, reset = false;
  // outputs: Q (timers, edges) or Q1 (bistables), ET (timers)
  bool q = false;
  std::int64_t et = 0;
  // internal: the timers' state (0 idle, 1 timing, 2 elapsed), the previous
  // IN and the start time; the edge detectors' memory M
  int state = 0;
  bool prev_in = false;
  std::int64_t start = 0;
  bool m = false;
};

// One call at time `now` (milliseconds on the scan time base, P.8), the
// inputs already set.
void execute(BlockState& b, std::int64_t now);

// A pin's value as a Literal (BOOL or TIME), and setting an input pin.
Literal pin_value(const BlockState& b, Pin p);
void set_pin(BlockState& b, Pin p, const Literal& v);

}  // namespace cemv::plc
