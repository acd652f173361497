#!/usr/bin/env bash
# The HTML of `cemv diff` loaded in headless Chromium (as
# tests/reports/evidence_headless.sh does for the evidence report): the page
# parses to its end, every section is in the DOM Chromium dumps, and no
# console error.
# usage: diff_html_headless.sh CEMV CASES TMPDIR
set -euo pipefail
cemv=$1 cases=$2 tmp=$3
rm -rf "$tmp" && mkdir -p "$tmp"
rc=0
"$cemv" diff "$cases/small_old.json" "$cases/small_new.json" --format html -o "$tmp/diff.html" || rc=$?
[ "$rc" -eq 1 ] || { echo "cemv diff exit $rc, expected 1"; exit 1; }
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] || { echo "chromium is missing: run scripts/install-deps"; exit 1; }
timeout 60 "$browser" --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking \
  --disable-component-update --disable-sync --user-data-dir="$tmp/profile" --enable-logging=stderr --v=0 \
  --dump-dom "file://$(realpath "$tmp/diff.html")" >"$tmp/dom.html" 2>"$tmp/chromium.log"
if grep -E "CONSOLE|Uncaught|Failed to load" "$tmp/chromium.log"; then echo "console errors"; exit 1; fi
for want in "Change comparison: SMALL_PAIR" "<h2>Structural comparison</h2>" "<h2>Semantic comparison</h2>" \
            "<h2>Impact set</h2>" "<h2>Retest (manual 12)</h2>" "effect[1] XV_1" "behaviour changed" \
            "type: \"N\" -&gt; \"S\"" "partial retest"; do
  grep -qF "$want" "$tmp/dom.html" || { echo "the loaded page lacks: $want"; exit 1; }
done
echo "diff report loads in chromium: $(wc -c <"$tmp/diff.html") bytes"
