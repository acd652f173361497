#!/usr/bin/env bash
# Writes the evidence report of an example and loads it in headless Chromium:
# the page must parse to its end (the DOM Chromium dumps holds the closing
# footer and every section) with no console error, and a second run with the
# same SOURCE_DATE_EPOCH must give the same bytes.
# usage: evidence_headless.sh CEMV MATRIX PROPS TMPDIR
set -euo pipefail
cemv=$1 matrix=$2 props=$3 tmp=$4
mkdir -p "$tmp"
export SOURCE_DATE_EPOCH=1700000000
"$cemv" evidence "$matrix" "$props" --out "$tmp/report.html" --timeout 20 >/dev/null
"$cemv" evidence "$matrix" "$props" --out "$tmp/again.html" --timeout 20 >/dev/null
cmp -s "$tmp/report.html" "$tmp/again.html" || { echo "not reproducible"; exit 1; }
grep -q "2023-11-14 22:13 UTC" "$tmp/report.html" || { echo "date not from SOURCE_DATE_EPOCH"; exit 1; }
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] || { echo "chromium is missing: run scripts/install-deps"; exit 1; }
timeout 60 "$browser" --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking \
  --disable-component-update --disable-sync --user-data-dir="$tmp/profile" --enable-logging=stderr --v=0 \
  --dump-dom "file://$(realpath "$tmp/report.html")" >"$tmp/dom.html" 2>"$tmp/chromium.log"
if grep -E "CONSOLE|Uncaught|Failed to load" "$tmp/chromium.log"; then echo "console errors"; exit 1; fi
for want in "1. Cause &amp; effect matrix" "2. Validation" "3. Properties" "4. Test generation" 'class="pagefoot screen"'; do
  grep -qF "$want" "$tmp/dom.html" || { echo "the loaded page lacks: $want"; exit 1; }
done
echo "evidence report loads in chromium: $(wc -c <"$tmp/report.html") bytes, reproducible"
