// The library's bodies, compiled once: the CMake consumer builds `consumer` with PROCEDURAY_SEPARATE
// (include/proceduray/config.hpp), the way docs/build_modes.md shows.
#include <proceduray/implementation.hpp>
