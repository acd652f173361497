#!/usr/bin/env python3
"""check_simulate_json.py CEMV MATRIX PASSING FAILING: `cemv simulate
--format json` writes cemv-simulation/1 (docs/scenario.md): the matrix name
and signature, the scenario file, each step with its expectations (expected,
observed, pass) and the verdict; the exit status agrees with the verdict."""
import json
import subprocess
import sys

cemv, matrix, passing, failing = sys.argv[1:5]


def simulate(scenario):
    p = subprocess.run([cemv, "simulate", matrix, scenario, "--format", "json"], capture_output=True, text=True)
    return p.returncode, json.loads(p.stdout)


sig = subprocess.run([cemv, "signature", matrix], capture_output=True, text=True).stdout.strip()
rc, j = simulate(passing)
assert rc == 0 and j["verdict"] == "PASS", (rc, j["verdict"])
assert j["format"] == "cemv-simulation/1"
assert j["matrix"] == "CH13_CAUSES" and j["signature"] == sig
assert j["scenario"] == passing and j["matrix_file"] == matrix
assert j["failed"] == 0 and j["expectations"] == sum(len(s["expectations"]) for s in j["steps"])
for s in j["steps"]:
    assert set(s) >= {"step", "cycle", "t_ms", "expectations"}
    for x in s["expectations"]:
        assert set(x) == {"key", "expected", "observed", "pass"} and x["pass"] is True
rc, j = simulate(failing)
assert rc == 1 and j["verdict"] == "FAIL" and j["failed"] >= 1
bad = [x for s in j["steps"] for x in s["expectations"] if not x["pass"]]
assert bad and bad[0]["key"] == "cause[1].active" and bad[0]["expected"] is True and bad[0]["observed"] is False
print("simulate json ok")
