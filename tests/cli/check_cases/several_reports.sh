#!/usr/bin/env bash
# several_reports.sh CEMV MATRIX PROPS TMPDIR: one run writing json (-o),
# junit and sarif (--report) gives the same files as a run per format.
set -eu
cemv=$1 matrix=$2 props=$3 tmp=$4
mkdir -p "$tmp"
"$cemv" check "$matrix" "$props" --format json -o "$tmp/one.json" \
  --report "junit:$tmp/one.xml" --report "sarif:$tmp/one.sarif" -q || [ $? -eq 1 ]
"$cemv" check "$matrix" "$props" --format junit -o "$tmp/alone.xml" -q || [ $? -eq 1 ]
"$cemv" check "$matrix" "$props" --format sarif -o "$tmp/alone.sarif" -q || [ $? -eq 1 ]
"$cemv" check "$matrix" "$props" --format json -o "$tmp/alone.json" -q || [ $? -eq 1 ]
cmp "$tmp/one.xml" "$tmp/alone.xml"
cmp "$tmp/one.sarif" "$tmp/alone.sarif"
cmp "$tmp/one.json" "$tmp/alone.json"
echo same
