#!/usr/bin/env bash
# every_line_names_file.sh CEMV MATRIX CASES: for each malformed input, every
# line cemv writes to standard error begins with the file's name.
set -u
cemv=$1 matrix=$2 cases=$3
fail=0
check() {  # FILE ARGS...
  local file=$1; shift
  local err
  err=$("$cemv" "$@" 2>&1 >/dev/null)
  [ -n "$err" ] || { echo "no message for $*"; fail=1; return; }
  while IFS= read -r line; do
    case $line in
      "$file":*) ;;
      *) echo "line does not begin with $file: $line"; fail=1 ;;
    esac
  done <<< "$err"
}
for f in tests/formats/malformed/*.json; do check "$f" validate "$f"; done
for f in "$cases"/scenario_*.json tests/scenarios/rejects/typo_tag.json tests/scenarios/rejects/syntax_error.json; do
  check "$f" simulate "$matrix" "$f"
done
check tests/scenarios/matrices/matrix_with_x.json simulate tests/scenarios/matrices/matrix_with_x.json tests/scenarios/rejects/trivial.json
check "$cases/duplicate_id.json" graph "$cases/duplicate_id.json"
for f in tests/sheets/csv_cases/bad_*.csv tests/sheets/csv_cases/not_a_grid.csv; do check "$f" import-csv "$f"; done
[ $fail = 0 ] && echo "every line names its file"
