#!/usr/bin/env bash
# defeats.sh [CEMV [BIG_MATRIX_TOOL]]: `cemv defeats` with the command line's
# defaults (K = 2, --jobs 1, no time limit) on the four examples, then on
# SIF group 1 of the 128 x 128 x 1024 big_matrix with K = 1
# (cemv_big_matrix_json 1: tests/support/random_matrix.hpp), wall and CPU
# time from /usr/bin/time, the load average, and whether each example's sets
# (path, status, distance, sets with their class, method, violation cycle and
# counterexample) are the committed examples/*/defeats.json's. Targets
# (issue 38): the four examples < 30 s in total, big_matrix group 1 < 120 s
# (docs/performance.md, "cemv defeats"). SKIP_BIG=1 leaves big_matrix out.
set -euo pipefail
cd "$(dirname "$0")/.."
cemv=${1:-build/cemv}
gen=${2:-$(dirname "$cemv")/tests/cemv_big_matrix_json}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
same_sets() {
  python3 -c '
import json, sys
def sets(f):
    d = json.load(open(f))
    return [(p["key"], p["status"], p["distance"],
             [(s["actions"], s["class"], s["method"], s["violation_cycle"], s["counterexample"]) for s in p["sets"]])
            for p in d["paths"]]
print("same sets as committed" if sets(sys.argv[1]) == sets(sys.argv[2]) else "SETS DIFFER from committed")
' "$1" "$2"
}
run() {  # NAME MATRIX ARGS...
  local name=$1 matrix=$2
  shift 2
  local rc=0
  /usr/bin/time -f "%e %U %S" -o "$tmp/time" "$cemv" defeats "$matrix" "$@" --format json -o "$tmp/$name.json" \
    2>/dev/null || rc=$?
  read -r wall user sys < "$tmp/time"
  echo "defeats $name $*: ${wall} s wall, $(python3 -c "print(f'{$user + $sys:.1f}')") s CPU, exit $rc," \
       "load $(cut -d' ' -f1-3 /proc/loadavg)"
}
for ex in tank-overfill burner-management pipeline-hipps compressor; do
  run "$ex" "examples/$ex/matrix.json"
  same_sets "$tmp/$ex.json" "examples/$ex/defeats.json"
done
if [ -z "${SKIP_BIG:-}" ]; then
  "$gen" 1 > "$tmp/big.json"
  run big_matrix "$tmp/big.json" --sif 1 --max-size 1
fi
