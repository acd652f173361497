#!/usr/bin/env python3
"""check_trace_changes.py CEMV MATRIX SCENARIO TMPDIR: the streamed trace is
valid cemv-trace/1; --trace-changes keeps the first and last cycle and
exactly those whose row (everything but cycle, t_ms, step) differs from the
previous cycle's, and says so in its header."""
import json
import subprocess
import sys

cemv, matrix, scenario, tmp = sys.argv[1:5]
full, changes = f"{tmp}/full.json", f"{tmp}/changes.json"
subprocess.run([cemv, "simulate", matrix, scenario, "--trace", full, "-q"], check=True)
subprocess.run([cemv, "simulate", matrix, scenario, "--trace", changes, "--trace-changes", "-q"], check=True)
a, b = json.load(open(full)), json.load(open(changes))
assert "changes_only" not in a and b["changes_only"] is True
cycles = a["cycles"]
row = lambda c: {k: v for k, v in c.items() if k not in ("cycle", "t_ms", "step")}
want = [c for i, c in enumerate(cycles) if i == 0 or i == len(cycles) - 1 or row(c) != row(cycles[i - 1]) or c["commands"]]
assert b["cycles"] == want, (len(b["cycles"]), len(want))
assert len(want) < len(cycles)
print(f"trace-changes ok: {len(want)} of {len(cycles)} cycles")
