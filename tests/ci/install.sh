#!/usr/bin/env bash
# install.sh SOURCE BUILD TMP:
#  - `cmake --install BUILD --prefix P` installs P/bin/cemv and P/bin/cemv-gate,
#    which run, the man pages and the documentation;
#  - the slim configuration (-DCEMV_TESTS=OFF, docs/ci.md) configures the
#    tool, its man pages and its package and nothing of the tests or the
#    benchmarks: no test or benchmark target, GoogleTest and Google Benchmark
#    never looked for. (Configured only: building it is building the tool,
#    which the suite's own build has done.)
set -uo pipefail
src=$(cd "$1" && pwd) build=$(cd "$2" && pwd) tmp=$3
fail() { echo "install.sh: $*" >&2; exit 1; }
rm -rf "$tmp" && mkdir -p "$tmp" || exit 1

cmake --install "$build" --prefix "$tmp/prefix" > "$tmp/install.log" 2>&1 || { cat "$tmp/install.log"; fail "cmake --install failed"; }
for f in bin/cemv bin/cemv-gate share/man/man1/cemv.1.gz share/man/man1/cemv-gate.1.gz \
         share/doc/cemv/README.md share/doc/cemv/copyright share/doc/cemv/docs/ci.md \
         share/doc/cemv/examples/tank-overfill/matrix.json; do
  [ -f "$tmp/prefix/$f" ] || fail "not installed: $f"
done
"$tmp/prefix/bin/cemv" --version | grep -q "^cemv [0-9]" || fail "the installed cemv does not run"
CEMV="$tmp/prefix/bin/cemv" "$tmp/prefix/bin/cemv-gate" --help | grep -q "^Usage: cemv-gate" || fail "cemv-gate --help"
echo "cmake --install: $(cd "$tmp/prefix" && find . -type f | wc -l) files"

cmake -S "$src" -B "$tmp/slim" -DCMAKE_BUILD_TYPE=Release -DCEMV_TESTS=OFF -DCEMV_BENCH=OFF > "$tmp/slim.log" 2>&1 ||
  { cat "$tmp/slim.log"; fail "the slim configuration failed"; }
targets=$(cmake --build "$tmp/slim" --target help | sed -n 's/^\.\.\. //p' | cut -d' ' -f1)
for t in cemv cemv_man_pages package install; do
  echo "$targets" | grep -qx "$t" || fail "the slim build has no target $t"
done
extra=$(echo "$targets" | grep -E '^(test_|bench_|cemv_check_double|cemv_change_double|cemv_testsupport|gtest|benchmark)' | tr '\n' ' ')
[ -z "$extra" ] || fail "the slim build has test or benchmark targets: $extra"
grep -qE '^(GTest_DIR|benchmark_DIR|GTEST_)' "$tmp/slim/CMakeCache.txt" && fail "the slim configuration looked for GoogleTest or Google Benchmark"
[ -f "$tmp/slim/CTestTestfile.cmake" ] && fail "the slim configuration has tests"
echo "slim configuration: $(echo "$targets" | wc -l) targets, none of the tests or benchmarks"
