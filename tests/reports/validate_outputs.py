#!/usr/bin/env python3
"""Checks a `cemv check` output file as its consumers read it.

  validate_outputs.py junit FILE TESTS FAILURES ERRORS
      parses as XML (xml.etree), one <testsuite>, the counts in its attributes
      equal the counted <testcase>, <failure> and <error> elements and the
      expected numbers.
  validate_outputs.py sarif FILE RESULTS
      the fields SARIF 2.1.0's schema requires, with their types and ranges,
      plus what code-scanning views rely on (rule ids resolvable, locations
      with a line, the matrix element named in message and logical location).
  validate_outputs.py json FILE PROPERTIES
      cemv-result/1: every documented field present with its type.
Exit 0 when it holds, 1 with a message otherwise.
"""
import json
import sys
import xml.etree.ElementTree as ET
from urllib.parse import urlparse


def fail(msg):
    print(f"validate_outputs: {msg}", file=sys.stderr)
    sys.exit(1)


def need(cond, msg):
    if not cond:
        fail(msg)


def check_junit(path, tests, failures, errors):
    root = ET.parse(path).getroot()
    need(root.tag == "testsuites", f"root is <{root.tag}>, expected <testsuites>")
    suites = root.findall("testsuite")
    need(len(suites) == 1, f"{len(suites)} testsuites, expected 1")
    suite = suites[0]
    cases = suite.findall("testcase")
    n_fail = sum(len(c.findall("failure")) for c in cases)
    n_err = sum(len(c.findall("error")) for c in cases)
    for el in (root, suite):
        need(int(el.get("tests")) == len(cases), f"<{el.tag}> tests={el.get('tests')} but {len(cases)} testcases")
        need(int(el.get("failures")) == n_fail, f"<{el.tag}> failures={el.get('failures')} but {n_fail}")
        need(int(el.get("errors")) == n_err, f"<{el.tag}> errors={el.get('errors')} but {n_err}")
    need((len(cases), n_fail, n_err) == (tests, failures, errors),
         f"(tests, failures, errors) = {(len(cases), n_fail, n_err)}, expected {(tests, failures, errors)}")
    for c in cases:
        need(c.get("name") and c.get("classname"), "a testcase without name or classname")
        for f in c.findall("failure") + c.findall("error"):
            need(f.get("message") and f.get("type"), f"testcase {c.get('name')}: failure without message/type")
    for el in root.iter():
        need("time" not in el.attrib and "timestamp" not in el.attrib, "times in JUnit output")


def is_str(x):
    return isinstance(x, str) and x != ""


def check_sarif(path, n_results):
    log = json.load(open(path, encoding="utf-8"))
    need(log.get("version") == "2.1.0", "version is not 2.1.0")
    need(is_str(log.get("$schema")) and "2.1.0" in log["$schema"], "$schema missing or not 2.1.0")
    runs = log.get("runs")
    need(isinstance(runs, list) and len(runs) == 1, "runs must be an array of one run")
    run = runs[0]
    driver = run.get("tool", {}).get("driver")
    need(isinstance(driver, dict), "runs[0].tool.driver missing")
    need(driver.get("name") == "cemv", "driver.name")
    need(is_str(driver.get("version")), "driver.version")
    # The documentation in cemv's repository, as URIs relative to its root
    # (docs/checker.md, "sarif"): never an invented host.
    def relative_doc(u, what):
        uri = urlparse(u or "")
        need(not uri.scheme and not uri.netloc and uri.path.endswith(".md"),
             f"{what} {u!r} is not a relative URI of a documentation file")
    relative_doc(driver.get("informationUri"), "driver.informationUri")
    rules = driver.get("rules")
    need(isinstance(rules, list) and rules, "driver.rules")
    ids = [r.get("id") for r in rules]
    need(all(is_str(i) for i in ids) and len(set(ids)) == len(ids), "rule ids missing or repeated")
    for r in rules:
        need(is_str(r.get("shortDescription", {}).get("text")), f"rule {r['id']}: shortDescription.text")
        if "helpUri" in r:
            relative_doc(r["helpUri"], f"rule {r['id']}: helpUri")
    results = run.get("results")
    need(isinstance(results, list), "runs[0].results must be an array")
    need(len(results) == n_results, f"{len(results)} results, expected {n_results}")
    for i, res in enumerate(results):
        where = f"results[{i}]"
        need(is_str(res.get("message", {}).get("text")), f"{where}.message.text")
        need(res.get("ruleId") in ids, f"{where}.ruleId {res.get('ruleId')!r} is not a rule")
        if "ruleIndex" in res:
            need(ids[res["ruleIndex"]] == res["ruleId"], f"{where}.ruleIndex does not match ruleId")
        need(res.get("level") in ("none", "note", "warning", "error"), f"{where}.level")
        locs = res.get("locations")
        need(isinstance(locs, list) and locs, f"{where}.locations")
        for loc in locs:
            phys = loc.get("physicalLocation")
            need(isinstance(phys, dict), f"{where}: physicalLocation")
            need(is_str(phys.get("artifactLocation", {}).get("uri")), f"{where}: artifactLocation.uri")
            need(" " not in phys["artifactLocation"]["uri"], f"{where}: uri not encoded")
            if "region" in phys:
                reg = phys["region"]
                need(isinstance(reg.get("startLine"), int) and reg["startLine"] >= 1, f"{where}: region.startLine")
                need(isinstance(reg.get("startColumn", 1), int) and reg.get("startColumn", 1) >= 1,
                     f"{where}: region.startColumn")
            logical = loc.get("logicalLocations")
            need(isinstance(logical, list) and logical, f"{where}: logicalLocations")
            for ll in logical:
                need(is_str(ll.get("name")), f"{where}: logicalLocations[].name")
                need(ll["name"] in res["message"]["text"], f"{where}: message does not name {ll['name']}")
        for rel in res.get("relatedLocations", []):
            phys = rel.get("physicalLocation", {})
            need(is_str(phys.get("artifactLocation", {}).get("uri")), f"{where}: relatedLocations[].uri")
            need(isinstance(phys.get("region", {}).get("startLine"), int) and phys["region"]["startLine"] >= 1,
                 f"{where}: relatedLocations[].region.startLine")
            need(is_str(rel.get("message", {}).get("text")), f"{where}: relatedLocations[].message.text")


PROPERTY_FIELDS = {
    "name": str, "description": str, "kind": str, "file": (str, type(None)),
    "line": (int, type(None)), "column": (int, type(None)), "verdict": str,
    "method": (str, type(None)), "depth": int, "reason": (str, type(None)), "notes": list,
    "elements": list, "support": list, "support_minimal": (bool, type(None)),
    "invariant": (str, type(None)), "scenario": (str, type(None)),
    "diagram": (str, type(None)), "waveforms": (str, type(None)),
    "violation_cycle": (int, type(None)), "expected": (str, type(None)),
}
VERDICTS = ("proved", "falsified", "reachable", "unreachable", "vacuous", "unknown")


def check_json(path, n_props):
    j = json.load(open(path, encoding="utf-8"))
    need(j.get("format") == "cemv-result/1", "format is not cemv-result/1")
    for key, typ in (("tool", dict), ("matrix", dict), ("property_files", list), ("standard", bool),
                     ("interrupted", bool), ("summary", dict), ("properties", list), ("unsupported", list)):
        need(isinstance(j.get(key), typ), f"field {key}")
    need("shard" in j, "field shard")
    need(j.get("support_mode") in ("off", "core", "full"), "field support_mode")
    need(is_str(j["matrix"].get("name")) and len(j["matrix"].get("signature", "")) == 64, "matrix name/signature")
    need(len(j["properties"]) == n_props, f"{len(j['properties'])} properties, expected {n_props}")
    need(j["summary"]["properties"] == n_props, "summary.properties")
    for v in VERDICTS:
        need(j["summary"][v] == sum(p["verdict"] == v for p in j["properties"]), f"summary.{v}")
    for p in j["properties"]:
        for key, typ in PROPERTY_FIELDS.items():
            need(key in p and isinstance(p[key], typ), f"property {p.get('name')}: field {key}")
        need(p["verdict"] in VERDICTS, f"property {p['name']}: verdict {p['verdict']}")


def main():
    if len(sys.argv) < 3:
        fail(__doc__)
    kind, path, nums = sys.argv[1], sys.argv[2], [int(x) for x in sys.argv[3:]]
    try:
        {"junit": check_junit, "sarif": check_sarif, "json": check_json}[kind](path, *nums)
    except (ET.ParseError, json.JSONDecodeError, OSError, KeyError, TypeError) as e:
        fail(f"{path}: {type(e).__name__}: {e}")
    print(f"{path}: valid {kind}")


if __name__ == "__main__":
    main()
