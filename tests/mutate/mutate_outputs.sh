#!/usr/bin/env bash
# `cemv mutate MATRIX --out DIR --equivalence`: exit 0, every mutant decided,
# mutants.json (cemv-mutants/1) names every file, and each distinguishing
# scenario passes on the original and fails on its mutant.
# usage: mutate_outputs.sh CEMV MATRIX TMPDIR
set -euo pipefail
cemv=$1 matrix=$2 tmp=$3
rm -rf "$tmp"
"$cemv" mutate "$matrix" --out "$tmp" --equivalence --timeout 60 >"$tmp.stdout"
grep -q "undecided 0" "$tmp.stdout" || { cat "$tmp.stdout"; exit 1; }
python3 - "$tmp" <<'PY' >"$tmp.list"
import json, os, sys
d = sys.argv[1]
j = json.load(open(os.path.join(d, "mutants.json")))
assert j["format"] == "cemv-mutants/1"
assert j["mutants"], "no mutants"
for m in j["mutants"]:
    assert os.path.exists(os.path.join(d, m["file"])), m["file"]
    assert m["equivalence"] in ("equivalent", "differs"), m
    if m["equivalence"] == "differs":
        print(m["file"], m["distinguishing"]["scenario"])
PY
[ -s "$tmp.list" ] || { echo "no non-equivalent mutant"; exit 1; }
while read -r mutant scenario; do
  "$cemv" simulate "$matrix" "$tmp/$scenario" >/dev/null || { echo "$scenario fails on the original"; exit 1; }
  rc=0
  "$cemv" simulate "$tmp/$mutant" "$tmp/$scenario" >/dev/null || rc=$?
  [ "$rc" -eq 1 ] || { echo "$scenario on $mutant: exit $rc, expected 1"; exit 1; }
done <"$tmp.list"
# -q prints no summary.
[ -z "$("$cemv" mutate "$matrix" --out "$tmp.q" -q)" ] || { echo "-q printed a summary"; exit 1; }
echo "cemv mutate: $(wc -l <"$tmp.list") killing scenarios replay as expected"
