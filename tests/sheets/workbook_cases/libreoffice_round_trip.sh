#!/usr/bin/env bash
# libreoffice_round_trip.sh CEMV SOFFICE TMPDIR MATRIX...: export-workbook each
# matrix to ODS and XLSX; LibreOffice converts the ODS files to XLSX and the
# XLSX files to ODS (one soffice run each); every file LibreOffice wrote
# imports with its matrix's signature.
set -euo pipefail
cemv=$1; soffice=$2; tmp=$3; shift 3
rm -rf "$tmp"; mkdir -p "$tmp/ods" "$tmp/xlsx"
source "$(dirname "$0")/libreoffice_env.sh"
for matrix in "$@"; do
  name=$(basename "$(dirname "$matrix")")
  "$cemv" export-workbook "$matrix" -o "$tmp/ods/$name.ods"
  "$cemv" export-workbook "$matrix" -o "$tmp/xlsx/$name.xlsx"
done
lo_convert xlsx "$tmp/lo-xlsx" "$tmp"/ods/*.ods
lo_convert ods "$tmp/lo-ods" "$tmp"/xlsx/*.xlsx
for matrix in "$@"; do
  name=$(basename "$(dirname "$matrix")")
  want=$("$cemv" signature "$matrix")
  for pair in "ods -> xlsx:lo-xlsx/$name.xlsx" "xlsx -> ods:lo-ods/$name.ods"; do
    file=$tmp/${pair#*:}
    "$cemv" import-workbook "$file" -o "$file.json" 2> "$file.log" || { cat "$file.log"; exit 1; }
    got=$("$cemv" signature "$file.json")
    [ "$got" = "$want" ] || { echo "$name ${pair%%:*}: signature $got, expected $want"; diff <("$cemv" fmt "$matrix") "$file.json" | head -20; exit 1; }
    # A workbook LibreOffice re-saved imports without a warning.
    grep -q "warning:" "$file.log" && { echo "$name ${pair%%:*}: warnings"; cat "$file.log"; exit 1; }
    echo "$name ${pair%%:*} by LibreOffice: same signature $got"
  done
done
echo "all $# matrices: same signature after LibreOffice re-saved them"
