#!/usr/bin/env bash
# capped.sh CEMV TMPDIR: a scenario with 60 unknown tags prints the "another
# matrix" line, 20 issues, then one "... and N more" line.
set -u
cemv=$1 tmp=$2
mkdir -p "$tmp"
{ printf '{"format": "cemv-scenario/1", "steps": ['
  for i in $(seq 1 60); do printf '%s{"inputs": {"NO_SUCH_%d": true}}' "$([ "$i" = 1 ] || echo ,)" "$i"; done
  printf ']}\n'; } > "$tmp/many.json"
err=$("$cemv" simulate tests/scenarios/matrices/ch13_causes.json "$tmp/many.json" 2>&1); rc=$?
[ $rc = 2 ] || { echo "exit $rc"; exit 1; }
echo "$err"
lines=$(echo "$err" | wc -l)
[ "$lines" = 21 ] || { echo "$lines lines"; exit 1; }
echo "$err" | head -1 | grep -q "none of the scenario's 60 tags is in matrix CH13_CAUSES" || exit 1
echo "$err" | tail -1 | grep -qx "$tmp/many.json: \.\.\. and 41 more" || exit 1
echo "capped at 20 and 1 line"
