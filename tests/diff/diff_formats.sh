#!/usr/bin/env bash
# `cemv diff` in every format (text, md, html, json; -o FILE and standard
# output), --out with the distinguishing scenario, and -q. The small pair:
# intersection cause 1 / effect 1 changed from N to S, so effect 1 latches.
# usage: diff_formats.sh CEMV CASES TMPDIR
set -euo pipefail
cemv=$1 cases=$2 tmp=$3
old=$cases/small_old.json new=$cases/small_new.json
rm -rf "$tmp" && mkdir -p "$tmp"
expect1() { local rc=0; "$@" || rc=$?; [ "$rc" -eq 1 ] || { echo "exit $rc, expected 1: $*"; exit 1; }; }
expect1 "$cemv" diff "$old" "$new" >"$tmp/report.txt"
expect1 "$cemv" diff "$old" "$new" --format md -o "$tmp/report.md"
expect1 "$cemv" diff "$old" "$new" --format html -o "$tmp/report.html"
expect1 "$cemv" diff "$old" "$new" --format json --out "$tmp/scenarios" >"$tmp/report.json"
# Both signatures in every header.
for f in report.txt report.md report.html report.json; do
  for sig in $("$cemv" signature "$old") $("$cemv" signature "$new"); do
    grep -q "$sig" "$tmp/$f" || { echo "$f lacks signature $sig"; exit 1; }
  done
done
grep -q "^Retest (manual 12): partial retest" "$tmp/report.txt" || { echo "text: no retest line"; exit 1; }
grep -q "^## Retest (manual 12)" "$tmp/report.md" || { echo "md: no retest section"; exit 1; }
grep -q "| effect\[1\] XV_1 | behaviour changed |" "$tmp/report.md" || { echo "md: effect 1 not changed"; exit 1; }
grep -q "</html>" "$tmp/report.html" || { echo "html: not complete"; exit 1; }
python3 - "$tmp/report.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
assert d["format"] == "cemv-diff/1"
for k in ("old", "new", "exit_code", "verdict", "structural", "semantic", "impact", "retest"):
    assert k in d, k
assert d["exit_code"] == 1
[c] = d["structural"]["changes"]
assert (c["element"], c["change"], c["critical"]) == ("intersection", "changed", True), c
assert c["fields"] == [{"field": "type", "old": "N", "new": "S", "critical": True}], c["fields"]
e1, e2 = d["semantic"]["effects"]
assert e1["verdict"] == "differs" and e2["verdict"] == "equivalent", (e1, e2)
assert e1["distinction"]["scenario"].endswith("effect_1.diff.scenario.json"), e1
assert d["impact"]["effects"] == [1] and d["impact"]["causes"] == [1, 2], d["impact"]
assert d["retest"]["scope"] == "partial"
PY
# The distinguishing scenario expects OLD's value: it passes on OLD, fails on NEW.
scen=$tmp/scenarios/effect_1.diff.scenario.json
"$cemv" simulate "$old" "$scen" >/dev/null || { echo "scenario fails on OLD"; exit 1; }
expect1 "$cemv" simulate "$new" "$scen" >/dev/null
# -q: nothing on standard output for the text report; a file is still written.
out=$(expect1 "$cemv" diff "$old" "$new" -q)
[ -z "$out" ] || { echo "-q printed: $out"; exit 1; }
expect1 "$cemv" diff "$old" "$new" -q --format json -o "$tmp/quiet.json" --out "$tmp/scenarios"
cmp -s "$tmp/quiet.json" "$tmp/report.json" || { echo "-q changed the JSON"; exit 1; }
# Deterministic: the same comparison gives the same bytes.
expect1 "$cemv" diff "$old" "$new" --format md -o "$tmp/again.md"
cmp -s "$tmp/report.md" "$tmp/again.md" || { echo "md not reproducible"; exit 1; }
echo "cemv diff: text, md, html, json, --out, -q"
