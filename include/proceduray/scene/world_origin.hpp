// Scenes far from the origin: keep the world in double and give the GPU float coordinates
// relative to an origin near the camera (re-origin, or camera-relative rendering).
//
//   proceduray::WorldOrigin origin(camera_eye);                       // doubles, near the camera
//   auto t = origin.instance(world_from_object);                      // glm::dmat4 -> InstanceTransform
//   glm::vec3 eye = origin.point(camera_eye);                          // what the raygen gets: (0, 0, 0)
//   glm::dvec3 hit = origin.world(hit_point);                          // back to world coordinates
//   if (origin.needs_reorigin(camera_eye, footprint)) origin = proceduray::WorldOrigin(camera_eye);
//
// Why: a float holds 24 bits, so a world coordinate x is rounded to |x| * 2^-24. The camera's
// eye, every instance's translation and the driver's world-to-object transform of each ray
// are floats, so a sphere 10^6 units out is hit up to ~0.06 units off, whatever its distance
// from the camera: 1.7 % of t at t = 4, dozens of pixel footprints. The pixel only resolves
// its footprint (pixel angle x t), so what must stay small is the coordinates' spacing next
// to the footprint. Subtracting an origin near the camera IN DOUBLE before the conversion makes
// every float coordinate a distance from the camera: the spacing then follows t, as the
// footprint does (tests/scene/world_origin_test.cpp measures both ways for 10^0..10^7).
//
// The origin is the user's to move: re-origin (and re-upload the transforms) when the camera
// has travelled so far from it that needs_reorigin says its spacing is no longer small next
// to the footprint. Rotations and scales pass through unchanged: only the translation column
// is shifted, so object-space shaders see the same rays up to the (now small) rounding.
#pragma once

#include <proceduray/config.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/glm.hpp>

#include "proceduray/error.hpp"
#include "proceduray/scene/geometry.hpp"

namespace proceduray {

/// Spacing of floats at magnitude |x| (the unit in the last place): 2^(exponent - 23); the
/// smallest normal float's spacing below it. What a float coordinate of size |x| is rounded to.
PROCEDURAY_DECL double float_spacing(double x);

/// A world origin in double; converts world points and transforms to float coordinates
/// relative to it (see the header).
class WorldOrigin {
 public:
  WorldOrigin() = default;
  explicit WorldOrigin(glm::dvec3 origin) : origin_(origin) {
    if (!finite(origin)) fail("WorldOrigin", "origin " + show(origin) + " is not finite", "pass a finite point near the camera");
  }

  glm::dvec3 origin() const { return origin_; }

  /// p - origin, rounded once to float.
  glm::vec3 point(glm::dvec3 p) const {
    if (!finite(p)) fail("WorldOrigin::point", "point " + show(p) + " is not finite", "pass a finite world point");
    return glm::vec3(p - origin_);
  }

  /// The world point of float coordinates relative to this origin.
  glm::dvec3 world(glm::vec3 local) const { return origin_ + glm::dvec3(local); }

  /// world_from_object with its translation made relative to the origin, rounded once to
  /// float. Throws UsageError for a non-finite or non-affine matrix (last row not 0 0 0 1).
  glm::mat4 transform(const glm::dmat4& world_from_object) const {
    constexpr const char* call = "WorldOrigin::transform";
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) {
        if (!std::isfinite(world_from_object[c][r])) {
          fail(call, "element [" + std::to_string(c) + "][" + std::to_string(r) + "] (column, row) is " +
                         std::to_string(world_from_object[c][r]),
               "pass a finite matrix");
        }
      }
    }
    const glm::dvec4 last(world_from_object[0][3], world_from_object[1][3], world_from_object[2][3], world_from_object[3][3]);
    if (last != glm::dvec4(0.0, 0.0, 0.0, 1.0)) {
      fail(call, "the last row is " + show(last) + ", not (0, 0, 0, 1)",
           "pass an affine transform (instances take 3x4 matrices: no projection)");
    }
    glm::dmat4 m = world_from_object;
    m[3] -= glm::dvec4(origin_, 0.0);
    return glm::mat4(m);
  }

  /// transform() as an instance's 3x4 rows.
  InstanceTransform instance(const glm::dmat4& world_from_object) const {
    return instance_transform(transform(world_from_object));
  }

  /// The rounding of a float coordinate of the world point p relative to this origin: the
  /// spacing at its largest component.
  double spacing_at(glm::dvec3 p) const {
    const glm::dvec3 d = glm::abs(p - origin_);
    return float_spacing(std::max(d.x, std::max(d.y, d.z)));
  }

  /// Whether a camera at `eye` whose nearest pixel footprint is `footprint` (world length:
  /// pixel angle x nearest t) sees coordinate rounding: the spacing at the eye exceeds
  /// `budget` footprints. Move the origin to the eye when it does. Throws UsageError for a
  /// footprint or budget that is not positive and finite.
  bool needs_reorigin(glm::dvec3 eye, double footprint, double budget = 1.0 / 64.0) const {
    constexpr const char* call = "WorldOrigin::needs_reorigin";
    if (!(footprint > 0.0) || !std::isfinite(footprint)) {
      fail(call, "footprint " + std::to_string(footprint) + " is not positive and finite",
           "pass the pixel angle times the nearest distance the camera sees");
    }
    if (!(budget > 0.0) || !std::isfinite(budget)) {
      fail(call, "budget " + std::to_string(budget) + " is not positive and finite",
           "pass the share of a footprint the rounding may take (default 1/64)");
    }
    return spacing_at(eye) > budget * footprint;
  }

 private:
  static bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
  static std::string show(glm::dvec3 v) {
    return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
  }
  static std::string show(glm::dvec4 v) {
    return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ", " +
           std::to_string(v.w) + ")";
  }
  [[noreturn]] static void fail(const char* call, const std::string& what, const std::string& fix) {
    throw UsageError(std::string(call) + ": " + what + "; " + fix);
  }

  glm::dvec3 origin_{0.0};
};

}  // namespace proceduray

#include "proceduray/scene/world_origin-inl.hpp"  // the bodies (config.hpp)
