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

#include "proceduray/march/cut_planes-inl.hpp"  // the bodies (config.hpp)
