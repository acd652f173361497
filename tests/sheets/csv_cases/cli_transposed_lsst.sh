#!/usr/bin/env bash
# cli_transposed_lsst.sh CEMV TABLE TMPDIR [OPTIONS...]: writes the LSST table
# transposed (effects as rows, as it was first published), imports it with the
# options given, and checks that it has the intersections of the table as
# published (by cause name, effect name and type). Prints the import's summary.
set -euo pipefail
cemv=$1; table=$2; tmp=$3; shift 3
mkdir -p "$tmp"
awk -F';' '{ for (i = 1; i < NF; ++i) cell[NR, i] = $i; if (NF - 1 > w) w = NF - 1; n = NR }
  END { for (i = 1; i <= w; ++i) { line = cell[1, i]; for (r = 2; r <= n; ++r) line = line ";" cell[r, i]; print line } }' \
  "$table" > "$tmp/transposed.csv"
"$cemv" import-csv "$tmp/transposed.csv" -o "$tmp/transposed.json" "$@" 2> "$tmp/transposed.err"
"$cemv" import-csv "$table" -o "$tmp/published.json" 2>/dev/null
by_name() { "$cemv" export-csv "$1" | awk -F, '/^cause,/ { c[$2] = $3 } /^effect,/ { e[$2] = $3 }
  /^intersection,/ { x[++n] = $2 "," $3 "," $4 } END { for (i = 1; i <= n; ++i) { split(x[i], f, ","); print c[f[1]], e[f[2]], f[3] } }' | sort; }
diff <(by_name "$tmp/published.json") <(by_name "$tmp/transposed.json")
echo "transposed table: $(by_name "$tmp/transposed.json" | wc -l) intersections as published; $(grep '^note:' "$tmp/transposed.err")"
