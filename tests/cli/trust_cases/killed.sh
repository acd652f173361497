#!/usr/bin/env bash
# killed.sh CEMV MATRIX TMPDIR: a `cemv simulate --trace T -o R` run killed
# (SIGKILL) while it writes leaves the previous T and R untouched: the trace
# streams into a temporary file next to T that is renamed only when complete.
# The scenario runs 200,000 cycles so that the kill lands during the run.
set -u
cemv=$1 matrix=$2 tmp=$3
mkdir -p "$tmp"
rm -f "$tmp"/.t.json.* "$tmp"/.r.json.*
printf '{"format": "cemv-scenario/1", "steps": [{"cycles": 200000}]}\n' > "$tmp/long.json"
echo "old trace" > "$tmp/t.json"
echo "old result" > "$tmp/r.json"
"$cemv" simulate "$matrix" "$tmp/long.json" --trace "$tmp/t.json" --format json -o "$tmp/r.json" & pid=$!
# Kill once the temporary trace exists and has grown.
for _ in $(seq 1 300); do
  temp=$(ls "$tmp"/.t.json.cemv-* 2>/dev/null | head -1)
  if [ -n "$temp" ] && [ "$(stat -c %s "$temp" 2>/dev/null || echo 0)" -gt 100000 ]; then break; fi
  sleep 0.02
done
kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
[ -n "${temp:-}" ] || { echo "no temporary trace was seen before the kill"; exit 1; }
[ "$(cat "$tmp/t.json")" = "old trace" ] || { echo "the trace file was changed by a killed run"; exit 1; }
[ "$(cat "$tmp/r.json")" = "old result" ] || { echo "the result file was changed by a killed run"; exit 1; }
rm -f "$tmp"/.t.json.* "$tmp"/.r.json.*
echo "old files intact"
