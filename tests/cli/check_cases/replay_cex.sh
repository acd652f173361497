#!/usr/bin/env bash
# replay_cex.sh CEMV MATRIX PROPS TMPDIR: the counterexample scenario that
# `cemv check --out` writes for a falsified property replays on the reference
# runtime with `cemv simulate`: its expectations are the values of the
# property's signals at the violation (docs/checker.md), so the replay passes
# exactly when the runtime reproduces the violation: exit 0.
set -u
cemv=$1 matrix=$2 props=$3 tmp=$4
rm -rf "$tmp" && mkdir -p "$tmp"
"$cemv" check "$matrix" "$props" --format json -o "$tmp/r.json" --out "$tmp/cex"; rc=$?
[ $rc -eq 1 ] || { echo "check: exit $rc, expected 1"; exit 1; }
scenarios=$(python3 -c "import json,sys; print('\n'.join(p['scenario'] for p in json.load(open(sys.argv[1]))['properties'] if p['verdict'] == 'falsified'))" "$tmp/r.json")
[ -n "$scenarios" ] || { echo "no scenario for the falsified property"; exit 1; }
for s in $scenarios; do
  "$cemv" simulate "$matrix" "$s" > "$tmp/sim.txt"; rc=$?
  [ $rc -eq 0 ] || { echo "simulate $s: exit $rc, expected 0 (the violation reproduced)"; cat "$tmp/sim.txt"; exit 1; }
done
echo "counterexamples replayed: $(echo "$scenarios" | wc -l)"
