#!/usr/bin/env bash
# The LSST pair (docs/change-acceptance.md): the two published versions of the
# TMA interlock table, imported from CSV, the missing override times supplied
# as a user would, compared with `cemv diff`. Expected, from reading the two
# grids (they differ in one cell, TMA-D-17 x TMA-A-5, "N" -> " "): the title
# (non-critical) and the N intersection cause 17 / effect 5 removed (critical);
# effect 5 behaves differently in the first cycle (cause 17 trips: OLD
# activates effect 5, NEW does not), every other effect is proved equivalent;
# impact set effect 5 and the causes of its two cones (17, 20, 25, 26, 31,
# 32, 41); partial retest justified; exit 1. The distinguishing scenario
# passes on OLD and fails on NEW.
# usage: lsst_pair.sh CEMV OLD_CSV NEW_CSV TMPDIR
set -euo pipefail
cemv=$1 old_csv=$2 new_csv=$3 tmp=$4
here=$(dirname "$0")
rm -rf "$tmp" && mkdir -p "$tmp"
"$cemv" import-csv "$old_csv" -o "$tmp/old.json" 2>/dev/null
"$cemv" import-csv "$new_csv" -o "$tmp/new.json" 2>/dev/null
python3 "$here/lsst_supply_override.py" "$tmp/old.json"
python3 "$here/lsst_supply_override.py" "$tmp/new.json"
"$cemv" validate -q "$tmp/old.json"
"$cemv" validate -q "$tmp/new.json"
rc=0
"$cemv" diff "$tmp/old.json" "$tmp/new.json" --format json -o "$tmp/diff.json" --out "$tmp/scenarios" || rc=$?
[ "$rc" -eq 1 ] || { echo "cemv diff exit $rc, expected 1"; exit 1; }
python3 - "$tmp/diff.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
assert d["format"] == "cemv-diff/1" and d["exit_code"] == 1, d["exit_code"]
changes = [(c["element"], c["change"], c["critical"], c["label"]) for c in d["structural"]["changes"]]
assert changes == [("matrix", "changed", False, "matrix"),
                   ("intersection", "removed", True, "intersection cause[17]/effect[5]")], changes
effects = d["semantic"]["effects"]
assert len(effects) == 17, len(effects)
for e in effects:
    if e["new_id"] == 5:
        assert e["verdict"] == "differs" and e["behaviour"] == "behaviour changed", e
        x = e["distinction"]
        assert (x["key"], x["cycle"], x["old"], x["new"]) == ("effect[5].active", 1, "1", "0"), x
        assert x["scenario"].endswith("effect_5.diff.scenario.json"), x
        assert [o["verdict"] for o in e["outputs"]] == ["differs"], e["outputs"]
    else:
        assert e["verdict"] == "equivalent", e
        assert e["behaviour"] == "unchanged, behaviour equivalent", e
assert d["impact"]["effects"] == [5], d["impact"]
assert d["impact"]["causes"] == [17, 20, 25, 26, 31, 32, 41], d["impact"]
assert d["retest"]["scope"] == "partial", d["retest"]
print("lsst pair: the expected classification")
PY
scen="$tmp/scenarios/effect_5.diff.scenario.json"
"$cemv" simulate "$tmp/old.json" "$scen" >/dev/null || { echo "the scenario fails on OLD"; exit 1; }
rc=0
"$cemv" simulate "$tmp/new.json" "$scen" >/dev/null || rc=$?
[ "$rc" -eq 1 ] || { echo "the scenario on NEW: exit $rc, expected 1 (a failed expectation)"; exit 1; }
echo "lsst pair: the distinguishing scenario passes on OLD and fails on NEW"
# The retest the change needs: the comparisons agree, so only the objectives
# of effect 5's cone and the impact set's causes, plus the distinguishing run
# as C001; every test green on NEW.
"$cemv" testgen "$tmp/new.json" --changed-from "$tmp/old.json" --out "$tmp/retest" -q
python3 - "$tmp/retest/coverage.json" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
elements = {o["element"] for o in c["objectives"]}
allowed = {"effect[5]"} | {f"cause[{i}]" for i in (17, 20, 25, 26, 31, 32, 41)}
assert elements and elements <= allowed, elements - allowed
assert c["tests"][0]["id"] == "C001" and c["summary"]["undecided"] == 0, c["summary"]
print(f"lsst retest: {c['summary']['objectives']} objectives, {c['summary']['tests']} tests")
PY
"$cemv" replay "$tmp/new.json" "$tmp/retest" >/dev/null
grep -q "^## The change" "$tmp/retest/checklist.md"
echo "lsst pair: testgen --changed-from gives the partial retest, green on NEW"
