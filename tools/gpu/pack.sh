#!/usr/bin/env bash
# Builds what a GPU run needs into gpu/ (stripped, gzipped binaries) and the loader's packages
# into .gl/, both beside the repository (git ignores them): carry them to a GPU machine that has the NVIDIA driver but no
# Vulkan loader, SDK or glslang, and run tools/gpu/run.sh there (../shared/GPU.md).
#
#   tools/gpu/pack.sh                       # Release build in build/gpu, stripped binaries in gpu/
#   tools/gpu/pack.sh proceduray_vk_tests   # only these targets
#   BUILD=build/fast tools/gpu/pack.sh      # from an existing Release build folder instead
#
# glslang and CLI11 are linked in (Debian ships glslang as static libraries); the Vulkan loader,
# the GL vendor-neutral libraries the NVIDIA ICD needs, tinyobjloader and stb (the targets link
# Debian's shared libraries) come as .deb files that run.sh unpacks there. Ubuntu 24.04's glibc is newer than Debian 12's, so these binaries run unchanged.
set -euo pipefail
cd "$(dirname "$0")/../.."
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=(proceduray_vk_tests proceduray_examples_tests bench_frame_loop 02_paper_scene 03_d3d12_scene 04_cis565_scene
           05_textured_scene bench_soak bench_peak bench_instances bench_paper_peer bench_flops proceduray_accuracy proceduray_sweep)
fi

build=${BUILD:-build/gpu}
if [ ! -f "$build/build.ninja" ]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG" \
    -DPython3_EXECUTABLE=/usr/bin/python3 > /dev/null
fi
ninja -C "$build" "${targets[@]}"

rm -rf gpu && mkdir -p gpu
for t in "${targets[@]}"; do
  bin=$(find "$build" -type f -name "$t" -perm -u+x | head -n 1)
  [ -n "$bin" ] || { echo "pack.sh: built no binary named $t" >&2; exit 1; }
  strip -o "gpu/$t" "$bin"
  # Compressed: the carried tree is limited to 64 MiB, and a stripped binary is ~10 MB (4 gzipped).
  gzip -9 -f "gpu/$t"
done
# The paper scene's GLSL declarations are generated at build time.
cp -r "$build/examples/02_paper_scene_glsl" gpu/

mkdir -p .gl
if ! ls .gl/libvulkan1_*.deb .gl/libtinyobjloader2rc10_*.deb .gl/libstb0_*.deb > /dev/null 2>&1; then
  lists=$(mktemp -d)
  o="-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=$lists"
  mkdir -p "$lists/partial"
  apt-get $o update > /dev/null
  (cd .gl && apt-get $o download libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 \
                                 vulkan-validationlayers libtinyobjloader2rc10 libstb0)
fi
du -sh gpu .gl
echo "pack.sh: carry [\".gl\", \"gpu\"] and run: bash tools/gpu/run.sh (logs in \$OUT or gpu-logs/)"
