#!/usr/bin/env bash
# regenerate.sh CEMV EXAMPLE [field]: the committed suite of examples/EXAMPLE/acceptance
# (automated and field, checklists included) is what cemv testgen writes now,
# byte for byte (docs/testgen.md, "Figures on the examples": the command and
# the date used). With `field`, only the field suite (acceptance/field, made
# with --field-only, under a second). A difference means the committed suite
# is stale or the generation is not reproducible.
set -u
cemv=$1; ex=$2; part=${3:-all}
sub=; only=
if [ "$part" = field ]; then sub=/field; only=--field-only; fi
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
mkdir -p "$work/$ex"
cp "examples/$ex/matrix.json" "$work/$ex/matrix.json"   # the same relative path from the suite to its matrix
SOURCE_DATE_EPOCH=1767225600 "$cemv" testgen "$work/$ex/matrix.json" --out "$work/$ex/acceptance" --jobs 2 -q $only \
  || { echo "regenerate.sh: cemv testgen exit $?" >&2; exit 1; }
if ! diff -r "examples/$ex/acceptance$sub" "$work/$ex/acceptance$sub" > "$work/diff.txt"; then
  head -40 "$work/diff.txt"
  echo "regenerate.sh: examples/$ex/acceptance$sub differs from what cemv testgen writes now" >&2
  exit 1
fi
echo "regenerate.sh $ex${sub}: byte for byte"
