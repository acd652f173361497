#!/usr/bin/env python3
"""Supplies the maximum override time the LSST grids lack, as a user would
(docs/change-acceptance.md, "The LSST pair"): every effect with a V or R
intersection gets "override": {"max_s": 600, "prealarm_s": 540} in the
imported cemv-matrix/1 file, which is rewritten in place.
usage: lsst_supply_override.py MATRIX.json"""
import json
import sys

path = sys.argv[1]
with open(path) as f:
    m = json.load(f)
needs = {x["effect"] for x in m["intersections"] if x["type"] in ("V", "R")}
for e in m["effects"]:
    if e["id"] in needs and not e.get("override"):
        e["override"] = {"max_s": 600, "prealarm_s": 540}
with open(path, "w") as f:
    json.dump(m, f, indent=1)
    f.write("\n")
print(f"{path}: override 600 s / prealarm 540 s supplied for effects {sorted(needs)}")
