#!/usr/bin/env bash
# sweep.sh CEMV MATRIX_JSON_TOOL TMPDIR COMMAND SIZE T...: runs `cemv COMMAND`
# on the generated SIZE x SIZE matrix (cemv_matrix_json; 128 is the
# 128 x 128 x 1024 big_matrix) once per --total-timeout value T, and requires
# every time an exit status of 0-3 (never a crash, a hang or an internal
# error) and complete output: the JSON it writes parses and lists every
# property, path, mutant or effect (the ones the limit cut short unknown),
# the other files it names exist. Issue 38, section 0.
set -u
cemv=$1 gen=$2 tmp=$3 command=$4 size=$5
shift 5
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$tmp"
matrix="$tmp/m$size.json"
[ -s "$matrix" ] || "$gen" "$size" > "$matrix" || { echo "cannot generate the $size x $size matrix"; exit 1; }
fail=0
for t in "$@"; do
  out="$tmp/$command-$size-$t"
  rm -rf "$out" && mkdir -p "$out"
  case $command in
    check) args=(check "$matrix" --standard --format json -o "$out/r.json") ;;
    testgen) args=(testgen "$matrix" --out "$out/suite" -q) ;;
    response) args=(response "$matrix" --format json -o "$out/r.json") ;;
    defeats) args=(defeats "$matrix" --max-size 1 --format json -o "$out/r.json") ;;
    mutate) args=(mutate "$matrix" --out "$out/mutants" --equivalence -q) ;;
    diff)
      # NEW: the first mutant of the matrix (valid by construction).
      [ -d "$tmp/mutants$size" ] || "$cemv" mutate "$matrix" --out "$tmp/mutants$size" -q || exit 1
      new=$(ls "$tmp/mutants$size"/*.json | grep -v mutants.json | head -1)
      args=(diff "$matrix" "$new" --format json -o "$out/r.json") ;;
    evidence) args=(evidence "$matrix" --standard --out "$out/e.html" --json "$out/r.json" -q) ;;
    *) echo "unknown command $command"; exit 1 ;;
  esac
  start=$(date +%s%N)
  # A hang is a failure too: the limit plus what loading and writing take.
  timeout 120 "$cemv" "${args[@]}" --total-timeout "$t" >"$out/stdout" 2>"$out/stderr"; rc=$?
  ms=$(( ($(date +%s%N) - start) / 1000000 ))
  echo "$command $size x $size --total-timeout $t: exit $rc after $ms ms"
  if [ $rc -gt 3 ]; then
    echo "  FAIL: exit $rc"; sed 's/^/  stderr: /' "$out/stderr" | head -5; fail=1; continue
  fi
  python3 "$here/check_outputs.py" "$command" "$out" "$matrix" || fail=1
done
exit $fail
