#!/usr/bin/env python3
"""without_import_records.py IN OUT: the matrix IN without its import records
(provenance.imports), written to OUT as cemv-matrix/1. An import records its
own source (file name, SHA-256, reader, warnings): two imports of the same
sheet from different files, or with a layout given the second time, give the
same matrix with different records. `cemv fmt OUT` then gives its canonical
form and `cemv signature OUT` its signature."""
import json
import sys

m = json.load(open(sys.argv[1], encoding="utf-8"))
p = m.get("provenance")
if p is not None:
    p.pop("imports", None)
    if not p:
        m.pop("provenance")
json.dump(m, open(sys.argv[2], "w", encoding="utf-8"), indent=2, ensure_ascii=False)
