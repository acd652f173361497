#!/usr/bin/env bash
# Runs the fuzz targets (docs/fuzzing.md). `make fuzz` calls it after building
# FUZZ_BUILD (default build-fuzz) with CEMV_FUZZ=ON.
#   fuzz/run.sh [TARGET...]              each target for FUZZ_SECONDS (default 600) seconds
#   fuzz/run.sh --merge SEEDS [TARGET...] add what SEEDS/<target>/ covers anew to the corpus
# Targets are the lines of fuzz/targets.cmake; the default is all of them, one
# after the other, one process each (the fuzzer's -jobs is left at 1: the
# machines this runs on are shared). The corpus kept in the repository,
# fuzz/corpus/<target>/, is read; new inputs go to the scratch folder
# FUZZ_BUILD/scratch/<target>/, findings (crash-*, timeout-*, oom-*, leak-*)
# to FUZZ_BUILD/findings/<target>/, the log to FUZZ_BUILD/logs/<target>.log.
# Exit status 1 when some target found something.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${FUZZ_BUILD:-$root/build-fuzz}
seconds=${FUZZ_SECONDS:-600}
merge=""
if [ "${1:-}" = "--merge" ]; then merge=$2; shift 2; fi
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  mapfile -t targets < <(sed -n 's/^cemv_fuzz_target(\([a-z_0-9]*\) .*/\1/p' "$root/fuzz/targets.cmake")
fi

status=0
for t in "${targets[@]}"; do
  bin=$build/fuzz/fuzz_$t
  [ -x "$bin" ] || { echo "run.sh: $bin is not built (make fuzz builds it)" >&2; exit 2; }
  corpus=$root/fuzz/corpus/$t
  scratch=$build/scratch/$t
  findings=$build/findings/$t
  mkdir -p "$corpus" "$scratch" "$findings" "$build/logs"
  dict=()
  [ -f "$root/fuzz/dict/$t.dict" ] && dict=(-dict="$root/fuzz/dict/$t.dict")
  log=$build/logs/$t.log
  if [ -n "$merge" ]; then
    echo "== $t: merging $merge/$t into fuzz/corpus/$t"
    "$bin" -merge=1 -timeout=25 -rss_limit_mb=2048 "$corpus" "$merge/$t" >"$log" 2>&1 || status=1
    grep -E "MERGE-OUTER: [0-9]+ new files" "$log"
    continue
  fi
  echo "== $t: fuzzing for $seconds s (log $log)"
  start=$(date +%s)
  # The scratch folder first: libFuzzer writes new inputs to its first folder.
  # Fork mode with one child: a crash, timeout or out-of-memory is saved and
  # the run goes on, so one run reports every finding of its time.
  "$bin" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
         -max_total_time="$seconds" -timeout=25 -rss_limit_mb=2048 -print_funcs=0 \
         -artifact_prefix="$findings/" "${dict[@]}" "$scratch" "$corpus" >"$log" 2>&1
  rc=$?
  end=$(date +%s)
  # The last status line: "#EXECUTIONS: cov: EDGES ft: FEATURES corp: INPUTS ... oom/timeout/crash: a/b/c".
  last=$(grep -E "^#[0-9]+" "$log" | tail -1)
  echo "   ran $((end - start)) s, exit $rc; last status: $last"
  if [ $rc -ne 0 ] || ls "$findings" | grep -q .; then
    echo "   FINDINGS in $findings:"; ls "$findings" | sed 's/^/     /'
    grep -m3 -E "ERROR: |runtime error|fuzz finding|deadly signal|Timeout|out-of-memory" "$log" | sed 's/^/     /'
    status=1
  fi
done
exit $status
