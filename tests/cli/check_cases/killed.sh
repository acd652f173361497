#!/usr/bin/env bash
# killed.sh CEMV MATRIX TMPDIR: `cemv check` killed (SIGKILL) mid-run leaves
# its JSON output absent, or the previous file intact, or a complete valid
# report; never half of one. The run checks 2000 properties and then one that
# never returns, so --total-timeout 1 makes it write a large report about
# 1 s after the properties are read; the kills are spread over the following
# seconds to land before, during and after the write (where they land depends
# on the machine's load; every outcome must be a whole file).
set -u
cemv=$1 matrix=$2 tmp=$3
mkdir -p "$tmp"
{ for i in $(seq 1 2000); do echo "invariant kill.p$i a property with a description to make the report large"; done
  echo "invariant kill.hang never returns"; } > "$tmp/kill.props"
rm -f "$tmp/k.json" "$tmp"/.k.json.*
"$cemv" check "$matrix" "$tmp/kill.props" --format json -o "$tmp/k.json" --total-timeout 5 & pid=$!
sleep 0.5; kill -9 $pid; wait $pid 2>/dev/null
[ ! -e "$tmp/k.json" ] || { echo "a report appeared although the run was killed before writing"; exit 1; }
previous='{"format": "cemv-result/1", "previous": true}'
outcomes=""
for delay in 1.0 1.1 1.2 1.3 1.4 1.5 1.7 1.9 2.2 2.6 3.0; do
  printf '%s\n' "$previous" > "$tmp/k.json"
  "$cemv" check "$matrix" "$tmp/kill.props" --format json -o "$tmp/k.json" --total-timeout 1 2>/dev/null & pid=$!
  sleep $delay; kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
  outcome=$(python3 - "$tmp/k.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))          # must parse: never half a file
if j.get("previous"):
    print("old")
else:
    assert j["interrupted"] is True and len(j["properties"]) == 2001, "incomplete report"
    print("new")
PY
) || { echo "after a kill at $delay s the report is not valid"; exit 1; }
  outcomes+="$delay:$outcome "
done
echo "kills: $outcomes"
