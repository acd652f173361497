#!/usr/bin/env bash
# The progress line of `cemv check` (cli/progress.hpp): drawn on standard
# error only when it is a terminal (here a pseudo-terminal from script(1)),
# never with --quiet or in a pipe, and the report files are byte-identical
# either way.
# usage: progress_tty.sh CEMV MATRIX PROPS TMPDIR
set -uo pipefail
cemv=$(realpath "$1") matrix=$2 props=$3 tmp=$4
rm -rf "$tmp" && mkdir -p "$tmp"
run() { "$cemv" check "$matrix" "$props" --format json -o "$1" "${@:2}"; }
run "$tmp/pipe.json" 2>"$tmp/pipe.err" >/dev/null
[ ! -s "$tmp/pipe.err" ] || { echo "progress written without a terminal:"; cat -v "$tmp/pipe.err"; exit 1; }
export TERM=xterm
script -qec "$cemv check $matrix $props --format json -o $tmp/tty.json" /dev/null >"$tmp/tty.out" </dev/null
grep -aq "cemv check: [0-9]*/3 properties, 0:[0-9][0-9]" "$tmp/tty.out" \
  || { echo "no progress line on the terminal:"; cat -v "$tmp/tty.out"; exit 1; }
grep -aq $'\r\033\\[K' "$tmp/tty.out" || { echo "the progress line is not erased"; exit 1; }
cmp -s "$tmp/pipe.json" "$tmp/tty.json" || { echo "the report differs with a terminal"; exit 1; }
script -qec "$cemv check $matrix $props --format json -o $tmp/quiet.json -q" /dev/null >"$tmp/quiet.out" </dev/null
if grep -aq "properties, " "$tmp/quiet.out"; then echo "progress drawn with --quiet"; exit 1; fi
echo "progress on a terminal only: $(tr -cd '\r' <"$tmp/tty.out" | wc -c) redraws"
