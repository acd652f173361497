"""check_outputs.py COMMAND OUT MATRIX: the outputs of one run of sweep.sh are
complete: the JSON parses and names every item of the run, each decided or
unknown; the files it refers to exist."""
import json
import os
import sys

command, out, matrix = sys.argv[1:4]


def load(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def fail(message):
    print("  FAIL:", message)
    sys.exit(1)


try:
    if command == "check":
        r = load(os.path.join(out, "r.json"))
        props = r["properties"]
        if not props:
            fail("no property in the report")
        for p in props:
            if p["verdict"] == "unknown" and not p.get("reason"):
                fail("unknown without a reason: " + p["name"])
        if r["interrupted"] is False and any(p.get("reason") == "time limit" for p in props):
            fail("a property unknown by the time limit in a run not interrupted")
        n = len(props)
        unknown = sum(p["verdict"] == "unknown" for p in props)
        print(f"  {n} properties, {unknown} unknown, interrupted {r['interrupted']}")
    elif command == "testgen":
        cov = load(os.path.join(out, "suite", "coverage.json"))
        objectives = cov["objectives"]
        for o in objectives:
            if o["status"] not in ("covered", "infeasible", "undecided"):
                fail("objective with status " + str(o["status"]))
        for name in ("checklist.md", "checklist.html", "checklist.csv"):
            if not os.path.isfile(os.path.join(out, "suite", name)):
                fail("no " + name)
        print(f"  {len(objectives)} objectives, {sum(o['status'] == 'undecided' for o in objectives)} undecided")
    elif command in ("response", "defeats"):
        r = load(os.path.join(out, "r.json"))
        print(f"  {len(r['paths'])} paths, interrupted {r.get('interrupted')}")
    elif command == "mutate":
        r = load(os.path.join(out, "mutants", "mutants.json"))
        for mu in r["mutants"]:
            if mu["equivalence"] not in ("equivalent", "differs", "unknown"):
                fail("mutant " + mu["id"] + " with equivalence " + str(mu["equivalence"]))
            if not os.path.isfile(os.path.join(out, "mutants", mu["file"])):
                fail("no file " + mu["file"])
        print(f"  {len(r['mutants'])} mutants, {sum(m['equivalence'] == 'unknown' for m in r['mutants'])} undecided")
    elif command == "diff":
        r = load(os.path.join(out, "r.json"))
        print(f"  exit_code {r['exit_code']}")
    elif command == "evidence":
        r = load(os.path.join(out, "r.json"))
        if not os.path.getsize(os.path.join(out, "e.html")):
            fail("empty HTML report")
        if r.get("format") != "cemv-evidence/1":
            fail("not cemv-evidence/1")
        print("  evidence written")
except (OSError, ValueError, KeyError, TypeError) as e:
    fail(f"{type(e).__name__}: {e}")
