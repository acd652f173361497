#!/usr/bin/env bash
# libreoffice_lsst.sh CEMV SOFFICE LSST_CSV TMPDIR: LibreOffice opens the LSST
# interlock table (CSV: UTF-8, separated by semicolons, as published) and saves it as XLSX; import-workbook
# reads that XLSX to the same matrix as import-csv reads the CSV.
set -euo pipefail
cemv=$1; soffice=$2; csv=$3; tmp=$4
rm -rf "$tmp"; mkdir -p "$tmp"
source "$(dirname "$0")/libreoffice_env.sh"
name=$(basename "$csv" .csv)
cp "$csv" "$tmp/$name.csv"
lo_infilter=CSV:59,34,76,1 lo_convert xlsx "$tmp/lo" "$tmp/$name.csv"
"$cemv" import-csv "$tmp/$name.csv" -o "$tmp/from-csv.json" 2> "$tmp/csv.warnings"
"$cemv" import-workbook "$tmp/lo/$name.xlsx" -o "$tmp/from-xlsx.json" 2> "$tmp/xlsx.warnings"
# The same matrix; only its provenance differs (each names its own source:
# file, SHA-256, reader, warnings as printed; docs/format.md "Provenance").
strip() { python3 -c 'import json,sys; m=json.load(open(sys.argv[1])); m.pop("provenance", None); print(json.dumps(m, indent=1, sort_keys=True))' "$1"; }
diff <(strip "$tmp/from-csv.json") <(strip "$tmp/from-xlsx.json") | head -30
[ "$(strip "$tmp/from-csv.json")" = "$(strip "$tmp/from-xlsx.json")" ] || exit 1
# The same warnings at the same rows and columns: FILE:L:C of the CSV is
# FILE:SHEET:L:C of the workbook, which names the cell (A1) too.
norm() { sed -E -e 's/^.*[^0-9:]:([0-9]+)(:[0-9]+)?: warning: ([A-Z]+[0-9]+: )?/\1\2 /' -e '/note:/d' "$1"; }
diff <(norm "$tmp/csv.warnings") <(norm "$tmp/xlsx.warnings") || { echo "warnings differ"; exit 1; }
python3 - "$tmp/from-xlsx.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
print("LSST saved as XLSX by LibreOffice imports as its CSV: %d causes, %d effects, %d intersections"
      % (len(m["causes"]), len(m["effects"]), len(m["intersections"])))
PY
