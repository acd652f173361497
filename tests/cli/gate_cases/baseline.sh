#!/usr/bin/env bash
# baseline.sh CEMV MATRIX PROPS TMP: `cemv check --baseline FILE` fails on
# what changed since an earlier cemv-result/1, not on its known findings:
# the unchanged result passes (exit 0) although it holds findings; a
# property the baseline shows proved and that is now falsified, and a new
# property that fails, are each named (exit 1); a file that is not a
# cemv-result/1 is bad input (exit 2).
set -u
cemv=$1 matrix=$2 props=$3 tmp=$4
mkdir -p "$tmp"
"$cemv" check "$matrix" "$props" --format json -o "$tmp/base.json" -q 2>/dev/null; rc=$?
[ $rc = 1 ] || { echo "baseline run: exit $rc, expected 1 (it has findings)"; exit 1; }
out=$("$cemv" check "$matrix" "$props" --baseline "$tmp/base.json" 2>&1); rc=$?
[ $rc = 0 ] || { echo "$out"; echo "same result against its baseline: exit $rc"; exit 1; }
echo "$out" | grep -q "cemv check --baseline: 5 of 5 properties as expected (3 known findings expected)" ||
  { echo "$out"; echo "no summary"; exit 1; }
# The baseline as if d.falsified_close had been proved, and without d.vacuous_when.
python3 - "$tmp/base.json" "$tmp/changed.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
for p in j["properties"]:
    if p["name"] == "d.falsified_close":
        p["verdict"] = "proved"
j["properties"] = [p for p in j["properties"] if p["name"] != "d.vacuous_when"]
json.dump(j, open(sys.argv[2], "w"))
PY
out=$("$cemv" check "$matrix" "$props" --baseline "$tmp/changed.json" 2>&1); rc=$?
[ $rc = 1 ] || { echo "$out"; echo "changed verdicts: exit $rc, expected 1"; exit 1; }
echo "$out" | grep -q "error: property 'd.falsified_close' falsified at cycle 3 (found by bmc), expected proved (baseline $tmp/changed.json)" ||
  { echo "$out"; echo "the changed verdict is not named"; exit 1; }
echo "$out" | grep -q "not as expected: d.falsified_close (falsified, expected proved), d.vacuous_when (vacuous, expected proved or reachable)" ||
  { echo "$out"; echo "the summary does not name both"; exit 1; }
# -q: the lines of the two, and the known finding as a note.
out=$("$cemv" check "$matrix" "$props" --baseline "$tmp/changed.json" -q 2>&1); rc=$?
[ $rc = 1 ] && [ "$(echo "$out" | grep -c ': error: ')" = 2 ] && [ "$(echo "$out" | grep -c ': note: .*(as expected)')" = 1 ] ||
  { echo "$out"; echo "-q: exit $rc, expected 2 errors and 1 note"; exit 1; }
echo '{"format": "cemv-scenario/1"}' > "$tmp/not_a_result.json"
out=$("$cemv" check "$matrix" "$props" --baseline "$tmp/not_a_result.json" 2>&1); rc=$?
[ $rc = 2 ] && echo "$out" | grep -q "not_a_result.json: error: not a cemv-result/1 file" ||
  { echo "$out"; echo "a bad baseline: exit $rc, expected 2"; exit 1; }
echo "baseline gates on changes"
