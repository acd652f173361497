#!/usr/bin/env bash
# trace_memory.sh [CEMV]: resident memory of `cemv simulate` on a 200,000-cycle
# scenario (5.5 hours of a 100 ms plant), as `/usr/bin/time -f %M` reports it
# (peak RSS in KiB), without a trace, with --trace (streamed, cemv-trace/1) and
# with --trace-changes, plus the size of each trace file. Target: the --trace
# run under 100 MB resident, and memory independent of the trace (README,
# "Commands"; docs/scenario.md, "Trace").
#
# The scenario drives examples/pipeline-hipps/matrix.json: every 2,000 cycles
# the pressure rises above the trip limit and falls back, so the observables
# change all along the run.
set -euo pipefail
cd "$(dirname "$0")/.."
cemv=${1:-build/cemv}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
matrix=examples/pipeline-hipps/matrix.json
{
  printf '{"format": "cemv-scenario/1",\n "initial": {"PT_301A": 60.0, "PT_301B": 60.0, "PT_301C": 60.0, "PT_310": 45.0, "FT_311": 800.0},\n "steps": [\n'
  for i in $(seq 1 100); do
    [ "$i" = 1 ] || printf ',\n'
    printf '  {"inputs": {"PT_301A": 90.0, "PT_301B": 90.0}, "cycles": 1000},\n'
    printf '  {"inputs": {"PT_301A": 60.0, "PT_301B": 60.0}, "cycles": 1000}'
  done
  printf '\n ]}\n'
} > "$tmp/long.json"

measure() {  # LABEL ARGS...: prints label, peak RSS and wall time
  local label=$1; shift
  /usr/bin/time -f "%M %e" -o "$tmp/time" "$cemv" simulate "$matrix" "$tmp/long.json" --quiet "$@" || true
  read -r kib seconds < "$tmp/time"
  printf '%-28s %8.1f MB resident  %6.2f s' "$label" "$(echo "$kib / 1024" | bc -l)" "$seconds"
  echo "$kib" > "$tmp/$label.kib"
}
measure "no trace"; echo
measure "--trace" --trace "$tmp/trace.json"
printf '  trace %6.1f MB\n' "$(echo "$(stat -c %s "$tmp/trace.json") / 1048576" | bc -l)"
measure "--trace --trace-changes" --trace "$tmp/changes.json" --trace-changes
printf '  trace %6.1f MB\n' "$(echo "$(stat -c %s "$tmp/changes.json") / 1048576" | bc -l)"
cycles=$(python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["cycles"]))' "$tmp/trace.json")
echo "cycles in the trace: $cycles"
traced=$(cat "$tmp/--trace.kib")
if [ "$traced" -lt $((100 * 1024)) ]; then echo "target met: --trace run under 100 MB resident"
else echo "TARGET MISSED: --trace run uses $((traced / 1024)) MB resident"; exit 1; fi
