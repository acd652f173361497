#!/usr/bin/env bash
# cli_into.sh CEMV MATRIX TMPDIR: export, change one timer in the workbook's
# XML (as an engineer would in the spreadsheet), import --into the original.
set -euo pipefail
cemv=$1; matrix=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp/x"
"$cemv" export-workbook "$matrix" -o "$tmp/m.xlsx"
python3 - "$tmp/m.xlsx" "$tmp/edited.xlsx" <<'PY'
import sys, zipfile
src, dst = sys.argv[1], sys.argv[2]
with zipfile.ZipFile(src) as z, zipfile.ZipFile(dst, "w", zipfile.ZIP_DEFLATED) as out:
    for info in z.infolist():
        data = z.read(info.filename)
        if info.filename == "xl/worksheets/sheet3.xml":   # Causes configuration
            data = data.replace(b"<v>2000</v>", b"<v>5000</v>", 1)
        out.writestr(info.filename, data)
PY
# One line, so that the test can match the change and its field together.
"$cemv" import-workbook "$tmp/edited.xlsx" --into "$matrix" -o "$tmp/new.json" 2>&1 | tr "\n" " "; echo
