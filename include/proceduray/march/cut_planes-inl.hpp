// The bodies of proceduray/march/cut_planes.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/march/cut_planes.hpp"

#if PROCEDURAY_BODIES
namespace proceduray {

PROCEDURAY_DECL glm::vec4 cut_plane(glm::vec3 normal, float offset) {
  const float len = glm::length(normal);
  if (!(len > 0.0f) || !std::isfinite(len) || !std::isfinite(offset)) {
    throw UsageError("cut_plane: normal (" + std::to_string(normal.x) + ", " + std::to_string(normal.y) + ", " +
                     std::to_string(normal.z) + ") with offset " + std::to_string(offset) +
                     " is zero or not finite; give the direction the removed side lies in");
  }
  return glm::vec4(normal / len, offset);
}

PROCEDURAY_DECL CutPlanes make_cut_planes(std::span<const glm::vec4> planes) {
  if (planes.size() > max_cut_planes) {
    throw UsageError("make_cut_planes: " + std::to_string(planes.size()) + " planes, over the limit of " +
                     std::to_string(max_cut_planes) + " (proceduray::max_cut_planes); intersect fewer");
  }
  CutPlanes out;
  out.count = static_cast<std::uint32_t>(planes.size());
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const glm::vec4 p = planes[i];
    const std::string which = "make_cut_planes: plane " + std::to_string(i);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(p.w)) {
      throw UsageError(which + " is not finite (NaN or infinity); check the values it is computed from");
    }
    const float len = glm::length(glm::vec3(p));
    if (std::abs(len - 1.0f) > 1.0e-3f) {
      throw UsageError(which + " has a normal of length " + std::to_string(len) + "; the cut is a distance only "
                       "with a unit normal: build it with cut_plane(normal, offset)");
    }
    out.plane[i] = p;
  }
  return out;
}

PROCEDURAY_DECL CutPlanes make_cut_planes(std::initializer_list<glm::vec4> planes) {
  return make_cut_planes(std::span<const glm::vec4>(planes.begin(), planes.size()));
}

}  // namespace proceduray
#endif  // PROCEDURAY_BODIES
