#!/usr/bin/env bash
# cli_round_trip.sh CEMV MATRIX TMPDIR: export-csv, import-csv, export-csv again;
# the two CSV files and the two imported matrices must be byte-identical.
set -euo pipefail
cemv=$1; matrix=$2; tmp=$3
mkdir -p "$tmp"
base=$tmp/$(basename "$(dirname "$matrix")")
"$cemv" export-csv "$matrix" -o "$base.csv"
"$cemv" import-csv "$base.csv" -o "$base.json"
"$cemv" export-csv "$base.json" -o "$base.2.csv"
cmp "$base.csv" "$base.2.csv"
"$cemv" import-csv "$base.2.csv" > "$base.2.json"
cmp "$base.json" "$base.2.json"
echo "round trip identical: $matrix"
