#!/usr/bin/env python3
"""recipes.py SOURCE BUILD DEB WORK: the CI recipes work as written (DEB: the
package, or the folder holding it).

ci/github/action.yml: its steps run in order on the examples, as a runner
runs a composite action: each `if:` evaluated, each `run:` with bash
--noprofile --norc -eo pipefail, its `env:` expressions filled in from the
inputs, github.* and earlier steps' outputs (GITHUB_OUTPUT), and shellcheck
finding nothing in it; a run script may not hold a `${{ }}` itself (an input
spliced into shell text is an injection). A `uses:` step is an action of
GitHub's, not run here: the files it is given must be there (the SARIF and
JUnit reports, the artifact's folder) and the SARIF valid. The package is the
.deb of the suite's build (input `package`, as a package job of the same
workflow would give it). Runs: shard 1 and 2 of 2 on two examples with
--expect (exit 0, validation only in shard 1), shard 1 again (every verdict
from the verdict cache), and once with expect false (the gate fails, and so
does the action's last step).

ci/gitlab/cemv.yml: the inputs interpolated into the template as GitLab does
($[[ inputs.NAME ]]), its jobs run with bash -eo pipefail (before_script, then
script; extends merged): cemv-package with the package in its cache,
cemv-validate, and cemv-check once per parallel job (CI_NODE_INDEX,
CI_NODE_TOTAL); their images are Debian 12 images, their JUnit reports there.
"""
import glob
import json
import os
import re
import shutil
import subprocess
import sys

import yaml

from cisandbox import Sandbox

MATRICES = "examples/burner-management/matrix.json examples/pipeline-*/matrix.json"


def fail(msg):
    sys.exit(f"recipes: {msg}")


# ---- GitHub Actions -------------------------------------------------------------

def expression(expr, ctx):
    """The value of a ${{ }} expression: contexts, literals, == != && || !, always(), contains()."""
    out = []
    for token in re.findall(r"'[^']*'|[A-Za-z_][\w.-]*\(?|==|!=|&&|\|\||!|\(|\)|,|\d+", expr):
        if token.startswith("'"):
            out.append(repr(token[1:-1]))
        elif token in ("==", "!="):
            out.append(token)
        elif token == "&&":
            out.append(" and ")
        elif token == "||":
            out.append(" or ")
        elif token == "!":
            out.append(" not ")
        elif token in ("(", ")", ","):
            out.append(token)
        elif token in ("always(", "success("):
            out.append("(lambda: True)(")
        elif token == "contains(":
            out.append("(lambda a, b: b in a)(")
        elif token.isdigit():
            out.append(token)
        else:
            out.append(repr(lookup(token, ctx)))
    return eval("".join(out), {"__builtins__": {}})


def lookup(name, ctx):
    parts = name.split(".")
    if parts[0] == "inputs":
        return ctx["inputs"][parts[1]]
    if parts[0] == "github":
        return ctx["github"][parts[1]]
    if parts[0] == "steps" and parts[2] == "outputs":
        return ctx["steps"].get(parts[1], {}).get(parts[3], "")
    fail(f"an expression the test does not know: {name}")


def fill(text, ctx):
    return re.sub(r"\$\{\{(.*?)\}\}", lambda m: str(expression(m.group(1), ctx)), str(text))


def run_action(sb, action, inputs, run_id):
    ctx = {"inputs": inputs, "steps": {},
           "github": {"action_path": os.path.join(sb.source, "ci/github"), "action_ref": "", "run_id": run_id}}
    for name, spec in action["inputs"].items():
        ctx["inputs"].setdefault(name, spec.get("default", ""))
    runner_temp = os.path.join(sb.work, "runner-temp")
    os.makedirs(runner_temp, exist_ok=True)
    log = []
    for i, step in enumerate(action["runs"]["steps"]):
        sid = step.get("id", f"step{i}")
        if "if" in step and not expression(step["if"], ctx):
            continue
        if "uses" in step:
            uses_step(sb, step["uses"], {k: fill(v, ctx) for k, v in step.get("with", {}).items()}, ctx, sid)
            continue
        if step.get("shell") != "bash":
            fail(f"step {sid}: shell must be bash")
        if "${{" in step["run"]:
            fail(f"step {sid}: an expression inside the script (give it through env)")
        script = os.path.join(sb.work, f"step-{sid}.sh")
        with open(script, "w") as f:
            f.write(step["run"])
        lint = subprocess.run(["shellcheck", "-s", "bash", script], capture_output=True, text=True)
        if lint.returncode != 0:
            fail(f"step {sid}: shellcheck:\n{lint.stdout}")
        output = os.path.join(sb.work, f"output-{sid}")
        open(output, "w").close()
        env = sb.env({k: fill(v, ctx) for k, v in step.get("env", {}).items()})
        env.update({"GITHUB_OUTPUT": output, "RUNNER_TEMP": runner_temp, "HOME": os.path.join(sb.work, "home")})
        rc, out = sb.run(step["run"], sb.repo, env)
        log.append(f"-- step {sid} (exit {rc})\n{out}")
        ctx["steps"][sid] = dict(line.split("=", 1) for line in open(output).read().splitlines() if "=" in line)
        if rc != 0:
            return rc, "".join(log), ctx
    return 0, "".join(log), ctx


def uses_step(sb, uses, given, ctx, sid):
    name = uses.split("@")[0]
    if name in ("actions/cache/restore", "actions/cache/save"):
        if not given.get("key") or not given.get("path"):
            fail(f"{uses} without key or path")
        if name.endswith("restore"):
            ctx["steps"][sid] = {"cache-hit": ""}  # restored by the cemv cache of the sandbox itself
        return
    if name == "github/codeql-action/upload-sarif":
        files = glob.glob(os.path.join(sb.repo, given["sarif_file"], "*.sarif"))
        if not files:
            fail(f"upload-sarif: no SARIF file under {given['sarif_file']}")
        for f in files:
            log = json.load(open(f))
            if log.get("version") != "2.1.0" or len(log["runs"]) != 1:
                fail(f"upload-sarif: {f} is not SARIF 2.1.0 with one run")
        return
    if name == "mikepenz/action-junit-report":
        if not glob.glob(os.path.join(sb.repo, given["report_paths"])):
            fail(f"action-junit-report: nothing matches {given['report_paths']}")
        return
    if name == "actions/upload-artifact":
        if not os.path.isdir(os.path.join(sb.repo, given["path"])) or not given.get("name"):
            fail(f"upload-artifact: no folder {given['path']}")
        return
    fail(f"a step uses {uses}, which the test does not know")


def github(sb, deb):
    action = yaml.safe_load(open(os.path.join(sb.source, "ci/github/action.yml")))
    if action["runs"]["using"] != "composite":
        fail("ci/github/action.yml is not a composite action")
    base = {"matrices": MATRICES, "package": deb, "shards": "2", "formats": "junit sarif json", "jobs": "1"}
    reports = os.path.join(sb.repo, "cemv-reports")
    for shard in ("1", "2"):
        rc, log, ctx = run_action(sb, action, dict(base, shard=shard), "1")
        if rc != 0 or ctx["steps"]["gate"].get("exit-code") != "0":
            print(log)
            fail(f"the action, shard {shard}: exit {rc}")
        has_validation = os.path.exists(os.path.join(reports, "validation.sarif"))
        if has_validation != (shard == "1"):
            fail(f"shard {shard}: the validation reports {'missing' if shard == '1' else 'written'}")
        if "from the cache" in log:
            fail(f"shard {shard}: verdicts from the cache on its first run")
        shutil.rmtree(reports)
        print(f"github action, shard {shard} of 2: exit 0")
    rc, log, ctx = run_action(sb, action, dict(base, shard="1"), "2")
    if rc != 0 or not re.search(r"; \d+ from the cache;|\d+ from the cache", log):
        print(log)
        fail("the action's second run of shard 1 took nothing from the verdict cache")
    print("github action, shard 1 again: verdicts from the cache, exit 0")
    shutil.rmtree(reports)
    rc, log, ctx = run_action(sb, action, dict(base, shard="1", expect="false"), "3")
    if rc == 0 or ctx["steps"]["gate"].get("exit-code") != "1":
        print(log)
        fail(f"with expect false the seeded defects must fail the action: exit {rc}")
    print("github action, expect false: the gate and the action fail (exit 1)")


# ---- GitLab CI -------------------------------------------------------------------

def interpolate(text, inputs):
    def value(m):
        v = inputs[m.group(1)]
        return ("true" if v else "false") if isinstance(v, bool) else str(v)
    return re.sub(r"\$\[\[\s*inputs\.([\w-]+)\s*\]\]", value, text)


def gitlab(sb, deb):
    text = open(os.path.join(sb.source, "ci/gitlab/cemv.yml")).read()
    header, body = text.split("\n---\n", 1)
    spec = yaml.safe_load(header)["spec"]["inputs"]
    inputs = {"matrices": MATRICES, "shards": 2, "cemv-repository": "https://gitlab.example.com/ORG/cemv.git",
              "cemv-ref": "v0.1.0"}
    for name, s in spec.items():
        if name not in inputs:
            if "default" not in (s or {}):
                fail(f"the test gives no value for the required input {name}")
            inputs[name] = s["default"]
    jobs = yaml.safe_load(interpolate(body, inputs))
    if "$[[" in json.dumps(jobs):
        fail("an input is not interpolated")

    def job(name):
        j = dict(jobs[name])
        if "extends" in j:
            base = dict(jobs[j.pop("extends")])
            base.update(j)
            j = base
        return j

    # cemv-package, with the package in its cache: nothing to build.
    os.makedirs(os.path.join(sb.repo, ".cemv-package"), exist_ok=True)
    shutil.copy(deb, os.path.join(sb.repo, ".cemv-package"))
    runs = [("cemv-package", {})]
    runs.append(("cemv-validate", {}))
    shards = job("cemv-check").get("parallel", 1)
    if shards != 2:
        fail(f"cemv-check: parallel {shards!r}, expected the shards input (2)")
    for i in range(1, shards + 1):
        runs.append(("cemv-check", {"CI_NODE_INDEX": str(i), "CI_NODE_TOTAL": str(shards)}))
    for name, node in runs:
        j = job(name)
        if j.get("image") not in ("debian:12", "debian:12-slim"):
            fail(f"{name}: image {j.get('image')}, expected a Debian 12 image")
        script = "\n".join(j.get("before_script", []) + j["script"]) + "\n"
        env = sb.env(dict({k: str(v) for k, v in j.get("variables", {}).items()}, CI_PROJECT_DIR=sb.repo, **node))
        shutil.rmtree(sb.root)
        os.makedirs(sb.root)
        rc, out = sb.run(script, sb.repo, env)
        if rc != 0:
            print(out)
            fail(f"{name} {node}: exit {rc}")
        junit = j.get("artifacts", {}).get("reports", {}).get("junit")
        if junit and not glob.glob(os.path.join(sb.repo, junit)):
            fail(f"{name}: no JUnit report matches {junit}")
        for path in j.get("artifacts", {}).get("paths", []):
            if not os.path.exists(os.path.join(sb.repo, path)):
                fail(f"{name}: artifact path {path} missing")
        print(f"gitlab job {name} {' '.join(f'{k}={v}' for k, v in node.items())}: exit 0")


def main():
    source, build, deb, work = sys.argv[1:5]
    if os.path.isdir(deb):  # the folder the package test wrote it to
        debs = glob.glob(os.path.join(deb, "cemv_*.deb"))
        if len(debs) != 1:
            fail(f"expected one cemv_*.deb in {deb}, found {debs}")
        deb = debs[0]
    deb = os.path.abspath(deb)
    sb = Sandbox(source, build, os.path.join(work, "github"))
    github(sb, deb)
    sb = Sandbox(source, build, os.path.join(work, "gitlab"))
    gitlab(sb, deb)
    print("the CI recipes work as written")


if __name__ == "__main__":
    main()
