#!/usr/bin/env bash
# expect.sh EXIT REGEX COMMAND...: runs COMMAND, fails unless it exits with EXIT
# and (when REGEX is not empty) its stdout+stderr match REGEX (grep -E).
expected=$1; pattern=$2; shift 2
out=$(timeout "${CEMV_EXPECT_TIMEOUT:-120}" "$@" 2>&1); rc=$?
printf '%s\n' "$out"
if [ "$rc" -ne "$expected" ]; then
  echo "expect.sh: exit status $rc, expected $expected" >&2; exit 1
fi
if [ -n "$pattern" ] && ! printf '%s\n' "$out" | grep -Eq -- "$pattern"; then
  echo "expect.sh: output does not match /$pattern/" >&2; exit 1
fi
exit 0
