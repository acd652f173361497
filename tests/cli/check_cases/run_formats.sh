#!/usr/bin/env bash
# run_formats.sh CEMV MATRIX PROPS EXPECTED_EXIT TMPDIR COUNTS...: runs `cemv check`
# in json, junit and sarif (to -o files), checks each exit status, validates
# each file as its consumer reads it (validate_outputs.py), and checks that a
# second run, with --jobs 2, writes byte-identical files.
# COUNTS: PROPERTIES FAILURES ERRORS SARIF_RESULTS.
set -u
cemv=$1 matrix=$2 props=$3 expected=$4 tmp=$5 n=$6 failures=$7 errors=$8 findings=$9
here=$(cd "$(dirname "$0")/.." && pwd)
validate="python3 $here/../reports/validate_outputs.py"
mkdir -p "$tmp" && rm -f "$tmp"/r.* "$tmp"/again.*
for fmt in json junit sarif; do
  "$cemv" check "$matrix" "$props" --format $fmt -o "$tmp/r.$fmt" --out "$tmp/cex"; rc=$?
  [ $rc -eq "$expected" ] || { echo "--format $fmt: exit $rc, expected $expected"; exit 1; }
  "$cemv" check "$matrix" "$props" --format $fmt -o "$tmp/again.$fmt" --out "$tmp/cex" --jobs 2 -q
  cmp "$tmp/r.$fmt" "$tmp/again.$fmt" || { echo "--format $fmt differs between runs"; exit 1; }
done
$validate json "$tmp/r.json" "$n" || exit 1
$validate junit "$tmp/r.junit" "$n" "$failures" "$errors" || exit 1
$validate sarif "$tmp/r.sarif" "$findings" || exit 1
echo "formats valid and deterministic"
