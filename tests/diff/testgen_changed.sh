#!/usr/bin/env bash
# `cemv testgen NEW --changed-from OLD` on the small pair (intersection
# cause 1 / effect 1 changed from N to S): the comparisons agree, so only
# the objectives about effect 1 and its cone (causes 1 and 2) are generated,
# none about effect 2; the distinguishing run is test C001, which expects
# NEW's behaviour (passes on NEW, fails on OLD); the checklist in every format
# opens with the list of changes and the retest scope; `cemv replay` runs the
# whole folder green on NEW.
# usage: testgen_changed.sh CEMV CASES TMPDIR
set -euo pipefail
cemv=$1 cases=$2 tmp=$3
old=$cases/small_old.json new=$cases/small_new.json
rm -rf "$tmp" && mkdir -p "$tmp"
"$cemv" testgen "$new" --changed-from "$old" --out "$tmp/change" >"$tmp/stdout.txt"
grep -q "partial retest: the comparisons agree" "$tmp/stdout.txt" || { echo "stdout lacks the scope"; cat "$tmp/stdout.txt"; exit 1; }
"$cemv" testgen "$new" --out "$tmp/full" >/dev/null
python3 - "$tmp/change/coverage.json" "$tmp/full/coverage.json" <<'PY'
import json, sys
change, full = (json.load(open(p)) for p in sys.argv[1:3])
elements = {o["element"] for o in change["objectives"]}
assert elements and elements <= {"effect[1]", "cause[1]", "cause[2]"}, elements
assert any(o["element"] == "effect[2]" for o in full["objectives"]), "the full suite has effect 2's objectives"
want = [o["id"] for o in full["objectives"] if o["element"] != "effect[2]"]
assert [o["id"] for o in change["objectives"]] == want, "not every objective of the cone"
assert change["tests"][0]["id"] == "C001" and change["tests"][0]["objectives"] == [], change["tests"][0]
assert change["summary"]["undecided"] == 0
print(f"changed-from: {len(change['objectives'])} of {len(full['objectives'])} objectives, "
      f"{len(change['tests'])} tests")
PY
head -20 "$tmp/change/checklist.md" | grep -q "^## The change" || { echo "checklist.md does not open with the change"; exit 1; }
grep -q "critical: changed intersection cause\[1\]/effect\[1\]" "$tmp/change/checklist.md" || { echo "md: no change list"; exit 1; }
grep -q "<h2>The change</h2>" "$tmp/change/checklist.html" || { echo "html: no change section"; exit 1; }
grep -qE '^# change,"?partial retest' "$tmp/change/checklist.csv" || { echo "csv: no retest row"; exit 1; }
c001=$(ls "$tmp/change"/C001-*.scenario.json)
"$cemv" replay "$new" "$tmp/change" >/dev/null || { echo "the suite does not replay green on NEW"; exit 1; }
rc=0
"$cemv" replay "$old" "$c001" >/dev/null || rc=$?
[ "$rc" -eq 1 ] || { echo "C001 on OLD: exit $rc, expected 1 (it shows the change)"; exit 1; }
echo "testgen --changed-from: partial suite, C001 shows the change"
