#!/usr/bin/env bash
# cli_round_trip.sh CEMV MATRIX TMPDIR: export-workbook to ODS and XLSX, import
# each; the signature must be the matrix's own.
set -euo pipefail
cemv=$1; matrix=$2; tmp=$3
mkdir -p "$tmp"
base=$tmp/$(basename "$(dirname "$matrix")")
want=$("$cemv" signature "$matrix")
for ext in ods xlsx; do
  "$cemv" export-workbook "$matrix" -o "$base.$ext"
  "$cemv" import-workbook "$base.$ext" -o "$base.$ext.json"
  got=$("$cemv" signature "$base.$ext.json")
  [ "$got" = "$want" ] || { echo "$ext: signature $got, expected $want"; exit 1; }
  echo "$ext: same signature $got"
done
