#!/usr/bin/env bash
# plc_check.sh [CEMV] [SIZE...]: `cemv plc-check` with the command line's
# defaults (--relation equal, --jobs 1, no time limit) on the tank example's
# program written by hand and its three copies with a seeded hand-coding error
# (examples/tank-overfill/plc), then on the program `cemv export-st` generates
# from big_matrix of each SIZE given (`cemv_matrix_json SIZE`; none by default,
# 128 is issue 39's 128 x 128 x 1024), wall and CPU time from /usr/bin/time,
# the exit status and the verdicts. Targets (issue 39): the correct program
# proved equal on every output in under 5 s, each faulty copy refuted in under
# 1 s, the 128 x 128 generated program proved in under 120 s
# (docs/performance.md, "PLC check").
set -euo pipefail
cd "$(dirname "$0")/.."
cemv=${1:-build/cemv}
shift || true
matrix_json=$(dirname "$cemv")/tests/support/cemv_matrix_json
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
dir=examples/tank-overfill
declare -A target=([tank_t100]=5 [tank_t100_reset_dominant]=1 [tank_t100_off_delay]=1 [tank_t100_one_of_three]=1)
declare -A expect=([tank_t100]=0 [tank_t100_reset_dominant]=1 [tank_t100_off_delay]=1 [tank_t100_one_of_three]=1)
for p in tank_t100 tank_t100_reset_dominant tank_t100_off_delay tank_t100_one_of_three; do
  rc=0
  /usr/bin/time -f "%e %U %S %M" -o "$tmp/time" "$cemv" plc-check "$dir/matrix.json" "$dir/plc/$p.st" \
    --map "$dir/plc/tank_t100.map.json" --format json -o "$tmp/r.json" 2>/dev/null || rc=$?
  read -r wall user sys rss < <(tail -n 1 "$tmp/time")  # after "Command exited with non-zero status"
  verdicts=$(python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))
print(", ".join(o["tag"] + " " + o["verdict"] + " (" + o.get("method", "") + ")" for o in r["outputs"]))
' "$tmp/r.json")
  cpu=$(python3 -c "print(f'{$user + $sys:.2f}')")
  echo "plc-check $p.st: ${wall} s wall, ${cpu} s CPU, $((rss / 1024)) MiB peak, exit $rc (expected ${expect[$p]});" \
       "$verdicts; target < ${target[$p]} s"
done
for n in "$@"; do
  "$matrix_json" "$n" > "$tmp/m$n.json"
  "$cemv" export-st "$tmp/m$n.json" -o "$tmp/P$n.st"
  rc=0
  /usr/bin/time -f "%e %U %S %M" -o "$tmp/time" "$cemv" plc-check "$tmp/m$n.json" "$tmp/P$n.st" \
    --map "$tmp/P$n.map.json" --format json -o "$tmp/r.json" 2>/dev/null || rc=$?
  read -r wall user sys rss < <(tail -n 1 "$tmp/time")
  verdicts=$(python3 -c '
import collections, json, sys
r = json.load(open(sys.argv[1]))
c = collections.Counter(o["verdict"] + " (" + o.get("method", "") + ")" for o in r["outputs"])
print(", ".join(f"{n} {v}" for v, n in sorted(c.items())))
' "$tmp/r.json")
  cpu=$(python3 -c "print(f'{$user + $sys:.2f}')")
  echo "plc-check export-st of big_matrix $n: ${wall} s wall, ${cpu} s CPU, $((rss / 1024)) MiB peak, exit $rc" \
       "(expected 0); $verdicts; target for 128: < 120 s"
done
