#!/usr/bin/env bash
# apply-params on an imported matrix gives the matrix that import --params
# gives (the import record aside: its defaults are taken after the parameters).
# usage: apply_same_as_import.sh CEMV CASES TMPDIR
set -euo pipefail
cemv=$1 cases=$2 tmp=$3
mkdir -p "$tmp"
"$cemv" import-csv "$cases/small.csv" -o "$tmp/a.json" -q
"$cemv" apply-params "$tmp/a.json" "$cases/small.params.json" -o "$tmp/b.json" -q
"$cemv" import-csv "$cases/small.csv" --params "$cases/small.params.json" -o "$tmp/c.json" -q
python3 - "$tmp/b.json" "$tmp/c.json" <<'PY'
import json, sys
b, c = (json.load(open(f)) for f in sys.argv[1:])
assert len(b["provenance"]["parameters"]) == 1 and len(c["provenance"]["parameters"]) == 1
for m in (b, c):
    m["provenance"]["imports"][0]["defaults"] = []
print("same" if b == c else "differ")
PY
