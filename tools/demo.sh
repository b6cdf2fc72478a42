#!/usr/bin/env bash
# Builds the demo and renders it; prints the path of the PNG it wrote.
#   tools/demo.sh [demo options...]      e.g. tools/demo.sh --size 1280x720 --device cpu
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PROCEDURAY_BUILD_DIR:-$root/build}/cmake
demo=02_paper_scene
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --target "$demo" -j"$(nproc)" >/dev/null
mkdir -p "$root/out"
"$build/examples/$demo" --out "$root/out/$demo.png" "$@"
