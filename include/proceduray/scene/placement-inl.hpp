// The bodies of proceduray/scene/placement.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/placement.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL std::vector<InstanceTransform> transforms(std::span<const Placement> placements) {
  std::vector<InstanceTransform> out;
  out.reserve(placements.size());
  for (const Placement& p : placements) out.push_back(p.transform());
  return out;
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
