#!/usr/bin/env bash
# Builds and runs every test, with the Khronos validation layer on in every Vulkan test:
#   1. CMake build (GCC) of the library, tests and examples
#   2. cmake --install, then tests/consumer built against the installed package (CMake and Meson)
#   3. Meson build with the second compiler (Debian's clang) and `meson test`: every header and
#      every test compiled and run by both compilers
#   4. CTest
#   5. the CMake and Meson test lists compared (tests/list_tests.py compare)
#   6. sanitizers: an ASan+UBSan (GCC) build of the non-Vulkan tests and of the Vulkan layer's tests,
#      run with leak detection on (tools/sanitizers/lsan.supp: the Vulkan driver's and loader's own)
# PROCEDURAY_TEST_STEPS="cmake meson ctest sanitize" runs a subset (default: all).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${PROCEDURAY_BUILD_DIR:-$root/build}
jobs=$(nproc)
steps=${PROCEDURAY_TEST_STEPS:-cmake meson ctest sanitize}
start=$SECONDS
step() { echo; echo "== $* (at $(( (SECONDS - start) / 60 )) min $(( (SECONDS - start) % 60 )) s)"; }
want() { [[ " $steps " == *" $1 "* ]]; }
# No debug info in these builds: it is a third of the compile time and CI reads no core files.
release=(-DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG")

if want cmake; then
  step "CMake build (GCC)"
  cmake -S "$root" -B "$out/cmake" -G Ninja "${release[@]}"
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
fi

if want meson; then
  step "Meson build (clang) and tests"
  if [ -d "$out/meson" ] && ! grep -q "clang++" "$out/meson/build.ninja" 2>/dev/null; then
    rm -rf "$out/meson"  # an older build by another compiler
  fi
  if [ -d "$out/meson" ]; then
    meson setup --reconfigure "$out/meson" "$root" >/dev/null
  else
    CC=clang CXX=clang++ meson setup "$out/meson" "$root" -Doptimization=2 -Ddebug=false >/dev/null
  fi
  grep -q "clang++" "$out/meson/build.ninja" || { echo "the Meson build is not using clang++"; exit 1; }
  meson compile -C "$out/meson" -j "$jobs"
  meson test -C "$out/meson" --num-processes "$jobs" --print-errorlogs
fi

if want ctest; then
  step "CTest"
  ctest --test-dir "$out/cmake" -j"$jobs" --output-on-failure

  step "CMake and Meson register the same tests"
  python3 "$root/tests/list_tests.py" compare "$out/cmake" "$out/meson"
fi

if want sanitize; then
  step "ASan + UBSan build"
  flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
  cmake -S "$root" -B "$out/sanitize" -G Ninja -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1" \
    "-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined" >/dev/null
  layers=(shader scene march accuracy image vk)
  # shellcheck disable=SC2046
  cmake --build "$out/sanitize" -j"$jobs" --target $(printf 'proceduray_%s_tests ' "${layers[@]}")

  step "ASan + UBSan tests"
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:halt_on_error=1"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  export LSAN_OPTIONS="suppressions=$root/tools/sanitizers/lsan.supp:print_suppressions=0"
  for layer in "${layers[@]}"; do
    echo "-- $layer"
    (cd "$out/sanitize/tests" && "./proceduray_${layer}_tests" --minimal)
  done
fi
step "done"
