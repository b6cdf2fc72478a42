// The library's bodies, compiled once for every test binary: the tests build with PROCEDURAY_SEPARATE
// (include/proceduray/config.hpp), which cuts each Vulkan test file from about 20 s to 7 s at -O2.
// Header-only builds are covered by the tools, the Meson consumer and the header checks.
#include <proceduray/implementation.hpp>
