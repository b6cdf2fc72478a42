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
#include <proceduray/aabb.hpp>
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

#include "proceduray/march/sphere_set-inl.hpp"  // the bodies (config.hpp)
