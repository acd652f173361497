#!/usr/bin/env bash
# `cemv check --out DIR` writes NAME.svg and NAME.vcd beside each
# counterexample scenario, and every report format names them: the JSON
# (`diagram`, `waveforms`), JUnit (`diagram:`/`waveforms:` lines) and SARIF
# (message and attachments). Each named file exists and is what it says.
# usage: check_names_pictures.sh CEMV MATRIX PROPS TMPDIR
set -uo pipefail
cemv=$1 matrix=$2 props=$3 tmp=$4
rm -rf "$tmp" && mkdir -p "$tmp"
"$cemv" check "$matrix" "$props" --out "$tmp/cex" --format json -o "$tmp/r.json" \
  --report junit:"$tmp/r.xml" --report sarif:"$tmp/r.sarif" >/dev/null
[ $? -eq 1 ] || { echo "expected exit 1 (a falsified property)"; exit 1; }
python3 - "$tmp" <<'PY' || exit 1
import json, os, sys, xml.etree.ElementTree as ET
tmp = sys.argv[1]
r = json.load(open(f"{tmp}/r.json"))
named = [(p["name"], p["diagram"], p["waveforms"]) for p in r["properties"] if p["scenario"]]
assert named, "no property with a scenario"
for name, svg, vcd in named:
    assert svg and svg.endswith(".svg") and open(svg).read().startswith("<svg"), (name, svg)
    assert vcd and vcd.endswith(".vcd") and "$enddefinitions" in open(vcd).read(), (name, vcd)
for p in r["properties"]:
    if not p["scenario"]:
        assert p["diagram"] is None and p["waveforms"] is None, p["name"]
junit = "".join(ET.parse(f"{tmp}/r.xml").getroot().itertext())
sarif = json.load(open(f"{tmp}/r.sarif"))["runs"][0]["results"]
for name, svg, vcd in named:
    assert f"diagram: {svg}" in junit and f"waveforms: {vcd}" in junit, name
for res in sarif:
    p = next(p for p in r["properties"] if p["name"] == res["properties"]["property"])
    if p["diagram"]:
        assert p["diagram"] in res["message"]["text"], p["name"]
        uris = [a["artifactLocation"]["uri"] for a in res["attachments"]]
        assert uris == [p["scenario"], p["diagram"], p["waveforms"]], uris
print(f"every format names the pictures of {len(named)} runs")
PY
