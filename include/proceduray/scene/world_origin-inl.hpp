// The bodies of proceduray/scene/world_origin.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/world_origin.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL double float_spacing(double x) {
  const double a = std::abs(x);
  if (!(a >= 0x1p-126)) return 0x1p-149;
  return std::ldexp(1.0, std::ilogb(a) - 23);
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
