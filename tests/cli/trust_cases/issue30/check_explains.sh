#!/usr/bin/env bash
# A counterexample explains itself: in the text report ("why, per step"), in
# cemv-result/1 (`explanation`), and under its timing diagram, whose rows are
# named after their elements. usage: check_explains.sh CEMV MATRIX PROPS TMPDIR
set -uo pipefail
cemv=$1 matrix=$2 props=$3 tmp=$4
mkdir -p "$tmp"
"$cemv" check "$matrix" "$props" --out "$tmp/cex" >"$tmp/check.txt"
[ $? -eq 1 ] || { echo "check: expected exit 1"; exit 1; }
grep -A1 "why, per step (docs/semantics.md):" "$tmp/check.txt" | grep -Eq "^      cycle [0-9]+: " || { echo "no step in the text"; exit 1; }
"$cemv" check "$matrix" "$props" --format json -o "$tmp/check.json"
python3 - "$tmp/check.json" <<'PY' || exit 1
import json, sys
r = json.load(open(sys.argv[1]))
p = next(p for p in r["properties"] if p["name"] == "cli.bypass_keeps_xv101_open")
assert p["verdict"] == "falsified"
steps = p["explanation"]
assert steps and all(set(s) == {"cycle", "signal", "before", "after", "why"} for s in steps), steps
assert any(s["signal"] == "cause[1].bypassed" and s["before"] == "0" and s["after"] == "1" and "(C.8)" in s["why"] for s in steps), steps
proved = next(p for p in r["properties"] if p["verdict"] == "proved")
assert proved["explanation"] == []
PY
svg="$tmp/cex/cli.bypass_keeps_xv101_open.svg"
grep -q '>cause 1 LT100_HH bypassed<' "$svg" || { echo "rows not named"; exit 1; }
grep -q 'Why, per step' "$svg" || { echo "no explanation under the diagram"; exit 1; }
echo "explained in text, JSON and diagram"
