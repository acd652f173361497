#!/usr/bin/env bash
# generated.sh KIND CEMV: runs CEMV on an input generated at run time (too big
# or too silly to commit) and exits with CEMV's status.
#   big      a 50 MB file           -> rejected before parsing (size limit)
#   deep     100000 nested '['      -> rejected before parsing (depth limit)
#   devzero  /dev/zero (no size)    -> rejected by the read cap
#   fixpoint fmt -o of an example, then fmt of that output: identical texts
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
  fixpoint)
    "$cemv" fmt examples/tank-overfill/matrix.json -o "$dir/a.json" || exit $?
    "$cemv" fmt "$dir/a.json" > "$dir/b.json" || exit $?
    cmp "$dir/a.json" "$dir/b.json" || exit 1
    [ "$("$cemv" signature "$dir/a.json")" = "$("$cemv" signature examples/tank-overfill/matrix.json)" ] || exit 1
    echo "fixed point" ;;
  *) echo "unknown kind $kind" >&2; exit 99 ;;
esac
