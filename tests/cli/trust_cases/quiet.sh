#!/usr/bin/env bash
# quiet.sh CEMV KIND ARGS...: --quiet prints nothing but errors.
#   validate: only the error findings, no warnings, no summary (exit 1 kept)
#   unwritable: an unwritable --trace fails before the scenario runs (no PASS)
set -u
cemv=$1 kind=$2; shift 2
case $kind in
  validate)
    out=$("$cemv" validate "$@" --quiet); rc=$?
    [ -n "$out" ] || { echo "no findings printed"; exit 1; }
    [ "$(printf '%s\n' "$out" | grep -vc '^error ')" = 0 ] || { echo "not only errors:"; echo "$out"; exit 1; }
    echo "quiet: errors only"; exit $rc ;;
  unwritable)
    out=$("$cemv" simulate "$@" 2>&1); rc=$?
    echo "$out"
    [ $rc = 2 ] || { echo "exit $rc"; exit 1; }
    printf '%s\n' "$out" | grep -q PASS && { echo "the scenario ran before the destination was checked"; exit 1; }
    printf '%s\n' "$out" | grep -q '^error: /no/such/dir/t.json: cannot write' || exit 1
    echo "fails first" ;;
  *) echo "unknown kind $kind"; exit 99 ;;
esac
