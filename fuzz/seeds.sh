#!/usr/bin/env bash
# The raw seeds of each fuzz target, gathered from the repository's tests and
# examples into OUT/<target>/ (docs/fuzzing.md). The corpora kept under
# fuzz/corpus/ are these seeds minimised with libFuzzer's -merge=1, which keeps
# the smallest inputs that reach every feature; run again when the formats grow:
#   fuzz/seeds.sh build/cemv /tmp/seeds && fuzz/run.sh --merge /tmp/seeds
# CEMV (a built binary) writes the CSV exports of every matrix.
set -euo pipefail
cemv=$1
out=$2
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
mkdir -p "$out"/{matrix_json,csv,scenario,properties}

matrices=$(grep -rl '"cemv-matrix/1"' --include='*.json' tests examples | sort)
i=0
for f in $matrices tests/formats/malformed/*.json; do
  i=$((i + 1)); cp "$f" "$out/matrix_json/$(printf %03d $i)-$(basename "$f")"
done

i=0
for f in $(find tests examples -name '*.csv' -o -name '*.tsv' | sort); do
  i=$((i + 1)); cp "$f" "$out/csv/$(printf %03d $i)-$(basename "$f")"
done
for f in $matrices; do
  i=$((i + 1)); name=$(printf %03d $i)-$(basename "$f" .json)
  "$cemv" export-csv "$f" -o "$out/csv/$name-records.csv" 2>/dev/null || true
  "$cemv" export-csv "$f" --layout grid -o "$out/csv/$name-grid.csv" 2>/dev/null || true
  "$cemv" export-csv "$f" --layout grid --orientation effects-as-rows -o "$out/csv/$name-grid-t.csv" 2>/dev/null || true
done
# The grid with other separators, as spreadsheets export it.
for f in "$out"/csv/*-grid.csv; do
  tr ',' ';' < "$f" > "${f%.csv}-semicolon.csv"
done

i=0
for f in $(grep -rl '"cemv-scenario/1"' --include='*.json' tests examples | sort) tests/scenarios/rejects/*.json; do
  i=$((i + 1)); cp "$f" "$out/scenario/$(printf %03d $i)-$(basename "$f")"
done

i=0
for f in $(find tests examples -name '*.props' | sort); do
  i=$((i + 1)); cp "$f" "$out/properties/$(printf %03d $i)-$(basename "$f")"
done
# The property texts of the parser's tests, one file each.
python3 - "$out/properties" tests/properties/test_parser.cpp tests/properties/test_parser_errors.cpp <<'PY'
import re, sys, ast
out = sys.argv[1]
n = 0
for src in sys.argv[2:]:
    text = open(src).read()
    # Adjacent C string literals form one text; keep those that state a property or an assumption.
    for m in re.finditer(r'((?:"(?:[^"\\\n]|\\.)*"\s*)+)', text):
        parts = re.findall(r'"((?:[^"\\\n]|\\.)*)"', m.group(1))
        try:
            s = "".join(ast.literal_eval('"' + p + '"') for p in parts)
        except Exception:
            continue
        if re.search(r'\b(property|assume)\b', s) and '{' in s:
            n += 1
            open(f"{out}/test-{n:03d}.props", "w").write(s)
PY
for t in matrix_json csv scenario properties; do echo "$t: $(ls "$out/$t" | wc -l) seeds, $(du -sh "$out/$t" | cut -f1)"; done
