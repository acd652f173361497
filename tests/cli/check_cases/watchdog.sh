#!/usr/bin/env bash
# watchdog.sh CEMV MATRIX PROPS TMPDIR: a checker that only its cancel token ends is ended
# by --total-timeout on time; the JSON report is complete and valid, says
# `interrupted`, keeps the verdicts already found and reports the rest unknown
# with reason "time limit"; the exit status is that of those verdicts.
set -u
cemv=$1 matrix=$2 props=$3 tmp=$4
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$tmp" && rm -f "$tmp/w.json"
start=$(date +%s%N)
timeout 20 "$cemv" check "$matrix" "$props" --format json -o "$tmp/w.json" --total-timeout 1; rc=$?
ms=$(( ($(date +%s%N) - start) / 1000000 ))
echo "exit $rc after $ms ms"
[ $rc -eq 1 ] || { echo "exit $rc, expected 1 (a property was falsified before the limit)"; exit 1; }
[ $ms -lt 3000 ] || { echo "took $ms ms with --total-timeout 1"; exit 1; }
python3 "$here/../reports/validate_outputs.py" json "$tmp/w.json" 4 || exit 1
python3 - "$tmp/w.json" <<'PY' || exit 1
import json, sys
j = json.load(open(sys.argv[1]))
got = [(p["name"], p["verdict"], p["reason"]) for p in j["properties"]]
want = [("h.ok", "proved", None), ("h.falsified_close", "falsified", None),
        ("h.hang", "unknown", "time limit"), ("h.after", "unknown", "time limit")]
assert j["interrupted"] is True, "interrupted is not true"
assert got == want, got
print("interrupted report:", got)
PY
