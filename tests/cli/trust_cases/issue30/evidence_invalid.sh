#!/usr/bin/env bash
# The evidence report of a matrix with validation errors: written (exit 1), a
# banner on the cover, the validation findings as the first chapter, nothing
# checked. usage: evidence_invalid.sh CEMV MATRIX TMPDIR
set -uo pipefail
cemv=$1 matrix=$2 tmp=$3
mkdir -p "$tmp"
"$cemv" evidence "$matrix" --standard --out "$tmp/invalid.html" --json "$tmp/invalid.json" -q
rc=$?
grep -q 'class="banner">This matrix has 1 validation errors' "$tmp/invalid.html" || { echo "no banner"; exit 1; }
first=$(grep -o '<h2 id="[a-z-]*"' "$tmp/invalid.html" | sed -n 2p)
[ "$first" = '<h2 id="validation"' ] || { echo "first chapter: $first"; exit 1; }
python3 -c 'import json,sys; e=json.load(open(sys.argv[1])); assert e["checked"] is False and e["requirements"] == [] and e["validation"]["errors"] == 1' "$tmp/invalid.json" || exit 1
echo "exit $rc; banner; validation first; nothing checked"
