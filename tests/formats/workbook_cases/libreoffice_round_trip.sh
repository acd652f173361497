#!/usr/bin/env bash
# libreoffice_round_trip.sh CEMV SOFFICE MATRIX TMPDIR: export-workbook to ODS,
# LibreOffice converts it to XLSX; export to XLSX, LibreOffice converts it to
# ODS; each file LibreOffice wrote imports with the matrix's signature.
set -euo pipefail
cemv=$1; soffice=$2; matrix=$3; tmp=$4
rm -rf "$tmp"; mkdir -p "$tmp"
source "$(dirname "$0")/libreoffice_env.sh"
want=$("$cemv" signature "$matrix")
check() {
  "$cemv" import-workbook "$1" -o "$1.json"
  local got; got=$("$cemv" signature "$1.json")
  [ "$got" = "$want" ] || { echo "$2: signature $got, expected $want"; diff <("$cemv" fmt "$matrix") "$1.json" | head -20; exit 1; }
  echo "$2 by LibreOffice: same signature $got"
}
"$cemv" export-workbook "$matrix" -o "$tmp/a.ods"
lo_convert xlsx "$tmp/lo1" "$tmp/a.ods"
check "$tmp/lo1/a.xlsx" "ods -> xlsx"
"$cemv" export-workbook "$matrix" -o "$tmp/b.xlsx"
lo_convert ods "$tmp/lo2" "$tmp/b.xlsx"
check "$tmp/lo2/b.ods" "xlsx -> ods"
