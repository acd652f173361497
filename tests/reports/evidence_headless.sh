#!/usr/bin/env bash
# Writes the evidence report of an example and loads it in headless Chromium:
# the page must parse to its end (the DOM Chromium dumps holds the closing
# footer and every section) with no console error, and a second run with the
# same SOURCE_DATE_EPOCH must give the same bytes. Printed to PDF, every
# chapter starts a page and every entry of the contents is on its page.
# usage: evidence_headless.sh CEMV MATRIX PROPS TMPDIR [EXTRA EVIDENCE OPTIONS... -- WANTED TEXT...]
set -euo pipefail
cemv=$1 matrix=$2 props=$3 tmp=$4
shift 4
extra=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do extra+=("$1"); shift; done
[ $# -gt 0 ] && shift
mkdir -p "$tmp"
export SOURCE_DATE_EPOCH=1700000000
"$cemv" evidence "$matrix" "$props" "${extra[@]}" --out "$tmp/report.html" --timeout 20 >/dev/null
"$cemv" evidence "$matrix" "$props" "${extra[@]}" --out "$tmp/again.html" --timeout 20 >/dev/null
cmp -s "$tmp/report.html" "$tmp/again.html" || { echo "not reproducible"; exit 1; }
grep -q "2023-11-14 22:13 UTC" "$tmp/report.html" || { echo "date not from SOURCE_DATE_EPOCH"; exit 1; }
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] || { echo "chromium is missing: run scripts/install-deps"; exit 1; }
flags=(--headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking
       --disable-component-update --disable-sync --user-data-dir="$tmp/profile")
timeout 60 "$browser" "${flags[@]}" --enable-logging=stderr --v=0 \
  --dump-dom "file://$(realpath "$tmp/report.html")" >"$tmp/dom.html" 2>"$tmp/chromium.log"
if grep -E "CONSOLE|Uncaught|Failed to load" "$tmp/chromium.log"; then echo "console errors"; exit 1; fi
for want in "Contents" "1. Requirements" "2. Standard properties" "3. Cause &amp; effect matrix" "4. Validation" \
            "5. Provenance" "6. Response time" "7. Test generation" "8. Limitations" "9. Conclusion and sign-off" \
            'class="pagefoot screen"' "$@"; do
  grep -qF "$want" "$tmp/dom.html" || { echo "the loaded page lacks: $want"; exit 1; }
done
timeout 60 "$browser" "${flags[@]}" --no-pdf-header-footer --print-to-pdf="$tmp/report.pdf" \
  "file://$(realpath "$tmp/report.html")" >/dev/null 2>&1
pages=$(grep -ao "/Count [0-9]*" "$tmp/report.pdf" | awk '$2 > n { n = $2 } END { print n + 0 }')
[ "$pages" -ge 11 ] || { echo "printed to $pages PDF pages; expected the cover, the contents and 9 chapters on their own pages"; exit 1; }
# Every contents entry on the page it names.
bash "$(dirname "$0")/evidence_pages.sh" "$tmp/report.html" "$tmp/pages" >/dev/null || { echo "contents pages wrong"; exit 1; }
echo "evidence report loads in chromium: $(wc -c <"$tmp/report.html") bytes, reproducible, $pages printed pages"
