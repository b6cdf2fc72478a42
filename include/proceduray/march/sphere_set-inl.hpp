// The bodies of proceduray/march/sphere_set.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/march/sphere_set.hpp"

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
