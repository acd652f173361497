"""What the tests of the CI recipes share (tests/ci/docs_ci.py, recipes.py):
a sandbox in which the commands of docs/ci.md, ci/github/action.yml and
ci/gitlab/cemv.yml run as a pipeline would run them, on the examples.

The only stand-ins are for what a test may not do to the machine it runs on:
`sudo` runs its command, and `apt-get install ./cemv_*.deb` unpacks the
package into a temporary root whose usr/bin is on the PATH (dpkg-deb -x),
after checking, as apt-get would, that every package its Depends names is
installed; `apt-get update` does nothing, and any other package asked for must
already be installed. Everything else runs as written.
"""
import os
import shutil
import subprocess
import tempfile

APT_GET = r"""#!/usr/bin/env bash
# apt-get as the CI recipe tests run it (tests/ci/cisandbox.py).
set -euo pipefail
root=${CEMV_TEST_ROOT:?}
command=""
for a in "$@"; do
  case "$a" in -*) ;; *) [ -n "$command" ] || command=$a ;; esac
done
case "$command" in
  update) exit 0 ;;
  install) ;;
  *) echo "apt-get (test): '$command' is not run by the tests" >&2; exit 100 ;;
esac
for a in "$@"; do
  case "$a" in
    install|-*) ;;
    */*.deb)
      [ -f "$a" ] || { echo "E: Unsupported file $a given on commandline" >&2; exit 100; }
      for dep in $(dpkg-deb -f "$a" Depends | tr ',' '\n' | sed 's/(.*)//; s/|.*//'); do
        [ "$(dpkg-query -W -f='${Status}' "$dep" 2>/dev/null)" = "install ok installed" ] ||
          { echo "apt-get (test): $a depends on $dep, which is not installed" >&2; exit 100; }
      done
      dpkg-deb -x "$a" "$root"
      echo "apt-get (test): unpacked $(dpkg-deb -f "$a" Package) $(dpkg-deb -f "$a" Version) into $root" ;;
    *)
      [ "$(dpkg-query -W -f='${Status}' "$a" 2>/dev/null)" = "install ok installed" ] ||
        { echo "E: Unable to locate package $a" >&2; exit 100; } ;;
  esac
done
"""

SUDO = """#!/usr/bin/env bash
exec "$@"
"""


class Sandbox:
    def __init__(self, source, build, work):
        self.source = os.path.abspath(source)
        self.build = os.path.abspath(build)
        self.work = os.path.abspath(work)
        shutil.rmtree(self.work, ignore_errors=True)
        self.root = os.path.join(self.work, "root")        # where the package is "installed"
        self.shims = os.path.join(self.work, "shims")
        self.repo = os.path.join(self.work, "plant-repo")  # the repository of the matrices
        for d in (self.root, self.shims, self.repo):
            os.makedirs(d)
        for name, text in (("apt-get", APT_GET), ("sudo", SUDO)):
            path = os.path.join(self.shims, name)
            with open(path, "w") as f:
                f.write(text)
            os.chmod(path, 0o755)
        # The examples as a repository of matrices under git (cemv diff's base).
        shutil.copytree(os.path.join(self.source, "examples"), os.path.join(self.repo, "examples"))
        git = ["git", "-C", self.repo, "-c", "user.name=test", "-c", "user.email=test@localhost"]
        for args in (["init", "-q"], ["add", "-A"], ["commit", "-q", "-m", "examples"]):
            subprocess.run(git + args, check=True)

    def env(self, extra=None):
        e = dict(os.environ)
        e["PATH"] = os.pathsep.join([self.shims, os.path.join(self.root, "usr", "bin"), e["PATH"]])
        e["CEMV_TEST_ROOT"] = self.root
        e.pop("CEMV", None)
        if extra:
            e.update(extra)
        return e

    def installed(self):
        return os.path.exists(os.path.join(self.root, "usr", "bin", "cemv"))

    def run(self, script, cwd, env=None, shell=("bash", "--noprofile", "--norc", "-eo", "pipefail")):
        """Runs a script as a CI runner does; returns (exit status, output)."""
        with tempfile.NamedTemporaryFile("w", suffix=".sh", dir=self.work, delete=False) as f:
            f.write(script)
        p = subprocess.run(list(shell) + [f.name], cwd=cwd, env=env or self.env(), text=True,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        return p.returncode, p.stdout
