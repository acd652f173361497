#!/usr/bin/env bash
# check_standard.sh [CEMV [MATRIX_TOOL]]: `cemv check MATRIX --standard` with the
# command line's defaults (--support core, --jobs 1, no time limit) on the
# generated 16 x 16 and 32 x 32 matrices and the 128 x 128 x 1024 big_matrix
# (cemv_matrix_json N: tests/support/random_matrix.hpp, square_matrix), wall
# and CPU time from /usr/bin/time, and the verdicts. Targets (issue 38):
# 16 x 16 < 3 s, 32 x 32 < 10 s, 128 x 128 x 1024 < 60 s (docs/performance.md).
# SIZES="16 32" limits the sizes.
set -euo pipefail
cd "$(dirname "$0")/.."
cemv=${1:-build/cemv}
gen=${2:-$(dirname "$cemv")/tests/support/cemv_matrix_json}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
declare -A target=([16]=3 [32]=10 [128]=60)
for n in ${SIZES:-16 32 128}; do
  "$gen" "$n" > "$tmp/m$n.json"
  rc=0
  /usr/bin/time -f "%e %U %S %M" -o "$tmp/time$n" "$cemv" check "$tmp/m$n.json" --standard --format json \
    -o "$tmp/r$n.json" 2>/dev/null || rc=$?
  read -r wall user sys rss < "$tmp/time$n"
  verdicts=$(python3 -c '
import json, sys, collections
r = json.load(open(sys.argv[1]))
c = collections.Counter(p["verdict"] for p in r["properties"])
print(len(r["properties"]), "properties:", ", ".join(f"{n} {v}" for v, n in sorted(c.items())), "; support", r["support_mode"])
' "$tmp/r$n.json")
  cpu=$(python3 -c "print(f'{$user + $sys:.1f}')")
  echo "check --standard ${n} x ${n}: ${wall} s wall, ${cpu} s CPU, $((rss / 1024)) MiB peak, exit $rc;" \
       "$verdicts; target < ${target[$n]} s"
done
