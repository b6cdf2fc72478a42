// Where the paper scene stands in the world, and the origin its float coordinates are taken from
// (proceduray/scene/world_origin.hpp): the stability case of a scene far from (0, 0, 0).
//
//   const paper::World far = paper::World::at({6e5, 4.8e5, -6.4e5});   // WorldOrigin at the camera
//   paper::PaperScene scene({}, paper::Tracing::recursive, paper::max_depth_limit, far);
//   paper::SceneConstants c = paper::default_constants(1024, 768, 0.0f);
//   far.place(c);                                                       // eye and light, moved the same
//   paper::World::at({1e6, 0.0, 0.0}, paper::Reorigin::off)             // raw floats: what WorldOrigin removes
//
// Why: a float world coordinate of 1e6 is rounded to 0.06 units, dozens of pixel footprints at
// this camera's distances. Every world point the GPU sees goes through one WorldOrigin, in
// double: the instances' translations, the eye and the light. Directions, the fractals' own
// parameters and object-space shading (the plane's checker) need nothing. The ground truth
// (reference.hpp) is the scene at (0, 0, 0): a translation changes no distance along a ray.
#pragma once

#include "paper_types.hpp"

#include <proceduray/scene/world_origin.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <span>
#include <string>
#include <vector>

namespace paper {

/// Whether World::at takes float coordinates relative to the camera (on) or to (0, 0, 0) (off).
enum class Reorigin { on, off };

/// The scene translated by `offset` (world units, double), rendered in float coordinates
/// relative to `origin`. The default is the report's figure: at (0, 0, 0), no re-origin.
struct World {
  glm::dvec3 offset{0.0};
  pr::WorldOrigin origin;

  /// The scene at `offset`; with Reorigin::on the origin is the default camera's eye there.
  /// Throws UsageError for a non-finite offset.
  static World at(glm::dvec3 offset, Reorigin reorigin = Reorigin::on) {
    if (!std::isfinite(offset.x) || !std::isfinite(offset.y) || !std::isfinite(offset.z)) {
      throw pr::UsageError("paper::World::at: offset (" + std::to_string(offset.x) + ", " + std::to_string(offset.y) +
                           ", " + std::to_string(offset.z) + ") is not finite; pass a finite world position");
    }
    const glm::dvec3 eye = offset + glm::dvec3(default_eye);
    return {offset, reorigin == Reorigin::on ? pr::WorldOrigin(eye) : pr::WorldOrigin()};
  }

  /// What the tools' `--origin X,Y,Z` (`xyz`, empty: not given) and `--raw-floats` ask for.
  static World from_options(const std::vector<double>& xyz, bool raw_floats) {
    if (xyz.empty()) return {};
    if (xyz.size() != 3) {
      throw pr::UsageError("paper::World: --origin takes 3 numbers X,Y,Z, not " + std::to_string(xyz.size()));
    }
    return at({xyz[0], xyz[1], xyz[2]}, raw_floats ? Reorigin::off : Reorigin::on);
  }

  /// An instance placed in the scene's own coordinates, moved to the world and made relative to
  /// the origin, in double before the one rounding to float.
  pr::InstanceTransform transform(const pr::Placement& p) const {
    return origin.instance(glm::translate(glm::dmat4(1.0), offset) * glm::dmat4(p.matrix()));
  }
  std::vector<pr::InstanceTransform> transforms(std::span<const pr::Placement> placements) const {
    std::vector<pr::InstanceTransform> out;
    for (const pr::Placement& p : placements) out.push_back(transform(p));
    return out;
  }

  /// The frame's world points (the eye and the light), moved and made relative to the origin.
  void place(SceneConstants& c) const {
    c.camera.eye = glm::vec4(origin.point(offset + glm::dvec3(glm::vec3(c.camera.eye))), c.camera.eye.w);
    c.light_position = origin.point(offset + glm::dvec3(c.light_position));
  }
};

}  // namespace paper
