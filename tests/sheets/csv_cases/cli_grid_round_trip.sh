#!/usr/bin/env bash
# cli_grid_round_trip.sh CEMV MATRIX TMPDIR: exports the matrix as a grid in both
# orientations and imports each grid back; the intersections (cause, effect,
# type: the first fields of the records layout's intersection rows) must be the
# same as the matrix's. Prints one line per orientation.
set -euo pipefail
cemv=$1; matrix=$2; tmp=$3
mkdir -p "$tmp"
base=$tmp/$(basename "$(dirname "$matrix")")
intersections() { "$cemv" export-csv "$1" | grep '^intersection,' | cut -d, -f2-4; }
intersections "$matrix" > "$base.expected"
[ -s "$base.expected" ] || { echo "no intersections in $matrix"; exit 1; }
for orientation in causes-as-rows effects-as-rows; do
  "$cemv" export-csv --layout grid --orientation "$orientation" "$matrix" -o "$base.$orientation.csv"
  "$cemv" import-csv "$base.$orientation.csv" -o "$base.$orientation.json" 2> "$base.$orientation.err"
  grep -q "orientation $orientation from the corner labels" "$base.$orientation.err"
  intersections "$base.$orientation.json" > "$base.$orientation.got"
  diff "$base.expected" "$base.$orientation.got"
  echo "$orientation: $(wc -l < "$base.expected") intersections identical"
done
