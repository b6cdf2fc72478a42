// A flat rectangle as a triangle mesh: the ground plane most scenes stand their objects on.
//
//   scene.add_geometry("ground", proceduray::GeometryDesc::triangles(proceduray::quad_xz({-12, -10}, {12, 10})));
//
// Why: every example spelled the same four corners and six indices, and a swapped pair of
// indices flips the normal with no error. The two triangles lie at height y, span min..max in x
// and z, and their right-hand-rule normal is +y (up), which closest-hit shaders can rely on.
#pragma once

#include <proceduray/config.hpp>

#include <string>

#include <glm/glm.hpp>

#include "proceduray/scene/errors.hpp"
#include "proceduray/scene/geometry.hpp"

namespace proceduray {

/// Two triangles at height `y` spanning `min`..`max` (x, z), normal +y; throws InvalidGeometryError
/// unless min < max on both axes.
PROCEDURAY_DECL TriangleMesh quad_xz(glm::vec2 min, glm::vec2 max, float y = 0.0f);

}  // namespace proceduray

#include "proceduray/scene/quad_mesh-inl.hpp"  // the bodies (config.hpp)
