#!/usr/bin/env python3
"""related_locations.py SARIF MATRIX PROPERTY CELL...

The SARIF result of PROPERTY (falsified) has, besides its location in the
property file, a related location in MATRIX for each CELL ("2,1": the
intersection of cause 2 and effect 1), at the line where that intersection's
object starts in the file, and no other.
"""
import json
import re
import sys


def main():
    sarif, matrix, prop, cells = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    lines = open(matrix, encoding="utf-8").read().split("\n")
    results = [r for r in json.load(open(sarif))["runs"][0]["results"] if r["properties"]["property"] == prop]
    if len(results) != 1:
        sys.exit(f"{len(results)} results for {prop}")
    r = results[0]
    if r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] == matrix:
        sys.exit("the result itself is placed in the matrix, not at the property")
    related = r.get("relatedLocations", [])
    if len(related) != len(cells):
        sys.exit(f"{len(related)} related locations, expected {len(cells)}: {related}")
    for rel, cell in zip(related, cells):
        cause, effect = cell.split(",")
        phys = rel["physicalLocation"]
        if phys["artifactLocation"]["uri"] != matrix:
            sys.exit(f"related location in {phys['artifactLocation']['uri']}, not {matrix}")
        line = phys["region"]["startLine"]
        obj = "\n".join(lines[line - 1:line + 8])
        if not re.search(rf'"cause": {cause},', obj) or not re.search(rf'"effect": {effect},', obj):
            sys.exit(f"line {line} of {matrix} is not intersection {cell}:\n{obj}")
        if f"intersection[{cell}]" not in rel["message"]["text"]:
            sys.exit(f"the related location does not name intersection[{cell}]")
    print(f"{prop}: related locations at the lines of {', '.join(cells)}")


if __name__ == "__main__":
    main()
