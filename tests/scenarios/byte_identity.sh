#!/usr/bin/env bash
# Every answer is independent of --jobs and of the machine's load (docs/checker.md
# "Budgets"): `check`, `testgen` and `response` run on two examples, once alone
# with --jobs 1 and once with --jobs 4 beside processes that keep every core
# busy, and every file they write is compared byte for byte. The busy processes
# run at the lowest priority: they still take every idle moment and preempt
# cemv's threads, without starving the suite's other tests beside this one.
# Only what a format carries as a time of day is set aside (the checklist's
# Date row).
# Usage: byte_identity.sh CEMV EXAMPLES_DIR WORK_DIR
set -euo pipefail
cemv=$(realpath "$1")
examples=$(realpath "$2")
work=$3
rm -rf "$work"
mkdir -p "$work"

run() {  # run OUT JOBS
  local out=$1 jobs=$2
  for ex in tank-overfill pipeline-hipps; do
    local m=$examples/$ex/matrix.json
    mkdir -p "$out/$ex"
    # Relative paths: the reports name the files they point to as given.
    pushd "$out/$ex" >/dev/null
    # check exits 1: each example's requirements hold a seeded defect.
    "$cemv" check "$m" "$examples/$ex/requirements.props" --jobs "$jobs" --format json -o check.json --out check -q ||
      [ $? -eq 1 ]
    "$cemv" check "$m" --standard --jobs "$jobs" --format json -o standard.json -q
    "$cemv" testgen "$m" --sif 2 --budget 2 --proof-budget 1 --jobs "$jobs" --out testgen -q
    # response exits 1: tank-overfill's low-low path is over its budget.
    "$cemv" response "$m" --jobs "$jobs" --format json -o response.json --out response -q || [ $? -eq 1 ]
    popd >/dev/null
  done
  # A checklist is dated: the one line that may differ from day to day.
  find "$out" -name 'checklist.*' -exec sed -i -E 's/20[0-9]{2}-[01][0-9]-[0-3][0-9]/DATE/g' {} +
}

run "$work/alone" 1

burners=()
for _ in $(seq "$(nproc)"); do
  nice -n 19 bash -c 'while :; do :; done' &
  burners+=($!)
done
trap 'kill "${burners[@]}" 2>/dev/null || true' EXIT
run "$work/loaded" 4
kill "${burners[@]}" 2>/dev/null || true

files=$(cd "$work/alone" && find . -type f | sort)
[ "$files" = "$(cd "$work/loaded" && find . -type f | sort)" ] || {
  echo "the two runs wrote different files:"
  diff <(cd "$work/alone" && find . -type f | sort) <(cd "$work/loaded" && find . -type f | sort)
  exit 1
}
count=0
for f in $files; do
  cmp "$work/alone/$f" "$work/loaded/$f" || { echo "differs: $f"; diff "$work/alone/$f" "$work/loaded/$f" | head -20; exit 1; }
  count=$((count + 1))
done
[ "$count" -ge 20 ] || { echo "only $count files written"; exit 1; }
echo "byte-identical: $count files of check, testgen and response, --jobs 1 alone and --jobs 4 beside $(nproc) busy processes"
