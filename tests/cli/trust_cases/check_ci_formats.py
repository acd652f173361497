#!/usr/bin/env python3
"""check_ci_formats.py CEMV FILE...: `cemv validate FILE... --format sarif`
has every field the SARIF 2.1.0 schema requires (sarifLog, run, tool,
toolComponent, reportingDescriptor, result, message, location,
physicalLocation, artifactLocation, region) with the types it requires, rules
from the validation catalogue and results located in their files; `--format
junit` parses as XML with one testsuite per file and one testcase per rule."""
import json
import subprocess
import sys
import xml.etree.ElementTree as ET

cemv, files = sys.argv[1], sys.argv[2:]


def run(fmt):
    p = subprocess.run([cemv, "validate", *files, "--format", fmt], capture_output=True, text=True)
    assert p.returncode == 2, f"{fmt}: exit {p.returncode} (one file is unreadable)"
    return p.stdout


def require(obj, key, kind, where):
    assert isinstance(obj, dict), f"{where} is not an object"
    assert key in obj, f"{where}.{key} is missing"
    assert isinstance(obj[key], kind), f"{where}.{key} is not {kind}"
    return obj[key]


log = json.loads(run("sarif"))
assert require(log, "version", str, "log") == "2.1.0"
assert log.get("$schema", "").endswith("sarif-2.1.0.json")
runs = require(log, "runs", list, "log")
assert len(runs) == 1
run0 = runs[0]
driver = require(require(run0, "tool", dict, "run"), "driver", dict, "tool")
require(driver, "name", str, "driver")
rules = require(driver, "rules", list, "driver")
catalogue = {r["id"] for r in rules}
for i, r in enumerate(rules):
    require(r, "id", str, f"rules[{i}]")
    require(require(r, "shortDescription", dict, f"rules[{i}]"), "text", str, f"rules[{i}].shortDescription")
    require(require(r, "help", dict, f"rules[{i}]"), "text", str, f"rules[{i}].help")
    assert "section" in r.get("properties", {}), f"rules[{i}] has no manual section"
assert "E-DUPLICATE-CAUSE-ID" in catalogue and "E-INTERSECTION-X" in catalogue and "E-LOAD" in catalogue
results = require(run0, "results", list, "run")
seen_files = set()
for i, res in enumerate(results):
    where = f"results[{i}]"
    require(require(res, "message", dict, where), "text", str, where + ".message")
    rule = require(res, "ruleId", str, where)
    assert rule in catalogue, f"{where}: rule {rule} is not in the driver's rules"
    idx = res.get("ruleIndex")
    assert idx is None or rules[idx]["id"] == rule, f"{where}: ruleIndex points at another rule"
    assert res.get("level") in ("error", "warning", "note", "none")
    locs = require(res, "locations", list, where)
    phys = require(locs[0], "physicalLocation", dict, where + ".locations[0]")
    uri = require(require(phys, "artifactLocation", dict, where), "uri", str, where)
    region = require(phys, "region", dict, where)
    assert isinstance(region.get("startLine"), int) and region["startLine"] >= 1
    assert isinstance(region.get("startColumn"), int) and region["startColumn"] >= 1
    seen_files.add(uri)
    if rule == "E-DUPLICATE-CAUSE-ID":
        assert region["startLine"] == 7 and region["startColumn"] == 5, f"{where}: {region}"
assert any(f.endswith("errors.json") for f in seen_files)
assert "no/such.json" in seen_files

root = ET.fromstring(run("junit"))
assert root.tag == "testsuites"
suites = root.findall("testsuite")
assert [s.get("name") for s in suites] == files, [s.get("name") for s in suites]
for s in suites:
    cases = s.findall("testcase")
    assert int(s.get("tests")) == len(cases)
    assert int(s.get("failures")) == sum(1 for c in cases if c.find("failure") is not None)
dup = [s for s in suites if s.get("name").endswith("duplicate_id.json")][0]
failing = [c.get("name") for c in dup.findall("testcase") if c.find("failure") is not None]
assert "E-DUPLICATE-CAUSE-ID" in failing, failing
names = [c.get("name") for c in dup.findall("testcase")]
assert len(names) == len(set(names)) and len(names) >= len(catalogue) - 1
missing = [s for s in suites if s.get("name") == "no/such.json"][0]
assert missing.find("testcase/error") is not None
print("sarif and junit valid")
