#!/usr/bin/env python3
"""hostile_workbooks.py DIR: writes the hostile workbooks of docs/workbook.md
"Limits" into DIR, for measuring what `cemv import-workbook` takes to refuse
each (bench/workbook/measure.sh). Each is a valid zip of valid XML."""
import os, sys, zipfile

out = sys.argv[1]
os.makedirs(out, exist_ok=True)
ODS_MIME = "application/vnd.oasis.opendocument.spreadsheet"

def ods(name, table_xml):
    with zipfile.ZipFile(os.path.join(out, name), "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr(zipfile.ZipInfo("mimetype"), ODS_MIME, compress_type=zipfile.ZIP_STORED)
        z.writestr("content.xml", '<office:document-content><office:body><office:spreadsheet>'
                   '<table:table table:name="Causes configuration">' + table_xml +
                   '</table:table></office:spreadsheet></office:body></office:document-content>')

def xlsx(name, sheet_xml, shared=None):
    with zipfile.ZipFile(os.path.join(out, name), "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("[Content_Types].xml", "<Types/>")
        z.writestr("xl/workbook.xml", '<workbook><sheets><sheet name="a" r:id="rId1"/></sheets></workbook>')
        rels = '<Relationship Id="rId1" Target="worksheets/sheet1.xml"/>'
        if shared is not None:
            rels += ('<Relationship Id="rId2" Type="http://schemas.openxmlformats.org/officeDocument/2006/'
                     'relationships/sharedStrings" Target="sharedStrings.xml"/>')
            z.writestr("xl/sharedStrings.xml", shared)
        z.writestr("xl/_rels/workbook.xml.rels", "<Relationships>" + rels + "</Relationships>")
        z.writestr("xl/worksheets/sheet1.xml", "<worksheet><sheetData>" + sheet_xml + "</sheetData></worksheet>")

# A zip bomb: 1 GiB of blanks, about 1 MiB deflated.
with zipfile.ZipFile(os.path.join(out, "bomb.ods"), "w", zipfile.ZIP_DEFLATED) as z:
    z.writestr(zipfile.ZipInfo("mimetype"), ODS_MIME, compress_type=zipfile.ZIP_STORED)
    with z.open("content.xml", "w", force_zip64=True) as f:
        chunk = b" " * (1 << 20)
        for _ in range(1024):
            f.write(chunk)
# A million rows: one row repeated (ODS), and written out (XLSX, 27 MB of XML).
ods("million-rows.ods", '<table:table-row table:number-rows-repeated="1000000"><table:table-cell '
    'office:value-type="float" office:value="1"><text:p>1</text:p></table:table-cell></table:table-row>')
xlsx("million-rows.xlsx", "<row><c><v>1</v></c></row>" * 1000000)
# The most rows that fit under the 8 MiB entry limit: pugixml parses all of it.
xlsx("rows-at-entry-limit.xlsx", "<row><c><v>1</v></c></row>" * 320000)
# The most cells under the entry limit, in few rows.
xlsx("cells-at-entry-limit.xlsx", ("<row>" + "<c><v>1</v></c>" * 10000 + "</row>") * 52)
# A 100 MB string, and a 7.5 MiB one (under the entry limit, over the cell limit).
xlsx("string-100mb.xlsx", '<row><c t="s"><v>0</v></c></row>', "<sst><si><t>" + "x" * 100000000 + "</t></si></sst>")
xlsx("string-7mib.xlsx", '<row><c t="s"><v>0</v></c></row>', "<sst><si><t>" + "x" * (15 << 19) + "</t></si></sst>")
# The largest matrix 3.4 allows, as JSON for export-workbook: 128 causes, 128
# effects, 1024 intersections, every text at its longest.
import json
m = {"format": "cemv-matrix/1", "name": "BIG", "title": "t" * 80,
     "causes": [{"id": i, "name": "C%d_%s" % (i, "X" * 24), "description": "d" * 80, "function": "2oo3",
                 "tags": [{"name": "T%d_%s" % (i, k)} for k in "ABC"]} for i in range(1, 129)],
     "effects": [{"id": i, "name": "E%d" % i, "description": "e" * 80,
                  "tags": [{"name": "Y%d_%d" % (i, k)} for k in range(1, 5)]} for i in range(1, 129)],
     "intersections": [{"cause": c, "effect": e, "type": "N"} for c in range(1, 129) for e in range(1, 9)]}
json.dump(m, open(os.path.join(out, "big-matrix.json"), "w"))
for f in sorted(os.listdir(out)):
    print("%-28s %10d bytes" % (f, os.path.getsize(os.path.join(out, f))))
