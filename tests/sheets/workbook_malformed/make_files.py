#!/usr/bin/env python3
"""make_files.py CEMV: (re)writes the workbook files of this folder's table
(EXPECTED.tsv) from the tank-overfill example, each with one defect. Files
added later (fuzzing findings) are kept as they are."""
import os, re, subprocess, sys, tempfile, zipfile

cemv = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
root = os.path.join(here, "..", "..", "..")
ODS = "application/vnd.oasis.opendocument.spreadsheet"
tmp = tempfile.mkdtemp()

def export(ext):
    path = os.path.join(tmp, "m." + ext)
    subprocess.run([cemv, "export-workbook", os.path.join(root, "examples/tank-overfill/matrix.json"), "-o", path], check=True)
    return path

def rewrite(src, name, entry, edit):
    with zipfile.ZipFile(src) as z, zipfile.ZipFile(os.path.join(here, name), "w", zipfile.ZIP_DEFLATED) as out:
        for info in z.infolist():
            data = z.read(info.filename)
            if info.filename == entry:
                data = edit(data)
            info.date_time = (2000, 1, 1, 0, 0, 0)
            out.writestr(info, data, compress_type=info.compress_type)

def ods(name, content):
    with zipfile.ZipFile(os.path.join(here, name), "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr(zipfile.ZipInfo("mimetype", (2000, 1, 1, 0, 0, 0)), ODS, compress_type=zipfile.ZIP_STORED)
        z.writestr(zipfile.ZipInfo("content.xml", (2000, 1, 1, 0, 0, 0)), content, compress_type=zipfile.ZIP_DEFLATED)

def table(rows):
    return ('<office:document-content><office:body><office:spreadsheet><table:table table:name="Causes configuration">'
            + rows + '</table:table></office:spreadsheet></office:body></office:document-content>')

xlsx, odsf = export("xlsx"), export("ods")
rewrite(xlsx, "time-not-a-number.xlsx", "xl/worksheets/sheet3.xml", lambda d: d.replace(b"<v>2000</v>", b"<v>abc</v>", 1))
rewrite(odsf, "unknown-column.ods", "content.xml",
        lambda d: d.replace(b"<text:p>Bypass tag</text:p>", b"<text:p>Bypas tag</text:p>", 1))
rewrite(xlsx, "bad-mark.xlsx", "xl/worksheets/sheet4.xml",
        lambda d: re.sub(rb'(<c r="C3" t="inlineStr"><is><t xml:space="preserve">)[^<]*', rb"\1Q", d, count=1))
rewrite(odsf, "missing-name.ods", "content.xml", lambda d: d.replace(b"<text:p>Name</text:p>", b"<text:p></text:p>", 1))
rewrite(xlsx, "shared-string-index.xlsx", "xl/worksheets/sheet1.xml",
        lambda d: d.replace(b'<c r="A2" t="inlineStr"><is><t xml:space="preserve">Name</t></is></c>', b'<c r="A2" t="s"><v>7</v></c>', 1))
open(os.path.join(here, "empty.xlsx"), "wb").close()
open(os.path.join(here, "not-a-zip.ods"), "w").write("name,title\n")
ods("broken-xml.ods", "<office:document-content><office:body>")
ods("zip-bomb.ods", " " * (64 << 20))
ods("million-rows.ods", table('<table:table-row table:number-rows-repeated="1000000"><table:table-cell '
                              'office:value-type="float" office:value="1"><text:p>1</text:p></table:table-cell></table:table-row>'))
ods("deep-spans.ods", table("<table:table-row><table:table-cell><text:p>" + "<text:span>" * 100000 + "x" +
                            "</text:span>" * 100000 + "</text:p></table:table-cell></table:table-row>"))
ods("huge-cell.ods", table('<table:table-row><table:table-cell office:value-type="string"><text:p>' + "x" * (1 << 20) +
                           "</text:p></table:table-cell></table:table-row>"))
