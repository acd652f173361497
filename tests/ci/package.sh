#!/usr/bin/env bash
# package.sh BUILD TMP: the Debian package of the built tree (cpack, as
# `make package` runs it, into TMP instead of BUILD) holds a working cemv:
#  - its Version is the exact build `cemv --version` prints;
#  - unpacked into a temporary root (dpkg-deb -x), `cemv --version` and
#    `cemv check` on an installed example run (the example's verdicts as its
#    `# expect:` comments state), and so does `cemv-gate`;
#  - every shared library the binary needs (its NEEDED entries) belongs to a
#    package its Depends declares, and every library it loads resolves;
#  - the man pages hold every command.
# Builds nothing (cmake/package.cmake: packaging does not depend on the
# build): a few seconds on a built tree.
set -uo pipefail
build=$(cd "$1" && pwd) tmp=$2
fail() { echo "package.sh: $*" >&2; exit 1; }
rm -rf "$tmp" && mkdir -p "$tmp/pkg" "$tmp/root" || exit 1

(cd "$build" && cpack -G DEB -B "$tmp/pkg" > "$tmp/cpack.log" 2>&1) || { cat "$tmp/cpack.log"; fail "cpack failed"; }
debs=("$tmp"/pkg/cemv_*.deb)
if [ ${#debs[@]} != 1 ] || [ ! -f "${debs[0]}" ]; then fail "expected one cemv_*.deb, got: ${debs[*]}"; fi
deb=${debs[0]}
field() { dpkg-deb -f "$deb" "$1"; }
version=$(field Version) depends=$(field Depends)
echo "$(basename "$deb"): Version $version; Depends $depends"
[ "$("$build/cemv" --version)" = "cemv $version" ] || fail "Version $version, but the built cemv says $("$build/cemv" --version)"
if [ "$(field Package)" != cemv ] || [ -z "$(field Maintainer)" ] || [ -z "$(field Description)" ]; then
  fail "control fields"
fi

dpkg-deb -x "$deb" "$tmp/root" || fail "dpkg-deb -x failed"
bin=$tmp/root/usr/bin/cemv
if [ ! -x "$bin" ] || [ ! -x "$tmp/root/usr/bin/cemv-gate" ]; then fail "no usr/bin/cemv, usr/bin/cemv-gate"; fi
[ "$("$bin" --version)" = "cemv $version" ] || fail "the unpacked cemv says $("$bin" --version)"
[ "$(CEMV=$bin "$tmp/root/usr/bin/cemv-gate" --version)" = "cemv-gate $version" ] || fail "cemv-gate --version"

# cemv check on an example, as installed with the package.
example=$tmp/root/usr/share/doc/cemv/examples/burner-management
(cd "$example" && "$bin" check matrix.json requirements.props --expect --format junit -o "$tmp/check.junit.xml") ||
  fail "cemv check on the installed example: exit $?"
grep -q 'tests="8" failures="0" errors="0"' "$tmp/check.junit.xml" || fail "the example's JUnit report"
echo "unpacked cemv: --version, check on $(basename "$example"): 8 properties as expected"

# Every NEEDED library comes from a package Depends declares.
declared=$(echo "$depends" | tr ',' '\n' | sed 's/(.*)//; s/|.*//; s/ //g' | sort -u)
owner() {  # the package that holds a library file (usrmerge: /lib is /usr/lib)
  local f=$1 p
  for c in "$f" "$(realpath "$f")" "/usr$f" "${f#/usr}"; do
    p=$(dpkg -S "$c" 2>/dev/null | head -1 | cut -d: -f1) && [ -n "$p" ] && { echo "$p"; return 0; }
  done
  return 1
}
ldd_out=$(ldd "$bin") || fail "ldd failed"
echo "$ldd_out" | grep -q "not found" && fail "libraries not found: $(echo "$ldd_out" | grep 'not found')"
needed=$(objdump -p "$bin" | awk '$1 == "NEEDED" {print $2}')
[ -n "$needed" ] || fail "no NEEDED entries"
for lib in $needed; do
  path=$(echo "$ldd_out" | awk -v l="$lib" '$1 == l && $2 == "=>" {print $3}')
  [ -n "$path" ] || fail "$lib: not resolved by ldd"
  pkg=$(owner "$path") || fail "$lib ($path): no package holds it"
  echo "$declared" | grep -qx "$pkg" || fail "$lib ($path) is in package $pkg, which Depends does not declare"
  echo "  NEEDED $lib -> $path ($pkg, declared)"
done

# The man pages: every command of cemv --help has its section.
for page in cemv cemv-gate; do
  gzip -t "$tmp/root/usr/share/man/man1/$page.1.gz" || fail "$page.1.gz"
done
sections=$(zcat "$tmp/root/usr/share/man/man1/cemv.1.gz" | awk '$1 == ".SS" {print $2}')
for c in $("$bin" --help | awk '/^Subcommands:/{s=1;next} s&&NF{print $1}'); do
  echo "$sections" | grep -qx "$c" || fail "the man page has no section for $c"
done
for f in copyright README.md docs/ci.md docs/checker.md; do
  [ -f "$tmp/root/usr/share/doc/cemv/$f" ] || fail "no usr/share/doc/cemv/$f"
done
echo "package ok: $(basename "$deb")"
