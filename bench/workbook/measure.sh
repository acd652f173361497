#!/usr/bin/env bash
# measure.sh CEMV DIR: time and peak memory of `cemv import-workbook` on each
# hostile workbook of hostile_workbooks.py and on the largest valid workbook
# (128 causes x 128 effects, 1024 intersections: examples are far smaller).
set -uo pipefail
cemv=$1; dir=$2
python3 "$(dirname "$0")/hostile_workbooks.py" "$dir" > /dev/null
"$cemv" export-workbook "$dir/big-matrix.json" -o "$dir/big-matrix.ods"
"$cemv" export-workbook "$dir/big-matrix.json" -o "$dir/big-matrix.xlsx"
for f in "$dir"/*.ods "$dir"/*.xlsx; do
  /usr/bin/time -f "%e s %M KiB" -o "$dir/time.txt" "$cemv" import-workbook "$f" -o /dev/null > "$dir/out.txt" 2>&1
  rc=$?
  printf '%-28s exit %d  %-22s %s\n' "$(basename "$f")" "$rc" "$(cat "$dir/time.txt")" "$(grep -m1 -o 'error: .*' "$dir/out.txt" | cut -c1-110)"
done
