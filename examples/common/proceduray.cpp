// The library's bodies, compiled once for every example (the examples build with
// PROCEDURAY_SEPARATE: see include/proceduray/config.hpp).
#include <proceduray/implementation.hpp>
