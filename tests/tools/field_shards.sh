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
# A part of another calibration (another size) is refused, naming both.
"$tool" calibrate --sdf "$glsl" --lipschitz 1.75 --size 20x15 --device cpu --cache "$out/cache" --shard 1/3 \
  --out "$out/other.csv" 2>/dev/null >/dev/null
if message=$("$tool" merge "$out/other.csv" "$out/part2.csv" --out "$out/bad.csv" 2>&1); then
  echo "FAIL: parts of two calibrations were merged"; exit 1
fi
grep -q "at 40x30.*merge the parts of one calibration" <<<"$message" || { echo "FAIL: unclear refusal: $message"; exit 1; }
echo "shards merged: $((rows - 1)) rows, equal to the unsharded run"
