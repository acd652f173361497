#!/usr/bin/env bash
# generated.sh KIND CEMV: runs CEMV on an input generated at run time (too big
# or too silly to commit) and exits with CEMV's status.
#   big      a 50 MB file           -> rejected before parsing (size limit)
#   deep     100000 nested '['      -> rejected before parsing (depth limit)
#   devzero  /dev/zero (no size)    -> rejected by the read cap
#   fixpoint fmt -o of an example, then fmt of that output: identical texts
#   many-nan 400000 NaN in a matrix (2.4 MB) -> the first 20 placed, in well under a second
#   many-issues  a scenario of 160000 steps, each setting an unknown tag (14 MB) -> the same
# The last two were found by fuzzing (docs/fuzzing.md): placing each issue
# counted the line breaks before it again, quadratic in the number of issues
# (minutes of CPU for these files: about 4 and 6 on an idle machine; now
# under 3 s); their tests' TIMEOUT catches a relapse.
set -u
kind=$1 cemv=$2
dir=$(mktemp -d) || exit 99
trap 'rm -rf "$dir"' EXIT
case $kind in
  big)     { printf '['; head -c $((50 * 1024 * 1024)) /dev/zero | tr '\0' ' '; printf ']'; } > "$dir/big.json"
           "$cemv" fmt "$dir/big.json" ;;
  deep)    head -c 100000 /dev/zero | tr '\0' '[' > "$dir/deep.json"
           "$cemv" fmt "$dir/deep.json" ;;
  devzero) "$cemv" fmt /dev/zero ;;
  many-nan)
    { printf '{"format": "cemv-matrix/1", "x": [NaN'; for _ in $(seq 1 1000); do printf ',\nNaN%.0s' $(seq 1 400); done
      printf ']}\n'; } > "$dir/many-nan.json"
    "$cemv" fmt "$dir/many-nan.json" ;;
  many-issues)
    step='{"inputs": {"NO_SUCH_TAG": 1}}                                                         '
    { printf '{"format": "cemv-scenario/1", "steps": [\n%s' "$step"
      for _ in $(seq 1 1000); do printf ",\n$step%.0s" $(seq 1 160); done
      printf ']}\n'; } > "$dir/many-issues.json"
    "$cemv" simulate examples/tank-overfill/matrix.json "$dir/many-issues.json" ;;
  fixpoint)
    "$cemv" fmt examples/tank-overfill/matrix.json -o "$dir/a.json" || exit $?
    "$cemv" fmt "$dir/a.json" > "$dir/b.json" || exit $?
    cmp "$dir/a.json" "$dir/b.json" || exit 1
    [ "$("$cemv" signature "$dir/a.json")" = "$("$cemv" signature examples/tank-overfill/matrix.json)" ] || exit 1
    echo "fixed point" ;;
  *) echo "unknown kind $kind" >&2; exit 99 ;;
esac
