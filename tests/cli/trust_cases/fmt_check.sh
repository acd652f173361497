#!/usr/bin/env bash
# fmt_check.sh CEMV TMPDIR: `cemv fmt --check FILE...` names each file not in
# canonical form and exits 1, changes no file, exits 0 when all are
# canonical and 2 when one cannot be read.
set -u
cemv=$1 tmp=$2
mkdir -p "$tmp"
"$cemv" fmt examples/tank-overfill/matrix.json -o "$tmp/canonical.json" || exit 1
cp tests/scenarios/matrices/ch13_causes.json "$tmp/loose.json"
before=$(sha256sum "$tmp/loose.json")
out=$("$cemv" fmt --check "$tmp/canonical.json" "$tmp/loose.json"); rc=$?
[ $rc = 1 ] || { echo "exit $rc for a non-canonical file"; exit 1; }
echo "$out" | grep -qx "$tmp/loose.json: not in canonical form (cemv fmt FILE -o FILE rewrites it)" || { echo "$out"; exit 1; }
echo "$out" | grep -q "canonical.json:" && { echo "a canonical file was named"; exit 1; }
[ "$(sha256sum "$tmp/loose.json")" = "$before" ] || { echo "fmt --check changed a file"; exit 1; }
"$cemv" fmt --check "$tmp/canonical.json" >/dev/null || { echo "canonical file: exit $?"; exit 1; }
"$cemv" fmt --check "$tmp/canonical.json" no/such.json 2>/dev/null; rc=$?
[ $rc = 2 ] || { echo "exit $rc for an unreadable file"; exit 1; }
"$cemv" fmt --check "$tmp/canonical.json" -o "$tmp/x.json" 2>/dev/null; rc=$?
[ $rc = 2 ] || { echo "--check with -o: exit $rc"; exit 1; }
echo "fmt --check ok"
