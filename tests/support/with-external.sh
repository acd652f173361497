#!/usr/bin/env bash
# with-external.sh DIR -- COMMAND...: runs COMMAND when the published LSST TMA
# tables are in DIR. They carry no licence, so they are never copied into the
# project: a clone without them still passes `make test`, the tests that read
# them exit 77 (CTest: "Skipped") saying how to provide them; with
# CEMV_REQUIRE_EXTERNAL=1 (CI, .ci/run) a missing table is a failure instead.
set -u
dir=$1; shift
[ "${1:-}" = -- ] && shift
missing=()
for f in lsst-tma-interlock-table.csv lsst-tma-interlock-table-2023-10-05.csv; do
  [ -f "$dir/$f" ] || missing+=("$f")
done
if [ ${#missing[@]} -eq 0 ]; then
  exec "$@"
fi
echo "waits for the published LSST tables: ${missing[*]} not in $dir;" \
     "run scripts/fetch-external, or configure with -DCEMV_LSST_DIR=DIR (README, \"Tests that read published data\")"
if [ "${CEMV_REQUIRE_EXTERNAL:-0}" = 1 ]; then
  echo "error: CEMV_REQUIRE_EXTERNAL=1: the published tables are required here" >&2
  exit 1
fi
exit 77
