// Planes that cut a procedural shape, as data: the report's figure 3 cuts its Julia set by one
// plane, figure 4 by two. A uniform or record carries them (a registered struct), so moving a cut
// is a host change, never a shader edit.
//
//   proceduray::CutPlanes cuts = proceduray::make_cut_planes({proceduray::cut_plane({0.3f, 0.3f, 1.0f}, 0.1f),
//                                                            proceduray::cut_plane({-1.0f, 0.0f, 0.0f}, 0.4f)});
//   // GLSL (primitives/julia.glsl): julia_cuts_distance(p, c, n, cuts.plane[0], cuts.plane[1], cuts.count)
//
// A plane (xyz, w) keeps the points with dot(xyz, p) <= w; xyz is unit length, so dot(xyz, p) - w
// is a distance and max() with a distance estimate stays one (the cut face is then exact).
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>
#include <proceduray/shader/field_list.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>

namespace proceduray {

/// Planes one CutPlanes block holds: julia.glsl's julia_cuts_distance takes two.
inline constexpr std::uint32_t max_cut_planes = 2;

/// Up to max_cut_planes planes; the shaders use the first `count`.
struct CutPlanes {
  glm::vec4 plane[max_cut_planes];
  std::uint32_t count = 0;
  std::uint32_t pad0 = 0, pad1 = 0, pad2 = 0;
};
PROCEDURAY_STRUCT(CutPlanes, scalar, plane, count, pad0, pad1, pad2);

/// The plane through the points p with dot(normalize(normal), p) = offset, keeping the side
/// `normal` points away from; throws UsageError for a zero or non-finite normal.
PROCEDURAY_DECL glm::vec4 cut_plane(glm::vec3 normal, float offset);

/// The block; throws UsageError naming the plane and the fix for more than max_cut_planes, a
/// non-finite value, or a normal that is not unit length (to 1e-3: build planes with cut_plane).
PROCEDURAY_DECL CutPlanes make_cut_planes(std::span<const glm::vec4> planes);
PROCEDURAY_DECL CutPlanes make_cut_planes(std::initializer_list<glm::vec4> planes);

}  // namespace proceduray

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
