#!/usr/bin/env bash
# Builds and runs every test, with the Khronos validation layer on in every Vulkan test. One test
# runner, CTest, run with both compilers:
#   1. CMake build with GCC: CMAKE_BUILD_TYPE=Release and its default flags (-O3), plus -Werror
#      (PROCEDURAY_WERROR, on here and for developers, off in a user's build)
#   2. cmake --install, the installed proceduray-field run from its prefix, then tests/consumer
#      built against the installed package (CMake and Meson)
#   3. CTest (GCC)
#   4. CMake build with the second compiler (Debian's clang, -O2, -Werror) and CTest again: every
#      header, every usage block and every test compiled and run by both compilers (the
#      one-header-alone checks only by GCC: they test the includes, not the compiler)
#   5. Meson build of the examples (clang, -Werror) and its smoke test (each example renders)
#   6. sanitizers: an ASan+UBSan (GCC) build of the non-Vulkan tests and of a Vulkan subset
#      (proceduray_vk_sanitize_tests), run with leak detection on and no suppressions
# PROCEDURAY_TEST_STEPS="cmake ctest clang meson sanitize" runs a subset (default: all).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${PROCEDURAY_BUILD_DIR:-$root/build}
jobs=$(nproc)
steps=${PROCEDURAY_TEST_STEPS:-cmake ctest clang meson sanitize}
start=$SECONDS
step() { echo; echo "== $* (at $(( (SECONDS - start) / 60 )) min $(( (SECONDS - start) % 60 )) s)"; }
want() { [[ " $steps " == *" $1 "* ]]; }

# README's first scene, built against the installed package, run where its shaders folder is.
first_scene() {
  rm -rf "$1/run" && mkdir -p "$1/run" && cp -r "$root/tests/consumer/shaders" "$1/run/"
  (cd "$1/run" && "$1/first_scene") || { echo "first_scene ($1) failed: the README's first scene does not run" >&2; return 1; }
}

if want cmake; then
  step "CMake build (GCC, Release with its default flags, -Werror)"
  cmake -S "$root" -B "$out/cmake" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPROCEDURAY_WERROR=ON
  cmake --build "$out/cmake" -j"$jobs"

  step "install and consumer project"
  rm -rf "$out/prefix"
  cmake --install "$out/cmake" --prefix "$out/prefix" >/dev/null
  # The installed tools run from the prefix: its headers and shaders, not the source tree's.
  prefix=$(realpath "$out/prefix")
  test -x "$prefix/bin/proceduray-chart" && test -x "$prefix/bin/proceduray-calibration-chart"
  test -x "$prefix/bin/proceduray-heatmap" && test -x "$prefix/bin/proceduray-split-chart"
  where=$(env -u PROCEDURAY_SHADER_DIR -u PROCEDURAY_INCLUDE_DIR "$prefix/bin/proceduray-field" where)
  grep -qx "shaders $prefix/share/proceduray/shaders" <<< "$where" || { echo "installed proceduray-field: $where" >&2; exit 1; }
  grep -qx "headers $prefix/include" <<< "$where" || { echo "installed proceduray-field: $where" >&2; exit 1; }
  env -u PROCEDURAY_SHADER_DIR -u PROCEDURAY_INCLUDE_DIR "$prefix/bin/proceduray-field" measure \
    --sdf "$root/tests/vk/shaders/fields/ball.glsl" --exact --size 16x12 --device cpu --validation \
    --cache "$out/field-cache-installed" | grep -q "^wrong_surface"
  # The measuring tools, installed: a user's field, and an example scene from the prefix's shaders.
  env -u PROCEDURAY_SHADER_DIR -u PROCEDURAY_INCLUDE_DIR -u PROCEDURAY_EXAMPLES_DIR "$prefix/bin/proceduray_accuracy" \
    --sdf "$root/tests/vk/shaders/fields/ball.glsl" --exact --size 16x12 --device cpu \
    --cache "$out/field-cache-installed" > "$out/installed-accuracy-field.txt"
  grep -q "^wrong_surface" "$out/installed-accuracy-field.txt"
  env -u PROCEDURAY_SHADER_DIR -u PROCEDURAY_EXAMPLES_DIR "$prefix/bin/proceduray_accuracy" --scene d3d12 \
    --size 16x12 --device cpu > "$out/installed-accuracy-d3d12.txt"
  grep -q "depth_px_median" "$out/installed-accuracy-d3d12.txt"
  test -x "$prefix/bin/proceduray_sweep"
  cmake -S "$root/tests/consumer" -B "$out/consumer-cmake" -G Ninja -DCMAKE_PREFIX_PATH="$out/prefix"
  cmake --build "$out/consumer-cmake"
  "$out/consumer-cmake/consumer" "$out/consumer-cmake.png"
  first_scene "$out/consumer-cmake"
  export PKG_CONFIG_PATH="$out/prefix/share/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
  rm -rf "$out/consumer-meson"  # tiny; a fresh setup re-reads the installed .pc
  meson setup "$out/consumer-meson" "$root/tests/consumer" >/dev/null
  meson compile -C "$out/consumer-meson"
  "$out/consumer-meson/consumer" "$out/consumer-meson.png"
  first_scene "$out/consumer-meson"
fi

if want ctest; then
  step "CTest (GCC)"
  ctest --test-dir "$out/cmake" -j"$jobs" --output-on-failure
fi

if want clang; then
  step "CMake build (clang, -O2, -Werror) and CTest"
  if [ -d "$out/clang" ] && ! grep -q "clang++" "$out/clang/CMakeCache.txt" 2>/dev/null; then
    rm -rf "$out/clang"  # an older build by another compiler
  fi
  # The benchmarks are not tests: the GCC build compiles them.
  CC=clang CXX=clang++ cmake -S "$root" -B "$out/clang" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG" -DPROCEDURAY_WERROR=ON -DPROCEDURAY_BUILD_BENCHES=OFF >/dev/null
  grep -q "clang++" "$out/clang/CMakeCache.txt" || { echo "the second build is not using clang++"; exit 1; }
  cmake --build "$out/clang" -j"$jobs"
  # "compiles alone" checks include-completeness against the same libstdc++ and were run with GCC;
  # clang still parses every header (each test binary's precompiled header holds the umbrella).
  ctest --test-dir "$out/clang" -j"$jobs" --output-on-failure -E "^headers: .* compiles alone$"
fi

if want meson; then
  step "Meson build of the examples (clang) and its smoke test"
  if [ -d "$out/meson" ] && ! grep -q "clang++" "$out/meson/build.ninja" 2>/dev/null; then
    rm -rf "$out/meson"  # an older build by another compiler
  fi
  if [ -d "$out/meson" ]; then
    meson setup --reconfigure "$out/meson" "$root" >/dev/null
  else
    CC=clang CXX=clang++ meson setup "$out/meson" "$root" -Doptimization=1 -Ddebug=false -Dwerror=true >/dev/null
  fi
  meson compile -C "$out/meson" -j "$jobs"
  meson test -C "$out/meson" --num-processes "$jobs" --print-errorlogs
fi

if want sanitize; then
  step "ASan + UBSan build"
  # vptr is left out: its checks need the typeinfo of every polymorphic class, and Debian builds
  # glslang's static libraries without RTTI (undefined `typeinfo for glslang::TShader`).
  # GCC 12 also warns maybe-uninitialized inside libstdc++ when ASan instruments it (a false
  # positive, not in our code), so that one warning is not an error here.
  flags="-fsanitize=address,undefined -fno-sanitize=vptr -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
  flags+=" -Wno-maybe-uninitialized"
  # -O0: a third of -O1's compile time under ASan; these tests are fast either way.
  cmake -S "$root" -B "$out/sanitize" -G Ninja -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O0 -g1" \
    -DPROCEDURAY_WERROR=ON "-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined" >/dev/null
  binaries=(proceduray_shader_tests proceduray_scene_tests proceduray_march_tests proceduray_accuracy_tests
            proceduray_image_tests proceduray_vk_sanitize_tests)
  cmake --build "$out/sanitize" -j"$jobs" --target "${binaries[@]}"

  step "ASan + UBSan tests"
  export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  export PROCEDURAY_TEST_OUTPUT="$out/sanitize/test-output"
  for binary in "${binaries[@]}"; do
    echo "-- $binary"
    (cd "$out/sanitize/tests" && "./$binary" --minimal)
  done
fi
step "done"
