#!/usr/bin/env bash
# cache.sh CEMV MATRIX PROPS TMP [OUT]: `cemv check --cache DIR` run twice:
# the second run takes every decided verdict from DIR and says so, and its
# JSON, JUnit and SARIF are the bytes of the first run's (with OUT: the
# counterexample and witness files under --out too). An entry that is not
# for its property (its stored key differs) is never used, nor (OUT given,
# the real checker) a stored counterexample the runtime does not reproduce.
set -u
cemv=$1 matrix=$2 props=$3 tmp=$4 out=${5:-}
rm -rf "$tmp" && mkdir -p "$tmp"
run() {  # run NAME: one run, reports in $tmp/NAME.*, files under $tmp/NAME-cex with OUT
  local extra=()
  [ -n "$out" ] && extra=(--out "$tmp/$1-cex")
  "$cemv" check "$matrix" "$props" --cache "$tmp/cache" --format json -o "$tmp/$1.json" \
    --report junit:"$tmp/$1.xml" --report sarif:"$tmp/$1.sarif" "${extra[@]}"
}
first=$(run first); rc1=$?
second=$(run second); rc2=$?
[ $rc1 = $rc2 ] || { echo "exit $rc1, then $rc2"; exit 1; }
decided=$(python3 -c "import json,sys; print(sum(p['verdict'] != 'unknown' for p in json.load(open(sys.argv[1]))['properties']))" "$tmp/first.json")
echo "$first" | grep -q "from the cache" && { echo "$first"; echo "the first run used a cache"; exit 1; }
echo "$second" | grep -q "; $decided from the cache; " || { echo "$second"; echo "expected $decided from the cache"; exit 1; }
for ext in json xml sarif; do
  if [ -n "$out" ]; then
    sed "s#$tmp/second-cex#$tmp/first-cex#g" "$tmp/second.$ext" > "$tmp/second.$ext.same-dir"
  else
    cp "$tmp/second.$ext" "$tmp/second.$ext.same-dir"
  fi
  cmp "$tmp/first.$ext" "$tmp/second.$ext.same-dir" || { echo "$ext differs from the first run's"; exit 1; }
done
if [ -n "$out" ]; then
  diff -r "$tmp/first-cex" "$tmp/second-cex" || { echo "the files under --out differ"; exit 1; }
fi
# An entry whose stored key is not its property's is not used. The entry
# spoilt is a falsified property's when there is one, the property the fourth
# run decides again too: a property decided alone may get another witness than
# in the first run, where it shared its cone group's runs with others (the
# verdict is the same; docs/checker.md "Cone groups"), so the last comparison
# below holds only when the same property is decided again both times.
entry=$(grep -l '"verdict": *"falsified"' "$tmp"/cache/*.json | head -1)
[ -n "$entry" ] || entry=$(ls "$tmp"/cache/*.json | head -1)
python3 - "$entry" <<'PY'
import json, sys
e = json.load(open(sys.argv[1]))
e["key"] = e["key"].replace("property ", "property x", 1)
json.dump(e, open(sys.argv[1], "w"))
PY
third=$(run third)
echo "$third" | grep -q "; $((decided - 1)) from the cache; " || { echo "$third"; echo "a foreign entry was used"; exit 1; }
# On the real checker (OUT given): a stored counterexample the runtime does
# not reproduce is not reported; the property is decided again.
if [ -n "$out" ]; then
  python3 - "$tmp"/cache/*.json <<'PY'
import json, sys
for f in sys.argv[1:]:
    e = json.load(open(f))
    if e["result"]["verdict"] == "falsified":
        e["result"]["trace"]["observables"][-1][0] ^= 1
        json.dump(e, open(f, "w"))
        break
else:
    sys.exit("no stored counterexample")
PY
  fourth=$(run fourth)
  echo "$fourth" | grep -q "; $((decided - 1)) from the cache; " || { echo "$fourth"; echo "a counterexample that does not replay was used"; exit 1; }
  cmp "$tmp/first.json" <(sed "s#$tmp/fourth-cex#$tmp/first-cex#g" "$tmp/fourth.json") || { echo "the re-decided result differs"; exit 1; }
fi
echo "cache: $decided verdicts reused, outputs identical"
