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
mkdir -p "$out"/{matrix_json,csv,scenario,properties,workbook,sheet_layout}

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
# Workbooks: every example exported as ODS and XLSX, the malformed workbooks
# of the tests, and (the target's second way in, fuzz/fuzz_workbook.cpp) the
# same archives unpacked into "@@ NAME" listings, plus a C&E grid on one sheet.
i=0
for f in examples/*/matrix.json tests/sheets/workbook_cases/*/matrix.json; do
  i=$((i + 1)); name=$(printf %03d $i)-$(basename "$(dirname "$f")")
  "$cemv" export-workbook "$f" -o "$out/workbook/$name.ods" -q
  "$cemv" export-workbook "$f" -o "$out/workbook/$name.xlsx" -q
done
for f in tests/sheets/workbook_malformed/*.ods tests/sheets/workbook_malformed/*.xlsx; do
  i=$((i + 1)); cp "$f" "$out/workbook/$(printf %03d $i)-$(basename "$f")"
done
python3 - "$out/workbook" <<'PY'
import io, os, sys, zipfile
out = sys.argv[1]
def listing(entries):
    return "\n".join("@@ " + name + "\n" + data for name, data in entries)
for f in sorted(os.listdir(out)):
    if f.endswith((".ods", ".xlsx")) and ("tank" in f or "edge" in f):
        with zipfile.ZipFile(os.path.join(out, f)) as z:
            entries = [(n, z.read(n).decode("utf-8")) for n in z.namelist()]
        open(os.path.join(out, "listing-" + f + ".txt"), "w").write(listing(entries))
# A C&E grid on the first sheet (read as import-csv reads a grid).
cells = [["", "", "E1", "E2"], ["", "", "XV-1 close", "P-1 stop"], ["C1", "LT-1 high", "S", "N"], ["C2", "PT-1 high", "", "S"]]
def ods_cell(t):
    return '<table:table-cell office:value-type="string"><text:p>%s</text:p></table:table-cell>' % t if t else "<table:table-cell/>"
rows = "".join("<table:table-row>" + "".join(ods_cell(t) for t in r) + "</table:table-row>" for r in cells)
content = ('<?xml version="1.0" encoding="UTF-8"?>\n<office:document-content xmlns:office="urn:oasis:names:tc:opendocument:xmlns:office:1.0" '
           'xmlns:table="urn:oasis:names:tc:opendocument:xmlns:table:1.0" xmlns:text="urn:oasis:names:tc:opendocument:xmlns:text:1.0">'
           '<office:body><office:spreadsheet><table:table table:name="Grid">' + rows + '</table:table></office:spreadsheet></office:body></office:document-content>')
open(os.path.join(out, "listing-grid.ods.txt"), "w").write(listing([("mimetype", "application/vnd.oasis.opendocument.spreadsheet"), ("content.xml", content)]))
strings = sorted({t for r in cells for t in r if t})
def col(i): return "ABCD"[i]
sheet = "".join('<row r="%d">' % (y + 1) + "".join('<c r="%s%d" t="s"><v>%d</v></c>' % (col(x), y + 1, strings.index(t)) for x, t in enumerate(r) if t) + "</row>" for y, r in enumerate(cells))
ns = 'xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main"'
rel = "http://schemas.openxmlformats.org/officeDocument/2006/relationships"
entries = [
    ("[Content_Types].xml", '<?xml version="1.0"?><Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types"><Default Extension="xml" ContentType="application/xml"/></Types>'),
    ("_rels/.rels", '<?xml version="1.0"?><Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships"><Relationship Id="rId1" Type="%s/officeDocument" Target="xl/workbook.xml"/></Relationships>' % rel),
    ("xl/workbook.xml", '<?xml version="1.0"?><workbook %s xmlns:r="%s"><sheets><sheet name="Grid" sheetId="1" r:id="rId1"/></sheets></workbook>' % (ns, rel)),
    ("xl/_rels/workbook.xml.rels", '<?xml version="1.0"?><Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships"><Relationship Id="rId1" Type="%s/worksheet" Target="worksheets/sheet1.xml"/><Relationship Id="rId2" Type="%s/sharedStrings" Target="sharedStrings.xml"/></Relationships>' % (rel, rel)),
    ("xl/sharedStrings.xml", '<?xml version="1.0"?><sst %s>' % ns + "".join("<si><t>%s</t></si>" % t for t in strings) + "</sst>"),
    ("xl/worksheets/sheet1.xml", '<?xml version="1.0"?><worksheet %s><sheetData>%s</sheetData></worksheet>' % (ns, sheet)),
]
open(os.path.join(out, "listing-grid.xlsx.txt"), "w").write(listing(entries))
PY

# The layout descriptions of the vendor workbook's tests.
i=0
for f in tests/sheets/vendor_cases/layout-*.json; do
  i=$((i + 1)); cp "$f" "$out/sheet_layout/$(printf %03d $i)-$(basename "$f")"
done

for t in matrix_json csv scenario properties workbook sheet_layout; do echo "$t: $(ls "$out/$t" | wc -l) seeds, $(du -sh "$out/$t" | cut -f1)"; done
