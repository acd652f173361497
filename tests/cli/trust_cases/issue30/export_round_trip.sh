#!/usr/bin/env bash
# An invalid matrix whose every field a sheet holds is exported, and its
# import gives the same signature. usage: export_round_trip.sh CEMV MATRIX TMPDIR
set -euo pipefail
cemv=$1 matrix=$2 tmp=$3
mkdir -p "$tmp"
"$cemv" export-csv "$matrix" -o "$tmp/no_override.csv"
"$cemv" import-csv "$tmp/no_override.csv" -o "$tmp/back.json"
[ "$("$cemv" signature "$matrix")" = "$("$cemv" signature "$tmp/back.json")" ] && echo "same signature"
