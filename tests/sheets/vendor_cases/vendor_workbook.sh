#!/usr/bin/env bash
# vendor_workbook.sh CEMV SOFFICE CASES TMPDIR: a contractor's SIS cause &
# effect workbook (CASES/sis-matrix.fods: a cover, a revision history, the SIS
# matrix and a remarks sheet; attribute columns, a stacked effect header, a
# 2oo3 group merged over three rows, S*, N*, NP, a struck-through deleted row)
# is saved by LibreOffice as XLSX, as ODS and as the CSV of its matrix sheet.
# Each is imported in every variant: with the layout (found from the sheet but
# for what cannot be, given whole, or saved by an import and given again), and
# without what cannot be found. Every variant must either give the intended
# matrix (CASES/sis-matrix.expected.json, written by hand from the sheet: the
# same signature from all three files, once the import record that names each
# source is set aside) or be refused with the cell named; none may exit 0 with
# another matrix.
set -uo pipefail
cemv=$1; soffice=$2; cases=$3; tmp=$4
rm -rf "$tmp"; mkdir -p "$tmp/lo" "$tmp/struck"
source "$(dirname "$0")/../workbook_cases/libreoffice_env.sh"
failures=0; variants=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# The workbook, and a variant whose deleted row is shown by strikethrough
# alone (its description no longer says DELETED), of the same name.
cp "$cases/sis-matrix.fods" "$tmp/sis-matrix.fods"
sed 's/ (DELETED Rev\. C)//' "$cases/sis-matrix.fods" > "$tmp/struck/sis-matrix.fods"
grep -q 'DELETED' "$tmp/struck/sis-matrix.fods" && fail "the strike-only variant still says DELETED"
for to in xlsx ods; do
  lo_convert "$to" "$tmp/lo" "$tmp/sis-matrix.fods" || exit 1
  lo_convert "$to" "$tmp/struck" "$tmp/struck/sis-matrix.fods" || exit 1
done
# The matrix sheet (the third) as CSV: comma, double quotes, UTF-8.
timeout 300 "$soffice" "$lo_profile" --headless --norestore --nolockcheck \
  --convert-to 'csv:Text - txt - csv (StarCalc):44,34,76,1,,0,false,true,false,false,false,3' \
  --outdir "$tmp/lo" "$tmp/sis-matrix.fods" > "$tmp/lo/csv.log" 2>&1
mv "$tmp/lo/sis-matrix-SIS Matrix.csv" "$tmp/lo/sis-matrix.csv" || { cat "$tmp/lo/csv.log"; exit 1; }
lo=$tmp/lo

# The intended matrix, and the same with the footnote's text unknown (a CSV of
# the one sheet, or a workbook read without its remarks sheet: S* and N* keep
# the note '*', and a warning says the footnote has no text).
"$cemv" fmt "$cases/sis-matrix.expected.json" -o "$tmp/intended.json" || exit 1
sed 's/"note": "\* Trip delayed 10 s during start-up (start-up timer in the BPCS)"/"note": "*"/' \
  "$tmp/intended.json" > "$tmp/intended-bare-footnote.json"
cmp -s "$tmp/intended.json" "$tmp/intended-bare-footnote.json" && fail "no footnote text in the intended matrix"

# Layouts without one of what the sheet cannot say.
layout() {  # layout NAME PYTHON-EDIT: the minimal layout, edited
  python3 - "$cases/layout-minimal.json" "$tmp/$1.json" "$2" <<'PY'
import json, sys
l = json.load(open(sys.argv[1]))
exec(sys.argv[3])
json.dump(l, open(sys.argv[2], "w"), indent=2)
PY
}
layout no-marks 'del l["marks"]'
layout no-trip-side 'del l["trip_sides"]'
layout no-remarks 'del l["remarks_sheet"]'
layout transposed 'l["orientation"] = "effects-as-rows"'

import_file() {  # import_file FILE OUT ARGS...: import-csv or import-workbook by extension
  local file=$1 out=$2; shift 2
  case $file in
    *.csv) "$cemv" import-csv "$file" -o "$out" "$@" ;;
    *) "$cemv" import-workbook "$file" -o "$out" "$@" ;;
  esac
}

# reads NAME EXPECTED FILE ARGS...: exit 0 with exactly EXPECTED (byte for byte).
reads() {
  local name=$1 expected=$2 file=$3; shift 3
  variants=$((variants + 1))
  rm -f "$tmp/out.json"
  import_file "$file" "$tmp/out.json" "$@" 2> "$tmp/err.txt"
  local rc=$?
  if [ $rc -ne 0 ]; then fail "$name: exit $rc"; cat "$tmp/err.txt"; return; fi
  # The same matrix but for its import record (which names its own source).
  python3 "$(dirname "$0")/../without_import_records.py" "$tmp/out.json" "$tmp/bare.json" && "$cemv" fmt "$tmp/bare.json" -o "$tmp/bare.json"
  if ! cmp -s "$expected" "$tmp/bare.json"; then
    fail "$name: exit 0 with another matrix"; diff "$expected" "$tmp/bare.json" | head -20; return
  fi
  echo "read   $name: $("$cemv" signature "$tmp/bare.json")"
}

# refused NAME FILE ARGS... -- REGEX...: exit 2, nothing written, every REGEX
# found in the messages, and no other error.
refused() {
  local name=$1 file=$2; shift 2
  local args=()
  while [ "$1" != "--" ]; do args+=("$1"); shift; done; shift
  variants=$((variants + 1))
  rm -f "$tmp/out.json"
  import_file "$file" "$tmp/out.json" "${args[@]}" 2> "$tmp/err.txt"
  local rc=$?
  if [ $rc -ne 2 ]; then fail "$name: exit $rc, expected a refusal"; cat "$tmp/err.txt"; return; fi
  [ -e "$tmp/out.json" ] && fail "$name: refused, yet a matrix was written"
  local errors; errors=$(grep -c ': error: ' "$tmp/err.txt")
  [ "$errors" -eq "$#" ] || { fail "$name: $errors errors, expected $#"; cat "$tmp/err.txt"; }
  for regex in "$@"; do
    grep -Eq -- "$regex" "$tmp/err.txt" || { fail "$name: no message matching $regex"; cat "$tmp/err.txt"; }
  done
  echo "refused $name: $(grep -m1 ': error: ' "$tmp/err.txt" | cut -c1-150)"
}

NP_XLSX='sis-matrix\.(xlsx|ods):SIS Matrix:16:8: error: H16: mark .NP. at cause C_5 / effect E_1 has no meaning'
SP_XLSX="sis-matrix\.(xlsx|ods):SIS Matrix:17:4: error: D17: setpoint '180' of cause '6': nothing says which side trips"
NP_CSV='sis-matrix\.csv:16:8: error: mark .NP. at cause C_5 / effect E_1 has no meaning'
SP_CSV="sis-matrix\.csv:17:4: error: setpoint '180' of cause '6': nothing says which side trips"

for f in xlsx ods; do
  book=$lo/sis-matrix.$f
  # The sheet found among four, the rest found from its headers: only the mark
  # NP, the trip side of item 6 and the remarks sheet are given.
  reads "$f, layout found but for NP, a trip side, the remarks" "$tmp/intended.json" "$book" \
    --sheet-layout "$cases/layout-minimal.json" --save-layout "$tmp/saved-$f.json"
  reads "$f, the whole layout given" "$tmp/intended.json" "$book" --sheet-layout "$cases/layout-full.json"
  reads "$f, the layout an XLSX import saved" "$tmp/intended.json" "$book" --sheet-layout "$tmp/saved-xlsx.json"
  reads "$f, --sheet by name" "$tmp/intended.json" "$book" --sheet "sis matrix" --sheet-layout "$cases/layout-minimal.json"
  reads "$f, --sheet by number" "$tmp/intended.json" "$book" --sheet 3 --sheet-layout "$cases/layout-minimal.json"
  reads "$f, deleted by strikethrough alone" "$tmp/intended.json" "$tmp/struck/sis-matrix.$f" \
    --sheet-layout "$cases/layout-minimal.json"
  reads "$f, without the remarks sheet" "$tmp/intended-bare-footnote.json" "$book" --sheet-layout "$tmp/no-remarks.json"
  refused "$f, no layout" "$book" -- "$NP_XLSX" "$SP_XLSX"
  refused "$f, no meaning for NP" "$book" --sheet-layout "$tmp/no-marks.json" -- "$NP_XLSX"
  refused "$f, no trip side" "$book" --sheet-layout "$tmp/no-trip-side.json" -- "$SP_XLSX"
  refused "$f, transposed" "$book" --sheet-layout "$tmp/transposed.json" -- \
    "error: .* the layout's orientation effects-as-rows would read every cause as an effect"
  refused "$f, the cover sheet" "$book" --sheet Cover --sheet-layout "$cases/layout-minimal.json" -- \
    "sis-matrix\.$f:Cover.*error: not a C&E grid"
done
cmp -s "$tmp/saved-xlsx.json" "$tmp/saved-ods.json" || fail "the XLSX and the ODS save different layouts"
cmp -s "$tmp/saved-xlsx.json" "$cases/layout-full.json" || fail "the saved layout is not layout-full.json"

csv=$lo/sis-matrix.csv
reads "csv, the layout an XLSX import saved" "$tmp/intended.json" "$csv" --sheet-layout "$tmp/saved-xlsx.json"
reads "csv, the whole layout given" "$tmp/intended.json" "$csv" --sheet-layout "$cases/layout-full.json"
reads "csv, layout found but for NP and a trip side (no footnote text)" "$tmp/intended-bare-footnote.json" "$csv" \
  --sheet-layout "$cases/layout-minimal.json"
grep -q "warning: footnotes \* are referenced but the file has no legend rows" "$tmp/err.txt" ||
  fail "csv without the footnote text: no warning"
refused "csv, no layout" "$csv" -- "$NP_CSV" "$SP_CSV"
refused "csv, no meaning for NP" "$csv" --sheet-layout "$tmp/no-marks.json" -- "$NP_CSV"
refused "csv, no trip side" "$csv" --sheet-layout "$tmp/no-trip-side.json" -- "$SP_CSV"
refused "csv, transposed" "$csv" --orientation effects-as-rows --sheet-layout "$cases/layout-minimal.json" -- \
  "error: .* --orientation effects-as-rows would read every cause as an effect"

if [ $failures -ne 0 ]; then echo "$failures of $variants variants failed"; exit 1; fi
echo "vendor workbook: all $variants variants read right (signature $("$cemv" signature "$tmp/intended.json")) or refused with the cell named; none misread"
