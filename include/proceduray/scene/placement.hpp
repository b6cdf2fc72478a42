// Where an instance goes, in the terms scenes are written in: a translation, a uniform scale and
// a rotation, turned into the 3x4 instance transform the TLAS takes.
//
//   constexpr proceduray::Placement julia{.translation = {-1.25f, 0.87f, 0.0f}, .scale = 0.85f};
//   scene.add_geometry("julia", proceduray::GeometryDesc::procedural({box}, {julia.transform()}));
//   julia.translation;   // still there for the tests and the camera, unlike a matrix's
//   GeometryDesc::procedural({box}, proceduray::transforms(placements));   // several instances
//
// Why: most instances are placed, not sheared, and spelling glm::translate, glm::rotate and
// glm::scale (in the right order) for each one hid the three numbers that matter. The transform is
// translate * rotate * scale: the local box is scaled, then turned, then moved. A zero scale or a
// zero axis with a non-zero angle gives a singular or non-finite transform, which add_geometry rejects
// naming the geometry and instance.
#pragma once

#include <proceduray/config.hpp>

#include <span>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "proceduray/scene/geometry.hpp"

namespace proceduray {

/// A translation, uniform scale and rotation (axis and angle) of an instance.
struct Placement {
  glm::vec3 translation{0.0f};       ///< where the local origin goes (world units)
  float scale = 1.0f;                ///< uniform scale of the local geometry; default 1
  glm::vec3 axis{0.0f, 1.0f, 0.0f};  ///< rotation axis (any length but zero); default +y
  float degrees = 0.0f;              ///< rotation angle about `axis`, counter-clockwise; default 0

  /// The object-to-world matrix: translate * rotate * scale.
  glm::mat4 matrix() const {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), translation);
    if (degrees != 0.0f) m = glm::rotate(m, glm::radians(degrees), axis);
    return glm::scale(m, glm::vec3(scale));
  }
  /// The TLAS instance transform of matrix().
  InstanceTransform transform() const { return instance_transform(matrix()); }
};

/// The instance transforms of `placements`, in order: a geometry's instances.
PROCEDURAY_DECL std::vector<InstanceTransform> transforms(std::span<const Placement> placements);

}  // namespace proceduray

#include "proceduray/scene/placement-inl.hpp"  // the bodies (config.hpp)
