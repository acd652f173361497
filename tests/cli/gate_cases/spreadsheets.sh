#!/usr/bin/env bash
# spreadsheets.sh CEMV TMP: a CSV table or a workbook given where a matrix is
# expected (validate, check, simulate's MATRIX) is named as what it is, with
# the command that converts it (exit 2), not answered with a JSON syntax
# error that quotes its bytes.
set -u
cemv=$1 tmp=$2
rm -rf "$tmp" && mkdir -p "$tmp"
tank=examples/tank-overfill/matrix.json
"$cemv" export-csv "$tank" -o "$tmp/table.csv" -q || exit 1
"$cemv" export-csv "$tank" --layout grid -o "$tmp/grid.txt" -q || exit 1
"$cemv" export-workbook "$tank" -o "$tmp/book.xlsx" -q || exit 1
cp "$tmp/book.xlsx" "$tmp/book.json"  # the content decides, not the name
"$cemv" export-workbook "$tank" -o "$tmp/book.ods" -q || exit 1
expect() {  # expect WHAT COMMAND...: exit 2 and the hint for WHAT
  local what=$1; shift
  out=$("$@" 2>&1); rc=$?
  [ $rc = 2 ] || { echo "$out"; echo "$*: exit $rc, expected 2"; exit 1; }
  echo "$out" | grep -q "error: not a cemv-matrix/1 file but .*cemv $what FILE -o matrix.json" ||
    { echo "$out"; echo "$*: no hint to use $what"; exit 1; }
  echo "$out" | grep -Eq "last read|invalid UTF-8|byte 0x" && { echo "$out"; echo "$*: quotes the file"; exit 1; }
  return 0
}
expect import-csv "$cemv" validate "$tmp/table.csv"
expect import-csv "$cemv" validate "$tmp/grid.txt"
expect import-workbook "$cemv" validate "$tmp/book.xlsx"
expect import-workbook "$cemv" validate "$tmp/book.json"
expect import-workbook "$cemv" validate "$tmp/book.ods"
expect import-csv "$cemv" check "$tmp/table.csv" --standard
expect import-workbook "$cemv" simulate "$tmp/book.ods" examples/tank-overfill/scenario-1-overfill-trip.json
echo "spreadsheets named, with the command that converts them"
