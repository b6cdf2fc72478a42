#!/usr/bin/env bash
# Compile time of the files a user pays for, header-only and with PROCEDURAY_SEPARATE
# (include/proceduray/config.hpp): wall seconds of `c++ -O2` (the CMake Release flags), the
# median of N runs (default 3) with min and max. Run it on an idle machine.
#
#   tools/bench/compile_time.sh                 # this tree
#   tools/bench/compile_time.sh /tmp/old-tree   # another checkout, for a before/after
#   RUNS=5 CXX=clang++ tools/bench/compile_time.sh
set -euo pipefail
tree=$(cd "${1:-$(dirname "$0")/../..}" && pwd)
runs=${RUNS:-3}
cxx=${CXX:-c++}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/glsl"  # example 02 reads its generated declarations at run time only

# A file with every scene/ header and nothing else, and one with the umbrella header.
for h in "$tree"/include/proceduray/scene/*.hpp; do echo "#include <proceduray/scene/${h##*/}>"; done > "$work/scene_layer.cpp"
echo 'int main() {}' >> "$work/scene_layer.cpp"
printf '#include <proceduray/proceduray.hpp>\nint main() {}\n' > "$work/umbrella.cpp"

flags=(-O2 -DNDEBUG -std=gnu++20 -Wall -Wextra -Wpedantic -Werror -Wno-missing-field-initializers
       -I"$tree/include" -isystem /usr/include/stb -DPROCEDURAY_SHADER_DIR=\""$tree/shaders"\"
       -DPROCEDURAY_EXAMPLES_DIR=\""$tree/examples"\" -DPAPER_GLSL_DIR=\""$work/glsl"\")

# median min max of `runs` compiles of $1 with extra flags $2...
time_one() {
  local file=$1; shift
  local times=()
  for ((i = 0; i < runs; ++i)); do
    local start end
    start=$(date +%s.%N)
    "$cxx" "${flags[@]}" "$@" -c -o "$work/out.o" "$file"
    end=$(date +%s.%N)
    times+=("$(echo "$end - $start" | bc)")
  done
  printf '%s\n' "${times[@]}" | sort -n | awk '{t[NR] = $1} END {printf "%6.2f %6.2f %6.2f", t[int((NR + 1) / 2)], t[1], t[NR]}'
}

printf '%-46s %-13s %6s %6s %6s\n' file mode median min max
row() {
  local name=$1 file=$2 mode=$3; shift 3
  printf '%-46s %-13s %s\n' "$name" "$mode" "$(time_one "$file" "$@")"
}
main="$tree/examples/02_paper_scene/main.cpp"
row "examples/02_paper_scene/main.cpp" "$main" header-only
row "examples/02_paper_scene/main.cpp" "$main" separate -DPROCEDURAY_SEPARATE
row "every scene/ header, empty main" "$work/scene_layer.cpp" header-only
row "every scene/ header, empty main" "$work/scene_layer.cpp" separate -DPROCEDURAY_SEPARATE
row "proceduray/proceduray.hpp, empty main" "$work/umbrella.cpp" header-only
row "proceduray/proceduray.hpp, empty main" "$work/umbrella.cpp" separate -DPROCEDURAY_SEPARATE
if [ -f "$tree/include/proceduray/implementation.hpp" ]; then
  printf '#include <proceduray/implementation.hpp>\n' > "$work/implementation.cpp"
  row "implementation.hpp (once per program)" "$work/implementation.cpp" separate -DPROCEDURAY_SEPARATE
fi
