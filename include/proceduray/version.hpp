// The library's version, as CMakeLists.txt and meson.build declare it (a test compares them).
//
//   std::printf("Proceduray %s\n", std::string(proceduray::version).c_str());
//
// Why in a header: a header-only library has no binary to ask, and data the library reads
// (march calibration tables) records the version that measured it and is refused by another.
#pragma once

#include <string_view>

namespace proceduray {

/// major.minor.patch; a change to how a march computes its hits bumps at least the minor.
inline constexpr std::string_view version = "0.2.0";

}  // namespace proceduray
