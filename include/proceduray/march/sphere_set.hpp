// Several spheres as one procedural primitive, as data (the D3D12 sample's "multiple spheres"
// is three fixed in GLSL): up to max_sphere_set spheres in a uniform or record block, and the
// box that holds them, for the procedural geometry.
//
//   proceduray::SphereSet balls = proceduray::make_sphere_set({{0.0f, 0.0f, 0.0f, 0.5f}, {0.7f, 0.2f, 0.0f, 0.25f}});
//   scene.add_geometry("balls", proceduray::GeometryDesc::procedural({proceduray::sphere_set_bounds(balls)}));
//   // GLSL: #include "primitives/sphere_set.glsl"
//   //       ray_spheres(o, d, sphere_list(constants.balls), 1.0, t_lo, t_hi, 0u, t, n)
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>
#include <proceduray/scene/geometry.hpp>
#include <proceduray/shader/field_list.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>

namespace proceduray {

/// Spheres one SphereSet holds: spheres.glsl's spheres_max.
inline constexpr std::uint32_t max_sphere_set = 8;

/// Spheres: sphere[i].xyz the centre, sphere[i].w the radius; the shaders use the first `count`.
struct SphereSet {
  glm::vec4 sphere[max_sphere_set];
  std::uint32_t count = 0;
  std::uint32_t pad0 = 0, pad1 = 0, pad2 = 0;
};
PROCEDURAY_STRUCT(SphereSet, scalar, sphere, count, pad0, pad1, pad2);

/// The block; throws UsageError naming the sphere and the fix for none, more than
/// max_sphere_set, a radius <= 0 or a non-finite value.
PROCEDURAY_DECL SphereSet make_sphere_set(std::span<const glm::vec4> spheres);
PROCEDURAY_DECL SphereSet make_sphere_set(std::initializer_list<glm::vec4> spheres);

/// The box holding every sphere of the set (radii times radius_scale); throws UsageError for
/// a set with no sphere.
PROCEDURAY_DECL Aabb sphere_set_bounds(const SphereSet& set, float radius_scale = 1.0f);

}  // namespace proceduray

#if PROCEDURAY_BODIES

namespace proceduray {

PROCEDURAY_DECL SphereSet make_sphere_set(std::span<const glm::vec4> spheres) {
  if (spheres.empty()) throw UsageError("make_sphere_set: 0 spheres; give at least one (centre xyz, radius w)");
  if (spheres.size() > max_sphere_set) {
    throw UsageError("make_sphere_set: " + std::to_string(spheres.size()) + " spheres, over the limit of " +
                     std::to_string(max_sphere_set) + " (proceduray::max_sphere_set); split them into objects");
  }
  SphereSet out;
  out.count = static_cast<std::uint32_t>(spheres.size());
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const glm::vec4 s = spheres[i];
    const std::string which = "make_sphere_set: sphere " + std::to_string(i);
    if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.z) || !std::isfinite(s.w)) {
      throw UsageError(which + " is not finite (NaN or infinity); check the values it is computed from");
    }
    if (!(s.w > 0.0f)) throw UsageError(which + " has radius " + std::to_string(s.w) + "; give a positive radius");
    out.sphere[i] = s;
  }
  return out;
}

PROCEDURAY_DECL SphereSet make_sphere_set(std::initializer_list<glm::vec4> spheres) {
  return make_sphere_set(std::span<const glm::vec4>(spheres.begin(), spheres.size()));
}

PROCEDURAY_DECL Aabb sphere_set_bounds(const SphereSet& set, float radius_scale) {
  if (set.count == 0 || set.count > max_sphere_set) {
    throw UsageError("sphere_set_bounds: the set has " + std::to_string(set.count) + " spheres; build it with "
                     "make_sphere_set (1 to " + std::to_string(max_sphere_set) + " spheres)");
  }
  Aabb box{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
  for (std::uint32_t i = 0; i < set.count; ++i) {
    const glm::vec3 c(set.sphere[i]);
    const glm::vec3 r(set.sphere[i].w * radius_scale);
    box.min = glm::min(box.min, c - r);
    box.max = glm::max(box.max, c + r);
  }
  return box;
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
