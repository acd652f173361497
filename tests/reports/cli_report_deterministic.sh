#!/usr/bin/env bash
# cli_report_deterministic.sh CEMV MATRIX TMPDIR: every report format twice,
# byte-identical; the signature appears at the top and the bottom.
set -euo pipefail
cemv=$1; matrix=$2; tmp=$3
mkdir -p "$tmp"
for f in md html json; do
  "$cemv" report "$matrix" --format "$f" > "$tmp/a.$f"
  "$cemv" report "$matrix" --format "$f" -o "$tmp/b.$f"
  cmp "$tmp/a.$f" "$tmp/b.$f"
done
sig=$(grep -o '[0-9a-f]\{64\}' "$tmp/a.md" | head -1)
[ "$(grep -c "$sig" "$tmp/a.md")" -eq 2 ]
[ "$(grep -o "$sig" "$tmp/a.html" | wc -l)" -eq 2 ]
echo "deterministic, signature $sig at top and bottom"
