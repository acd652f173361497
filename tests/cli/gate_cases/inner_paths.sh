#!/usr/bin/env bash
# inner_paths.sh CEMV TMP: a path inside an input file (a scenario's
# `matrix` key) is resolved against that file's folder and may not leave the
# working folder: an absolute path, a `..` beyond it and a symbolic link
# that leads out of it are refused (exit 2) without reading the file; with
# --trust-paths the path is followed, and an error about a file that is not
# a matrix quotes none of its bytes. Run from the source tree (it works in
# TMP/work).
set -u
cemv=$1 tmp=$2
rm -rf "$tmp" && mkdir -p "$tmp"
secret="$tmp/secret.txt"
printf 'root:S3CR3T-HASH:19000:0:99999:7:::\n' > "$secret"
scenario() { printf '{"format": "cemv-scenario/1", "matrix": "%s", "steps": []}\n' "$2" > "$1"; }
fail() { echo "$out"; echo "$1"; exit 1; }

# The working folder is $tmp/work; the secret lies outside it.
src=$(pwd)
mkdir -p "$tmp/work/plant/scenarios" && cd "$tmp/work" || exit 1
cp "$src/examples/tank-overfill/matrix.json" plant/matrix.json
inside=plant/scenarios
scenario "$inside/absolute.json" "$secret"
out=$("$cemv" simulate "$inside/absolute.json" 2>&1); rc=$?
[ $rc = 2 ] && echo "$out" | grep -q "absolute.json:1:[0-9]*: error: matrix: is an absolute path" || fail "absolute path: exit $rc"
scenario "$inside/up.json" "../../../secret.txt"
out=$("$cemv" simulate "$inside/up.json" 2>&1); rc=$?
[ $rc = 2 ] && echo "$out" | grep -q "error: matrix: leads outside the working folder" || fail "'..' out of the folder: exit $rc"
ln -s "$secret" "$inside/link.json"
scenario "$inside/via_link.json" "link.json"
out=$("$cemv" simulate "$inside/via_link.json" 2>&1); rc=$?
[ $rc = 2 ] && echo "$out" | grep -q "error: matrix: leads outside the working folder" || fail "a link out of the folder: exit $rc"
# Inside the folder, through '..' that stays inside: followed.
python3 - "$src/examples/tank-overfill/scenario-1-overfill-trip.json" "$inside/ok.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
s["matrix"] = "../matrix.json"
json.dump(s, open(sys.argv[2], "w"))
PY
out=$("$cemv" simulate "$inside/ok.json" 2>&1); rc=$?
[ $rc = 0 ] || fail "a path inside the folder: exit $rc"
# Trusted: followed, and the error names no byte of the file.
for s in absolute up via_link; do
  out=$("$cemv" simulate "$inside/$s.json" --trust-paths 2>&1); rc=$?
  [ $rc = 2 ] || fail "--trust-paths ($s): exit $rc"
  echo "$out" | grep -q "error: syntax error: not a JSON object" || fail "--trust-paths ($s): no message"
  echo "$out" | grep -Eq "S3CR|root|last read|'r'" && fail "--trust-paths ($s): the message quotes the file"
done
echo "inner paths stay inside the working folder"
