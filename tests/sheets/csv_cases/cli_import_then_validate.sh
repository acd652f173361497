#!/usr/bin/env bash
# cli_import_then_validate.sh CEMV GRID TMPDIR: import a grid, then validate the
# result; prints validate's override findings on one line, exits with validate's status.
cemv=$1; grid=$2; tmp=$3
mkdir -p "$tmp"
"$cemv" import-csv "$grid" -o "$tmp/imported.json" 2>/dev/null || exit $?
"$cemv" validate "$tmp/imported.json" > "$tmp/validate.out" 2>&1
rc=$?
grep -i override "$tmp/validate.out" | tr '\n' ' '
echo
exit $rc
