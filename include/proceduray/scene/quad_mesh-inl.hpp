// The bodies of proceduray/scene/quad_mesh.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/scene/quad_mesh.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL TriangleMesh quad_xz(glm::vec2 min, glm::vec2 max, float y) {
  if (!(min.x < max.x && min.y < max.y)) {
    throw InvalidGeometryError("quad_xz: min (" + std::to_string(min.x) + ", " + std::to_string(min.y) +
                               ") is not below max (" + std::to_string(max.x) + ", " + std::to_string(max.y) +
                               ") on both axes; swap the corners (a flat or empty rectangle has no area)");
  }
  return {{{min.x, y, min.y}, {max.x, y, min.y}, {max.x, y, max.y}, {min.x, y, max.y}}, {0, 2, 1, 0, 3, 2}};
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
