// The library's bodies, compiled once: the CMake consumer builds `consumer` with PROCEDURAY_SEPARATE
// (include/proceduray/config.hpp), the way README "Compile time" shows.
#include <proceduray/implementation.hpp>
