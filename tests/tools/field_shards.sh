#!/bin/bash
# Three shards of a calibration run by GNU parallel, merged in shard order, must equal one
# unsharded run byte for byte (errors and evaluation counts do not depend on timing).
#   field_shards.sh PROCEDURAY_FIELD GLSL OUT_DIR
set -euo pipefail
tool=$1 glsl=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
common=(--sdf "$glsl" --lipschitz 1.75 --size 40x30 --device cpu)
"$tool" calibrate "${common[@]}" --cache "$out/cache" --out "$out/whole.csv" 2>/dev/null
# Each shard its own cache: nothing is shared but the compiled field.
parallel --halt now,fail=1 "$tool" calibrate "${common[@]}" --cache "$out/cache{}" --shard {}/3 \
  --out "$out/part{}.csv" ::: 1 2 3 2>/dev/null
"$tool" merge "$out/part1.csv" "$out/part2.csv" "$out/part3.csv" --out "$out/merged.csv"
rows=$(grep -vc '^#' "$out/whole.csv")
[ "$rows" -gt 6 ] || { echo "FAIL: the unsharded table has $rows lines"; exit 1; }
for i in 1 2 3; do
  [ "$(grep -vc '^#' "$out/part$i.csv")" -gt 1 ] || { echo "FAIL: shard $i wrote no rows"; exit 1; }
done
cmp "$out/whole.csv" "$out/merged.csv" || { echo "FAIL: merged shards differ from the unsharded table"; exit 1; }
echo "shards merged: $((rows - 1)) rows, equal to the unsharded run"
