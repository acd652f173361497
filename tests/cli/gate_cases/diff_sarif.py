#!/usr/bin/env python3
"""diff_sarif.py CEMV OLD NEW OUT: `cemv diff OLD NEW --format sarif -o OUT`
exits as the text format does and writes SARIF 2.1.0 with a result for each
structural change at the line of its element in NEW, and one for each effect
whose behaviour changed at that effect's line, documentation URIs relative
to the repository.
"""
import json
import re
import subprocess
import sys


def element_at(lines, line):
    """The id fields of the JSON object starting at `line` (1-based)."""
    text = "\n".join(lines[line - 1:line + 40])
    depth, end = 0, 0
    for i, ch in enumerate(text):
        depth += ch == "{"
        depth -= ch == "}"
        if depth == 0 and ch == "}":
            end = i
            break
    obj = json.loads(text[:end + 1])
    return {k: obj[k] for k in ("id", "cause", "effect") if k in obj}


def main():
    cemv, old, new, out = sys.argv[1:5]
    rc = subprocess.run([cemv, "diff", old, new, "--format", "sarif", "-o", out]).returncode
    text_rc = subprocess.run([cemv, "diff", old, new], stdout=subprocess.DEVNULL).returncode
    if rc != text_rc:
        sys.exit(f"exit {rc} with --format sarif, {text_rc} with text")
    cemv_diff = json.loads(subprocess.run([cemv, "diff", old, new, "--format", "json"],
                                          capture_output=True, text=True).stdout)
    log = json.load(open(out))
    assert log["version"] == "2.1.0"
    run = log["runs"][0]
    driver = run["tool"]["driver"]
    for uri in [driver["informationUri"]] + [r["helpUri"] for r in driver["rules"]]:
        if re.match(r"^[a-z]+:", uri) or not uri.endswith(".md"):
            sys.exit(f"{uri} is not a relative URI of a documentation file")
    rules = [r["id"] for r in driver["rules"]]
    lines = open(new, encoding="utf-8").read().split("\n")
    changes = cemv_diff["structural"]["changes"]
    changed = [e for e in cemv_diff["semantic"]["effects"] if e["verdict"] != "equivalent"]
    results = run["results"]
    if len(results) != len(changes) + len(changed):
        sys.exit(f"{len(results)} results for {len(changes)} changes and {len(changed)} changed effects")
    for res, change in zip(results, changes):
        assert rules[res["ruleIndex"]] == res["ruleId"]
        loc = res["locations"][0]["physicalLocation"]
        assert loc["artifactLocation"]["uri"] == new, loc
        found = element_at(lines, loc["region"]["startLine"])
        want = change["new"] if change["element"] == "intersection" else {"id": change["new_id"]}
        if found != want:
            sys.exit(f"{change['label']} placed at line {loc['region']['startLine']}, which is {found}")
    for res, effect in zip(results[len(changes):], changed):
        assert res["ruleId"] == "CEMV-DIFF-BEHAVIOUR", res["ruleId"]
        line = res["locations"][0]["physicalLocation"]["region"]["startLine"]
        if element_at(lines, line) != {"id": effect["new_id"]}:
            sys.exit(f"effect {effect['new_id']} placed at line {line}")
    print(f"{len(results)} results at the changed lines of {new}")


if __name__ == "__main__":
    main()
