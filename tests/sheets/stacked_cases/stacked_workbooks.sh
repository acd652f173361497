#!/usr/bin/env bash
# stacked_workbooks.sh CEMV SOFFICE CASES TMPDIR: the five stacked effect
# headers of docs/csv.md "Stacked effect header" (CASES/*.csv), saved by
# LibreOffice as XLSX and as ODS: import-workbook reads each to the matrix
# import-csv reads from the CSV (its import record aside), with the output
# tags of the tag row as the effects' tags.
set -uo pipefail
cemv=$1; soffice=$2; cases=$3; tmp=$4
rm -rf "$tmp"; mkdir -p "$tmp/csv"
source "$(dirname "$0")/../workbook_cases/libreoffice_env.sh"
cp "$cases"/*.csv "$tmp/csv/"
for to in xlsx ods; do
  lo_infilter=CSV:44,34,76,1 lo_convert "$to" "$tmp/lo" "$tmp"/csv/*.csv || exit 1
done
strip() { python3 -c 'import json,sys; m=json.load(open(sys.argv[1])); m.pop("provenance", None); print(json.dumps(m, indent=1, sort_keys=True))' "$1"; }
failures=0; files=0
for csv in "$tmp"/csv/*.csv; do
  name=$(basename "$csv" .csv); files=$((files + 1))
  "$cemv" import-csv "$csv" -o "$tmp/$name.csv.json" 2> "$tmp/$name.csv.err" || { echo "FAIL: $name.csv"; cat "$tmp/$name.csv.err"; failures=$((failures + 1)); continue; }
  for to in xlsx ods; do
    if ! "$cemv" import-workbook "$tmp/lo/$name.$to" -o "$tmp/$name.$to.json" 2> "$tmp/$name.$to.err"; then
      echo "FAIL: $name.$to"; cat "$tmp/$name.$to.err"; failures=$((failures + 1)); continue
    fi
    if [ "$(strip "$tmp/$name.csv.json")" != "$(strip "$tmp/$name.$to.json")" ]; then
      echo "FAIL: $name.$to reads another matrix than its CSV"
      diff <(strip "$tmp/$name.csv.json") <(strip "$tmp/$name.$to.json") | head -20; failures=$((failures + 1))
    fi
  done
  tags=$(python3 -c 'import json,sys; print(" ".join(t["name"] for e in json.load(open(sys.argv[1]))["effects"] for t in e["tags"]))' "$tmp/$name.xlsx.json" 2>/dev/null)
  echo "$name: effect tags $tags"
done
[ $failures -eq 0 ] || { echo "$failures of $files variants failed"; exit 1; }
echo "stacked effect headers: all $files variants read alike from CSV, XLSX and ODS"
