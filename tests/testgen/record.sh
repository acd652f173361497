#!/usr/bin/env bash
# record.sh CEMV CASE: the field checklist of burner-management filled in,
# recorded (cemv record) and shown (cemv evidence --acceptance), as a field
# team and an assessor use them (docs/acceptance.md). Each CASE checks exit
# codes, the status of named elements and the grid's colours.
set -u
cemv=$1; case_=$2
ex=examples/burner-management
fill=tests/testgen/fill_checklist.py
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
fail() { echo "record.sh $case_: $*" >&2; exit 1; }
status() {  # status FILE ELEMENT -> accepted|deviation|not-tested
  python3 -c "import json,sys; a=json.load(open(sys.argv[1])); print([e['status'] for e in a['elements'] if e['element']==sys.argv[2]][0])" "$1" "$2"
}
expect_status() { local s; s=$(status "$1" "$2"); [ "$s" = "$3" ] || fail "$2 is $s, expected $3"; }
refused() {  # refused PATTERN CSV: exit 2 with FILE:LINE: error: PATTERN
  local out rc
  out=$("$cemv" record $ex/matrix.json "$2" -o "$work/r.json" 2>&1); rc=$?
  [ $rc -eq 2 ] || fail "exit $rc, expected 2: $out"
  printf '%s\n' "$out" | grep -Eq "^$2:[0-9]+: error: .*$1" || fail "no FILE:LINE: error: /$1/ in: $out"
}
case $case_ in
  all_ok)
    python3 $fill $ex/acceptance/field/checklist.csv "$work/ok.csv"
    "$cemv" record $ex/matrix.json "$work/ok.csv" -o "$work/acc.json" || fail "record exit $?"
    python3 - "$work/acc.json" <<'PY' || exit 1
import json, sys
a = json.load(open(sys.argv[1]))
assert a["format"] == "cemv-acceptance/1", a["format"]
s = a["summary"]
assert s["steps"] == s["ok"] and s["deviation"] == 0 and s["open"] == 0, s
assert s["accepted"] == s["elements"], s
kinds = {e["kind"] for e in a["elements"]}
assert kinds == {"cause", "effect", "intersection"}, kinds
assert all(r["initials"] == "JS" and r["date"] == "2026-03-02" for st in a["steps"] for r in st["records"])
PY
    SOURCE_DATE_EPOCH=1767225600 "$cemv" evidence $ex/matrix.json --out "$work/ev.html" --acceptance "$work/acc.json" -q \
      || fail "evidence exit $?"
    # 7 causes, 4 effects, 20 intersections, all green; nothing red or amber in the grid.
    n=$(grep -o 'class="[^"]*a-accepted[^"]*"' "$work/ev.html" | wc -l)
    [ "$n" -eq 32 ] || fail "$n accepted cells and heads (31 + legend expected)"
    grep -Eq '<t[dh] class="[^"]*a-(deviation|not-tested)' "$work/ev.html" && fail "a deviation or untested cell in an all-OK grid"
    # The same checklists give the same bytes.
    "$cemv" record $ex/matrix.json "$work/ok.csv" -o "$work/acc2.json" -q
    cmp -s "$work/acc.json" "$work/acc2.json" || fail "record is not reproducible"
    ;;
  deviation)
    python3 $fill $ex/acceptance/field/checklist.csv "$work/dev.csv" --deviation "F003/3:XV_221B did not close"
    "$cemv" record $ex/matrix.json "$work/dev.csv" -o "$work/acc.json"; rc=$?
    [ $rc -eq 1 ] || fail "exit $rc, expected 1 for a deviation"
    expect_status "$work/acc.json" "cause[3]" deviation
    expect_status "$work/acc.json" "intersection cause[3]/effect[1]" deviation
    expect_status "$work/acc.json" "effect[1]" deviation
    expect_status "$work/acc.json" "cause[1]" accepted
    expect_status "$work/acc.json" "intersection cause[1]/effect[2]" accepted
    expect_status "$work/acc.json" "effect[3]" accepted
    "$cemv" evidence $ex/matrix.json --out "$work/ev.html" --acceptance "$work/acc.json" -q || fail "evidence exit $?"
    grep -q '<td class="cause a-deviation">C3</td>' "$work/ev.html" || fail "cause 3 not red in the grid"
    grep -q 'Deviation, cause\[3\]: F003 step 3: XV_221B did not close (JS, 2026-03-02)' "$work/ev.html" \
      || fail "the deviation is not listed"
    ;;
  merge)
    # SIF by SIF on two days; a step left open leaves its elements not-tested.
    python3 $fill $ex/acceptance/field/checklist.csv "$work/d1.csv" --tests F001,F002,F003,F004
    python3 $fill $ex/acceptance/field/checklist.csv "$work/d2.csv" --tests F006
    "$cemv" record $ex/matrix.json "$work/d1.csv" "$work/d2.csv" -o "$work/acc.json" -q || fail "record exit $?"
    expect_status "$work/acc.json" "cause[1]" accepted
    expect_status "$work/acc.json" "cause[6]" accepted
    expect_status "$work/acc.json" "cause[5]" not-tested
    expect_status "$work/acc.json" "cause[7]" not-tested
    expect_status "$work/acc.json" "effect[3]" not-tested   # only cause 5 drives the FD fan
    expect_status "$work/acc.json" "intersection cause[7]/effect[1]" not-tested
    "$cemv" evidence $ex/matrix.json --out "$work/ev.html" --acceptance "$work/acc.json" -q || fail "evidence exit $?"
    grep -q '<td class="cause a-not-tested">C5</td>' "$work/ev.html" || fail "cause 5 not amber"
    ;;
  refusals)
    python3 $fill $ex/acceptance/field/checklist.csv "$work/ok.csv"
    sed 's/^# signature,1/# signature,2/' "$work/ok.csv" > "$work/sig.csv"
    refused "signature" "$work/sig.csv"
    (cat "$work/ok.csv"; echo 'F099,SIF 1,1,Test,Set X,at least 1.0 s,nothing,OK,JS,2026-03-02') > "$work/unknown.csv"
    refused "has no step F099 / 1" "$work/unknown.csv"
    python3 - "$work/ok.csv" "$work/noinit.csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1], newline="")))
for r in rows:
    if r and r[0] == "F002" and r[2] == "2":
        r[8] = ""
csv.writer(open(sys.argv[2], "w", newline=""), lineterminator="\n").writerows(rows)
PY
    refused "needs initials and a date" "$work/noinit.csv"
    sed 's/,2026-03-02$/,02.03.2026/' "$work/ok.csv" > "$work/date.csv"
    refused "is not YYYY-MM-DD" "$work/date.csv"
    # The tank's matrix is another matrix: its signature differs.
    out=$("$cemv" record examples/tank-overfill/matrix.json "$work/ok.csv" 2>&1); [ $? -eq 2 ] || fail "tank: $out"
    # An acceptance record of another matrix is refused by evidence.
    "$cemv" record $ex/matrix.json "$work/ok.csv" -o "$work/acc.json" -q
    out=$("$cemv" evidence examples/tank-overfill/matrix.json --out "$work/ev.html" --acceptance "$work/acc.json" 2>&1)
    [ $? -eq 2 ] && printf '%s' "$out" | grep -q "signature" || fail "evidence took another matrix's record: $out"
    ;;
  changed)
    # A change to cause 3's cells: the untouched elements keep their status.
    python3 $fill $ex/acceptance/field/checklist.csv "$work/ok.csv"
    "$cemv" record $ex/matrix.json "$work/ok.csv" -o "$work/old-acc.json" -q || fail "record exit $?"
    python3 -c "
import json, sys
m = json.load(open('$ex/matrix.json'))
m['intersections'] = [i for i in m['intersections'] if not (i['cause'] == 3 and i['effect'] == 4)]
json.dump(m, open('$work/new.json', 'w'), indent=1)"
    "$cemv" testgen "$work/new.json" --out "$work/new" --field-only -q || fail "testgen exit $?"
    python3 $fill "$work/new/field/checklist.csv" "$work/new.csv" --tests F003
    "$cemv" record "$work/new.json" "$work/new.csv" --changed-from $ex/matrix.json --previous "$work/old-acc.json" \
      -o "$work/acc.json" -q || fail "record exit $?"
    expect_status "$work/acc.json" "cause[3]" accepted
    expect_status "$work/acc.json" "effect[2]" accepted   # carried over
    python3 -c "
import json; a = json.load(open('$work/acc.json'))
e = {x['element']: x for x in a['elements']}
assert 'carried_over' in e['effect[2]'] and 'carried_over' not in e['cause[3]'], e['effect[2]']
assert e['effect[4]']['status'] == 'not-tested', e['effect[4]']" || fail "carry-over"
    ;;
  *) fail "unknown case" ;;
esac
echo "record.sh $case_: ok"
