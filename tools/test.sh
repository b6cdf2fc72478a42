#!/usr/bin/env bash
# Builds and runs every test, with the Khronos validation layer on in every Vulkan test:
#   1. CMake build of the library, tests and examples
#   2. cmake --install, then tests/consumer built against the installed package (CMake and Meson)
#   3. Meson build and `meson test`
#   4. CTest
#   5. the CMake and Meson test lists compared (tests/list_tests.py compare)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${PROCEDURAY_BUILD_DIR:-$root/build}
jobs=$(nproc)
step() { echo; echo "== $*"; }

step "CMake build"
cmake -S "$root" -B "$out/cmake" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build "$out/cmake" -j"$jobs"

step "install and consumer project"
rm -rf "$out/prefix"
cmake --install "$out/cmake" --prefix "$out/prefix" >/dev/null
cmake -S "$root/tests/consumer" -B "$out/consumer-cmake" -G Ninja -DCMAKE_PREFIX_PATH="$out/prefix"
cmake --build "$out/consumer-cmake"
"$out/consumer-cmake/consumer" "$out/consumer-cmake.png"
export PKG_CONFIG_PATH="$out/prefix/share/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
rm -rf "$out/consumer-meson"  # tiny; a fresh setup re-reads the installed .pc
meson setup "$out/consumer-meson" "$root/tests/consumer" >/dev/null
meson compile -C "$out/consumer-meson"
"$out/consumer-meson/consumer" "$out/consumer-meson.png"

step "Meson build and tests"
if [ -d "$out/meson" ]; then
  meson setup --reconfigure "$out/meson" "$root" >/dev/null
else
  meson setup "$out/meson" "$root" >/dev/null
fi
meson compile -C "$out/meson" -j "$jobs"
meson test -C "$out/meson" --num-processes "$jobs" --print-errorlogs

step "CTest"
ctest --test-dir "$out/cmake" -j"$jobs" --output-on-failure

step "CMake and Meson register the same tests"
python3 "$root/tests/list_tests.py" compare "$out/cmake" "$out/meson"
