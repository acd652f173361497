#!/usr/bin/env bash
# closed_pipe.sh CEMV MATRIX TMPDIR: `cemv check ... | head -c 10` ends quietly:
# no message on standard error, no crash (status 141, as a process SIGPIPE kills).
set -u
cemv=$1 matrix=$2 tmp=$3
mkdir -p "$tmp"
for i in $(seq 1 3000); do echo "invariant pipe.p$i a property with a long description to fill the pipe"; done > "$tmp/many.props"
"$cemv" check "$matrix" "$tmp/many.props" 2> "$tmp/pipe.err" | head -c 10 > /dev/null
rc=${PIPESTATUS[0]}
[ $rc -eq 141 ] || { echo "exit $rc, expected 141"; cat "$tmp/pipe.err"; exit 1; }
[ ! -s "$tmp/pipe.err" ] || { echo "messages on stderr:"; cat "$tmp/pipe.err"; exit 1; }
echo "closed pipe: quiet exit $rc"
