#!/usr/bin/env python3
"""No command bounds the wall clock unless the user asks it to (the developers'
guide: budgets are work; the clock bounds only what the user asked it to bound).
Every --timeout / --total-timeout option of every command that --help lists must
default to none: its help shows no default, or `=0`. A default limit in seconds
would make a verdict depend on the machine's load.
usage: no_default_clock.py CEMV"""
import re
import subprocess
import sys

cemv = sys.argv[1]
top = subprocess.run([cemv, "--help"], capture_output=True, text=True).stdout
commands = []
in_commands = False
for line in top.splitlines():
    if line.strip().lower().startswith("subcommands"):
        in_commands = True
        continue
    m = re.match(r"^  ([a-z][a-z0-9-]*)\s", line)
    if in_commands and m:
        commands.append(m.group(1))
if len(commands) < 10:
    sys.exit(f"found only {len(commands)} commands in `cemv --help`:\n{top}")

checked = 0
bad = []
for c in commands:
    text = subprocess.run([cemv, c, "--help"], capture_output=True, text=True).stdout
    for m in re.finditer(r"(--(?:total-)?timeout)\s+S(=(\S+))?", text):
        checked += 1
        default = m.group(3)
        if default is not None and float(default) != 0:
            bad.append(f"cemv {c} {m.group(1)} defaults to {default} s")
if bad:
    sys.exit("\n".join(bad))
if checked < 10:
    sys.exit(f"only {checked} time limits found: the help format changed?")
print(f"no command bounds the wall clock by default: {checked} time limits of {len(commands)} commands checked")
