#!/usr/bin/env bash
# The contents of a printed evidence report give the printed pages: prints
# the report to PDF with headless Chromium and checks, for every entry of the
# contents, that its heading is on the page the contents names, and that the
# PDF has as many pages as the report's own count (no sheet ran over).
# usage: evidence_pages.sh REPORT.html TMPDIR
set -euo pipefail
report=$1 tmp=$2
mkdir -p "$tmp"
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] || { echo "chromium is missing: run scripts/install-deps"; exit 1; }
command -v pdftotext >/dev/null || { echo "pdftotext is missing (poppler-utils): run scripts/install-deps"; exit 1; }
timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking \
  --disable-component-update --disable-sync --user-data-dir="$tmp/profile" --no-pdf-header-footer \
  --print-to-pdf="$tmp/report.pdf" "file://$(realpath "$report")" >/dev/null 2>&1
pages=$(pdfinfo "$tmp/report.pdf" 2>/dev/null | awk '/^Pages:/ { print $2 }')
[ -n "$pages" ] || pages=$(grep -ao "/Count [0-9]*" "$tmp/report.pdf" | awk '$2 > n { n = $2 } END { print n + 0 }')
sheets=$(grep -o '<section class="sheet' "$report" | wc -l)
[ "$pages" -eq "$sheets" ] || { echo "printed $pages pages for $sheets sheets: a sheet ran over its page"; exit 1; }
# Entries of the contents: number, title, page (the HTML is one row per entry).
grep -o '<tr class="l[12]"><td class="n">[^<]*</td><td><a href="#[^"]*">[^<]*</a></td><td class="pg">[0-9]*' "$report" |
  sed -E 's|<tr class="l[12]"><td class="n">([^<]*)</td><td><a href="#[^"]*">([^<]*)</a></td><td class="pg">([0-9]*)|\1\t\2\t\3|' \
  >"$tmp/toc.tsv"
entries=$(wc -l <"$tmp/toc.tsv")
[ "$entries" -gt 0 ] || { echo "no contents"; exit 1; }
while IFS=$'\t' read -r number title page; do
  title=$(printf '%s' "$title" | sed -e 's/&amp;/\&/g' -e 's/&lt;/</g' -e 's/&gt;/>/g' -e "s/&#39;/'/g" -e 's/&quot;/"/g')
  heading="$number $title"
  [ "${number%.*}" = "$number" ] && heading="$number. $title"
  pdftotext -f "$page" -l "$page" "$tmp/report.pdf" "$tmp/page.txt"
  grep -qF "$heading" "$tmp/page.txt" || { echo "'$heading' is not on page $page, which the contents name"; exit 1; }
done <"$tmp/toc.tsv"
echo "evidence contents: $entries entries, each on the page it names; $pages pages"
