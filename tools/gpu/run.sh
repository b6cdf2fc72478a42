#!/usr/bin/env bash
# Runs on the GPU machine, from the repository root, after tools/gpu/pack.sh here: unpacks the
# loader, then runs every Vulkan test binary (validation layer on) and the benchmarks, one log
# per step in $OUT (else gpu-logs/), and a summary in run.log.
#
#   bash tools/gpu/run.sh              # everything
#   bash tools/gpu/run.sh tests        # only the test binaries
#   bash tools/gpu/run.sh bench        # only the benchmarks
#   bash tools/gpu/run.sh must         # only what issue #30's must-holds read (about 4 minutes)
set -uo pipefail
cd "$(dirname "$0")/../.."
what=${1:-all}
out=${OUT:-gpu-logs}
mkdir -p "$out" /tmp/proceduray-test-output
for f in .gl/*.deb; do dpkg -x "$f" / ; done
ldconfig
# pack.sh gzips the binaries to fit the carried tree's limit.
for z in gpu/*.gz; do [ -e "$z" ] && gunzip -f "$z"; done
# The ICD file when the loader does not find it by itself (seen on the H100/H200 machines).
if [ -f /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json ] && [ -z "${VK_DRIVER_FILES:-}" ]; then
  export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
fi
export GLIBC_TUNABLES=glibc.rtld.optional_static_tls=65536
export PROCEDURAY_SHADER_DIR=$PWD/shaders PROCEDURAY_EXAMPLES_DIR=$PWD/examples PROCEDURAY_TEST_SOURCE_DIR=$PWD/tests
export PROCEDURAY_GLSL_DIR=$PWD/gpu/02_paper_scene_glsl PROCEDURAY_BENCH_SHADER_DIR=$PWD/tools/bench/shaders
export PROCEDURAY_TEST_OUTPUT=/tmp/proceduray-test-output PROCEDURAY_DEVICE=gpu
# NVIDIA's own shader cache is off until its folder exists.
mkdir -p "${__GL_SHADER_DISK_CACHE_PATH:-$HOME/.cache/nvidia}"

log=$out/run.log
: > "$log"
step() {  # step NAME COMMAND...: runs it, its output in NAME.txt, one summary line in run.log
  local name=$1
  shift
  local start=$SECONDS
  "$@" > "$out/$name.txt" 2>&1
  local rc=$?
  printf '%-28s rc=%d %4ds  %s\n' "$name" "$rc" $((SECONDS - start)) \
    "$(grep -E 'test cases:|Status:' "$out/$name.txt" | tr '\n' ' ')" >> "$log"
}
(nvidia-smi --query-gpu=name,driver_version --format=csv,noheader || true) > "$out/gpu.txt" 2>&1
if [ "$what" = must ]; then
  step bench_peak gpu/bench_peak --device gpu && grep -h "FMAs" "$out/bench_peak.txt" >> "$log"
  export XDG_CACHE_HOME=/tmp/proceduray-cache-must
  for s in 02_paper_scene 03_d3d12_scene; do
    rm -rf "$XDG_CACHE_HOME"
    step "${s}_cold" "gpu/$s" --device gpu --frames 1 --out "/tmp/$s.png"
    for i in 1 2; do step "${s}_warm_$i" "gpu/$s" --device gpu --frames 1 --out "/tmp/$s.png"; done
    grep -H "shader and pipeline work" "$out/${s}"_cold.txt "$out/${s}"_warm_*.txt >> "$log"
    for i in 1 2; do step "${s}_1080p_$i" "gpu/$s" --device gpu --size 1920x1080 --frames 200 --out "/tmp/$s.png"; done
    grep -H "^trace" "$out/${s}"_1080p_*.txt >> "$log"
  done
  step paper_peer gpu/bench_paper_peer --device gpu --size 1920x1080 --frames 200 && cat "$out/paper_peer.txt" >> "$log"
  flops=$(gpu/bench_flops --size 256x256 | awk 'tolower($1) == "mandelbulb" { print $2 }')
  peak=$(grep -o '[0-9.]* GFLOP/s' "$out/bench_peak.txt" | sort -g | tail -n 1 | cut -d' ' -f1)
  step bench_instances gpu/bench_instances --device gpu --size 1920x1080 --frames 20 --flops-per-eval "$flops" \
    --peak-gflops "$peak" --csv "$out/instances.csv" && cat "$out/bench_instances.txt" >> "$log"
  cat "$out/gpu.txt" "$log"
  exit 0
fi
if [ "$what" = all ] || [ "$what" = tests ]; then
  for t in gpu/proceduray_*_tests; do step "$(basename "$t")" "$t"; done
fi
if [ "$what" = all ] || [ "$what" = bench ]; then
  # The device's FP32 peak, the ceiling the marching numbers are read against.
  [ -x gpu/bench_peak ] && step bench_peak gpu/bench_peak --device gpu && grep -h "FMAs" "$out/bench_peak.txt" >> "$log"
  [ -x gpu/bench_frame_loop ] && step bench_frame_loop gpu/bench_frame_loop --device gpu --sizes 1024,4096 --frames 200
  if [ -x gpu/02_paper_scene ]; then
    # A cold start, then a second one with both caches warm (SPIR-V and pipeline, in XDG_CACHE_HOME).
    export XDG_CACHE_HOME=/tmp/proceduray-cache
    rm -rf "$XDG_CACHE_HOME"
    step paper_cold_start gpu/02_paper_scene --device gpu --frames 1 --out /tmp/paper.png
    for i in 1 2 3 4 5; do step paper_warm_start_$i gpu/02_paper_scene --device gpu --frames 1 --out /tmp/paper.png; done
    grep -h "shader and pipeline work" "$out"/paper_*_start*.txt >> "$log"
  fi
  if [ -x gpu/03_d3d12_scene ]; then  # the same for the D3D12 scene, specialized (default) and general
    export XDG_CACHE_HOME=/tmp/proceduray-cache-d3d12
    for v in specialized general; do
      flag=$([ $v = general ] && echo --general || true)
      rm -rf "$XDG_CACHE_HOME"
      step "d3d12_cold_$v" gpu/03_d3d12_scene --device gpu --frames 1 $flag --out /tmp/d3d12.png
      for i in 1 2 3; do step "d3d12_warm_${v}_$i" gpu/03_d3d12_scene --device gpu --frames 1 $flag --out /tmp/d3d12.png; done
      grep -H "shader and pipeline work" "$out"/d3d12_*_"$v"*.txt >> "$log"
    done
  fi
  # Both scenes of the report's size class at 1920x1080, 200 frames, three runs each (medians).
  for s in 02_paper_scene 03_d3d12_scene; do
    [ -x "gpu/$s" ] || continue
    for i in 1 2 3; do step "${s}_1080p_$i" "gpu/$s" --device gpu --size 1920x1080 --frames 200 --out "/tmp/$s.png"; done
    grep -h "^trace" "$out/${s}"_1080p_*.txt >> "$log"
    # The general pipeline (knobs read per ray), interleaved with the specialized default.
    for i in 1 2; do
      step "${s}_1080p_general_$i" "gpu/$s" --device gpu --size 1920x1080 --frames 200 --general --out "/tmp/$s.png"
      step "${s}_1080p_special_$i" "gpu/$s" --device gpu --size 1920x1080 --frames 200 --out "/tmp/$s.png"
    done
    grep -H "^trace" "$out/${s}"_1080p_general_*.txt "$out/${s}"_1080p_special_*.txt >> "$log"
  done
  # Frame time against marched instances: the library's pipeline and the compute peer.
  if [ -x gpu/bench_instances ]; then
    # The share of the peak: the Mandelbulb's flops per evaluation (counted from its code) over bench_peak's best.
    share=()
    if [ -x gpu/bench_flops ] && [ -f "$out/bench_peak.txt" ]; then
      flops=$(gpu/bench_flops --size 256x256 | awk 'tolower($1) == "mandelbulb" { print $2 }')
      peak=$(grep -o '[0-9.]* GFLOP/s' "$out/bench_peak.txt" | sort -g | tail -n 1 | cut -d' ' -f1)
      [ -n "$flops" ] && [ -n "$peak" ] && share=(--flops-per-eval "$flops" --peak-gflops "$peak")
    fi
    step bench_instances gpu/bench_instances --device gpu --size 1920x1080 --frames 20 "${share[@]}" --csv "$out/instances.csv"
    cat "$out/bench_instances.txt" >> "$log"
  fi
  # The paper scene: the library against the compute peer, interleaved (images compared).
  if [ -x gpu/bench_paper_peer ]; then
    step paper_peer gpu/bench_paper_peer --device gpu --size 1920x1080 --frames 200
    cat "$out/paper_peer.txt" >> "$log"
  fi
  # Frame time against reflection depth (examples/04_cis565_scene), with validation off.
  if [ -x gpu/04_cis565_scene ]; then
    step cis565_depth_sweep gpu/04_cis565_scene --device gpu --size 1920x1080 --frames 100 --depth-sweep --out /tmp/cis565.png
    grep -A6 "^depth" "$out/cis565_depth_sweep.txt" >> "$log"
  fi
  # The textured scene with validation on: textures, meshes and beads added and removed each frame.
  if [ -x gpu/05_textured_scene ]; then
    step textured_scene gpu/05_textured_scene --device gpu --size 1920x1080 --frames 60 --validation \
      --out "$out/05_textured_scene.png"
    grep -E "^trace|^beads" "$out/textured_scene.txt" >> "$log"
  fi
  [ -x gpu/bench_soak ] && step bench_soak gpu/bench_soak --device gpu --frames 2000 --every 500
fi
cat "$out/gpu.txt" "$log"
