#!/usr/bin/env bash
# closed_pipe.sh CEMV: every command whose output is cut short by its reader
# (`| head -c 1`) ends without a message on standard error.
set -u
cemv=$1
tank=examples/tank-overfill/matrix.json
big=$(mktemp -d) || exit 99
trap 'rm -rf "$big"' EXIT
for args in "report $tank" "validate $tank --format sarif" "fmt $tank" "graph $tank" "export-csv $tank" \
            "export-smt examples/pipeline-hipps/matrix.json --depth 40" \
            "simulate tests/scenarios/matrices/ch13_causes.json tests/scenarios/13_1_1_on_delay_bullets1_2_4_delayed_activation.json --format json"; do
  # shellcheck disable=SC2086
  "$cemv" $args 2>"$big/err" | head -c 1 >/dev/null
  if [ -s "$big/err" ]; then echo "cemv $args wrote to stderr:"; cat "$big/err"; exit 1; fi
done
echo quiet
