#!/usr/bin/env bash
# shards.sh CEMV MATRIX PROPS...: shards 1/3, 2/3 and 3/3 check disjoint sets
# of properties whose union is the unsharded run, and each report names its shard.
set -u
cemv=$1 matrix=$2; shift 2
all=$("$cemv" check "$matrix" "$@" --format json | python3 -c "import json,sys; print('\n'.join(sorted(p['name'] for p in json.load(sys.stdin)['properties'])))")
parts=""
for i in 1 2 3; do
  out=$("$cemv" check "$matrix" "$@" --format json --shard $i/3)
  echo "$out" | python3 -c "import json,sys; assert json.load(sys.stdin)['shard'] == '$i/3'" || exit 1
  parts+=$(echo "$out" | python3 -c "import json,sys; print('\n'.join(p['name'] for p in json.load(sys.stdin)['properties']))")$'\n'
done
union=$(printf '%s' "$parts" | sed '/^$/d' | sort)
[ "$union" = "$all" ] || { echo "shards do not partition the properties"; diff <(echo "$all") <(echo "$union"); exit 1; }
[ -z "$(printf '%s' "$parts" | sed '/^$/d' | sort | uniq -d)" ] || { echo "a property is in two shards"; exit 1; }
echo "3 shards partition $(echo "$all" | wc -l) properties"
