#!/usr/bin/env bash
# The LSST TMA example (examples/lsst-tma/README.md), from the published
# sheet in ../shared/external to the evidence report, without editing JSON.
# One stage per call, each checking what it produced:
#   import    both versions of the sheet, with the parameters: valid matrices
#   check     the requirements: every verdict as its `# expect:` comment says,
#             each counterexample explained by the rules of the semantics
#   diff      the change of 2023-10-18: one intersection, effect 5
#   evidence  the report (HTML and cemv-evidence/1), printed page by page
# usage: lsst_tma.sh STAGE CEMV SHARED_EXTERNAL TMPDIR
set -euo pipefail
stage=$1 cemv=$2 external=$3 tmp=$4
example=examples/lsst-tma
mkdir -p "$tmp"
case "$stage" in
import)
  "$cemv" import-csv "$external/lsst-tma-interlock-table.csv" --params "$example/params.json" \
    -o "$tmp/lsst-tma.json" 2>"$tmp/import.log"
  "$cemv" import-csv "$external/lsst-tma-interlock-table-2023-10-05.csv" --params "$example/params.json" \
    -o "$tmp/lsst-tma-2023-10-05.json" 2>/dev/null
  grep -q "note: parameters params.json (sha256 [0-9a-f]*...): set 18 values, 5 footnotes explained, 4 limitations stated" \
    "$tmp/import.log" || { echo "the import does not say what the parameters set"; cat "$tmp/import.log"; exit 1; }
  grep -q "24 defaults adopted" "$tmp/import.log" || { echo "the import does not state its defaults"; exit 1; }
  for m in "$tmp/lsst-tma.json" "$tmp/lsst-tma-2023-10-05.json"; do
    "$cemv" validate "$m" | grep -qx "0 errors, 12 warnings" || { echo "$m: not 0 errors, 12 warnings"; exit 1; }
  done
  python3 - "$tmp/lsst-tma.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
p = m["provenance"]
assert p["imports"][0]["file"] == "lsst-tma-interlock-table.csv", p["imports"][0]["file"]
assert len(p["imports"][0]["warnings"]) == 11, len(p["imports"][0]["warnings"])
rec = p["parameters"][0]
assert rec["file"] == "params.json"
fields = {(v["element"], v["field"]) for v in rec["values"]}
for want in [("effect[1] TMA_A_1", "override"), ("effect[1] TMA_A_1", "reset_tag"), ("effect[4] TMA_A_4", "override")]:
    assert want in fields, want
assert [f["mark"] for f in rec["footnotes"]] == ["(1)", "(2)", "(3)", "(4)", "(5)"]
e1 = next(e for e in m["effects"] if e["id"] == 1)
assert e1["override"] == {"max_s": 600, "prealarm_s": 540} and e1["reset_tag"] == "MAIN_AXIS_OVR_SW"
assert all(t.get("simulation_allowed") is False for c in m["causes"] for t in c["tags"])
PY
  echo "lsst import: two valid matrices, every value with its origin"
  ;;
check)
  set +e
  "$cemv" check "$tmp/lsst-tma.json" "$example/requirements.props" --format json -o "$tmp/check.json" --out "$tmp/cex"
  rc=$?
  set -e
  [ "$rc" -eq 1 ] || { echo "cemv check exit $rc, expected 1 (two requirements falsified)"; exit 1; }
  python3 - "$tmp/check.json" "$example/requirements.props" <<'PY'
import json, re, sys
result = json.load(open(sys.argv[1]))
text = open(sys.argv[2]).read()
expect = {name: verdict for verdict, name in re.findall(r"# expect: (\w+)\nproperty ([\w.]+)", text)}
assert len(expect) == 7, expect
got = {p["name"]: p["verdict"] for p in result["properties"]}
assert got == expect, (got, expect)
why = {p["name"]: p["explanation"] for p in result["properties"]}
assert any("R latch cleared without a reset" in s["why"] and "(E.5" in s["why"] for s in why["req4.r_stored_until_reset"]), why["req4.r_stored_until_reset"]
assert any("in the same cycle a new override started" in s["why"] for s in why["req7.override_ends_within_its_maximum"])
assert why["req1.n_platform_not_retracted"] == []
PY
  for f in req4.r_stored_until_reset req7.override_ends_within_its_maximum; do
    "$cemv" simulate "$tmp/lsst-tma.json" "$tmp/cex/$f.scenario.json" >/dev/null
    grep -q "Why, per step" "$tmp/cex/$f.svg" || { echo "$f.svg has no explanation"; exit 1; }
  done
  echo "lsst check: 7 verdicts as expected, counterexamples explained"
  ;;
diff)
  set +e
  "$cemv" diff "$tmp/lsst-tma-2023-10-05.json" "$tmp/lsst-tma.json" --format json -o "$tmp/diff.json"
  rc=$?
  set -e
  [ "$rc" -eq 1 ] || { echo "cemv diff exit $rc, expected 1 (effect 5 changed)"; exit 1; }
  python3 - "$tmp/diff.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
critical = [c["label"] for c in d["structural"]["changes"] if c["critical"]]
assert critical == ["intersection cause[17]/effect[5]"], critical
changed = [e["name"] for e in d["semantic"]["effects"] if e["verdict"] == "differs"]
assert changed == ["TMA_A_5"], changed
assert d["behaviour_not_compared"] == []
PY
  echo "lsst diff: one intersection removed, effect 5 changed, the rest proved equivalent"
  ;;
evidence)
  export SOURCE_DATE_EPOCH=1700000000
  "$cemv" evidence "$tmp/lsst-tma.json" "$example/requirements.props" --standard --timeout 120 \
    --out "$tmp/lsst-tma.html" --json "$tmp/lsst-tma.evidence.json" -q
  python3 - "$tmp/lsst-tma.evidence.json" <<'PY'
import json, sys
e = json.load(open(sys.argv[1]))
assert e["format"] == "cemv-evidence/1"
assert e["sources"][0]["file"] == "lsst-tma-interlock-table.csv" and len(e["sources"][0]["sha256"]) == 64
assert e["parameters"][0]["file"] == "params.json"
names = [r["name"] for r in e["requirements"]]
assert names[0] == "req1.n_platform_not_retracted" and len(names) == 7, names
r4 = e["requirements"][3]
assert r4["statement"].startswith("always ") and len(r4["file_sha256"]) == 64 and r4["line"] > 0
assert r4["verdict"] == "falsified" and r4["explanation"], r4
assert e["standard"]["included"] and len(e["standard"]["properties"]) == 168
assert e["conclusion"]["requirements_not_passed"] == ["req4.r_stored_until_reset (falsified)", "req7.override_ends_within_its_maximum (falsified)"]
kinds = {l["kind"] for l in e["limitations"]}
assert {"footnote not modelled", "stated limitation", "value supplied", "default adopted"} <= kinds, kinds
assert e["signoff"]["assessor"] is None
PY
  bash tests/reports/evidence_pages.sh "$tmp/lsst-tma.html" "$tmp/pages"
  ;;
*) echo "unknown stage $stage"; exit 2 ;;
esac
