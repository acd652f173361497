#!/usr/bin/env python3
"""docs_ci.py SOURCE BUILD WORK: every command of docs/ci.md runs.

Each ```sh block runs, in order, with bash -eo pipefail (as a CI runner runs a
script), in the folder its first line names: "# In cemv's source tree" (a
checkout of cemv whose build-slim is the suite's own built tree, so that
scripts/build-package packages it instead of compiling everything again) or
"# In the repository of the matrices" (a git repository holding a copy of the
examples), with the stand-ins of tests/ci/cisandbox.py for sudo and apt-get.
Every block must succeed. Each ```yaml block is a pipeline that uses a recipe:
every input it gives must be one of the recipe's (ci/github/action.yml,
ci/gitlab/cemv.yml), every required input given. Any other block fails the
test, so a command cannot be added to the page without being run.
"""
import os
import re
import sys

import yaml

from cisandbox import Sandbox


def fail(msg):
    sys.exit(f"docs_ci: {msg}")


def check_github(doc, source):
    action = yaml.safe_load(open(os.path.join(source, "ci/github/action.yml")))
    inputs = action["inputs"]
    uses = 0
    for job in doc["jobs"].values():
        for step in job.get("steps", []):
            if "run" in step:
                fail("a workflow step in docs/ci.md runs a command: write it as a shell block")
            if not re.match(r"^ORG/cemv/ci/github@", step.get("uses", "")):
                continue
            uses += 1
            given = step.get("with", {})
            for name in given:
                if name not in inputs:
                    fail(f"the workflow gives the action an input it does not have: {name}")
            for name, spec in inputs.items():
                if spec.get("required") and name not in given:
                    fail(f"the workflow does not give the action its required input {name}")
    if not uses:
        fail("a workflow that does not use ci/github")
    return f"workflow: {uses} use of ci/github, inputs known"


def check_gitlab(doc, source):
    spec = next(yaml.safe_load_all(open(os.path.join(source, "ci/gitlab/cemv.yml"))))["spec"]["inputs"]
    included = [i for i in doc["include"] if i.get("file") == "ci/gitlab/cemv.yml"]
    if len(included) != 1:
        fail("the GitLab example does not include ci/gitlab/cemv.yml once")
    given = included[0].get("inputs", {})
    for name in given:
        if name not in spec:
            fail(f"the GitLab example gives the template an input it does not have: {name}")
    for name, s in spec.items():
        if "default" not in (s or {}) and name not in given:
            fail(f"the GitLab example does not give the template its required input {name}")
    return f"include: ci/gitlab/cemv.yml, {len(given)} inputs known"


def main():
    source, build, work = sys.argv[1:4]
    sb = Sandbox(source, build, work)
    # A checkout of cemv: its scripts, and the suite's build as build-slim.
    checkout = os.path.join(sb.work, "cemv")
    os.makedirs(checkout)
    os.symlink(os.path.join(sb.source, "scripts"), os.path.join(checkout, "scripts"))
    os.symlink(sb.build, os.path.join(checkout, "build-slim"))

    text = open(os.path.join(source, "docs/ci.md"), encoding="utf-8").read()
    blocks = re.findall(r"^```([^\n]*)\n(.*?)^```$", text, re.M | re.S)
    if not blocks:
        fail("docs/ci.md has no blocks")
    ran = checked = 0
    for lang, body in blocks:
        if lang == "sh":
            first = body.strip().splitlines()[0]
            if first.startswith("# In cemv's source tree"):
                cwd = checkout
            elif first.startswith("# In the repository of the matrices"):
                cwd = sb.repo
                if not sb.installed():
                    fail("a block uses cemv before the page has installed it")
            else:
                fail(f"a shell block that does not say where it runs: {first!r}")
            rc, out = sb.run(body, cwd)
            print(f"$ ({os.path.basename(cwd)})\n{body}{out}")
            if rc != 0:
                fail(f"exit status {rc} of the block above")
            ran += 1
        elif lang == "yaml":
            doc = yaml.safe_load(body)
            if "jobs" in doc:
                print(check_github(doc, source))
            elif "include" in doc:
                print(check_gitlab(doc, source))
            else:
                fail("a yaml block that is neither a workflow nor a GitLab include")
            checked += 1
        else:
            fail(f"a ```{lang} block: docs/ci.md holds only sh and yaml blocks")
    for f in ("reports/validation.sarif", "reports/burner.shard-1-of-2.junit.xml",
              "reports/burner.shard-1-of-2.sarif", "reports/tank-overfill.diff.sarif",
              "reports/examples-pipeline-hipps-matrix.shard-1-of-2.junit.xml"):
        if not os.path.isfile(os.path.join(sb.repo, f)):
            fail(f"the page's commands did not write {f}")
    print(f"docs/ci.md: {ran} shell blocks run, {checked} pipelines checked")


if __name__ == "__main__":
    main()
