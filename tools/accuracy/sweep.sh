#!/usr/bin/env bash
# A first speed-against-accuracy sweep: proceduray_accuracy over hit thresholds (and the D3D12
# sample's settings) for one scene, appended to one CSV, then charted by chart.py.
#   tools/accuracy/sweep.sh paper 160x120 cpu docs/images/sweep_paper.png mandelbulb julia
#   tools/accuracy/sweep.sh d3d12 320x240 gpu /tmp/sweep_d3d12.png
# Arguments: scene (paper, d3d12), size, device (cpu, gpu), PNG, then the objects to chart
# (default: every object with hits); the CSV is written next to the PNG (same name, .csv).
# PROCEDURAY_ACCURACY names the tool's binary (default: the CMake build's).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
[ $# -ge 4 ] || { echo "usage: $0 paper|d3d12 WxH cpu|gpu out.png [object ...]" >&2; exit 2; }
scene=$1 size=$2 device=$3 png=$4
shift 4
objects=()
for o in "$@"; do objects+=(--object "$o"); done
tool=${PROCEDURAY_ACCURACY:-$root/build/cmake/tools/accuracy/proceduray_accuracy}
[ -x "$tool" ] || { echo "sweep.sh: no $tool; build first (tools/test.sh) or set PROCEDURAY_ACCURACY" >&2; exit 2; }
csv=${png%.png}.csv
rm -f "$csv"
runs=("--threshold 1" "--threshold 0.5" "--threshold 0.25" "--threshold 0.125" "--threshold 0.0625"
      "--threshold 0.03125" "--steps 512 --relative 1e-4")
i=0
for knobs in "${runs[@]}"; do
  i=$((i + 1))
  echo "sweep: run $i of ${#runs[@]}: $knobs" >&2
  # shellcheck disable=SC2086  # the knobs are words
  "$tool" --scene "$scene" --size "$size" --device "$device" $knobs --csv "$csv" --append > /dev/null
done
# Debian's python3 first: python3-matplotlib installs there (a pyenv python3 may lack it).
python=python3
[ -x /usr/bin/python3 ] && python=/usr/bin/python3
"$python" "$root/tools/accuracy/chart.py" "$csv" --out "$png" --front "${objects[@]}"
