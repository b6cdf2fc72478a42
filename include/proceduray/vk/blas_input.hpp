// What a BLAS is built from: procedural boxes or triangle meshes, checked by the scene's rules,
// uploaded to host-visible buffers and described for Vulkan (build_blas, RefittableBlas).
//
//   const VkAabbPositionsKHR box{-1, -1, -1, 1, 1, 1};
//   const proceduray::vk::AabbGeometry boxes{.boxes = {&box, 1}, .opaque = false};   // any-hit runs
//   const glm::vec3 quad[] = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
//   const std::uint32_t tris[] = {0, 1, 2, 0, 2, 3};
//   const proceduray::vk::TriangleGeometry mesh{.vertices = quad, .indices = tris};
//
// Geometry i of a list gets gl_GeometryIndexEXT == i. Inputs are checked by the scene's rules
// (scene/geometry.hpp): a bad box or vertex throws InvalidGeometryError, an empty list UsageError.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>
#include <proceduray/scene/geometry.hpp>
#include <proceduray/vk/buffer.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace proceduray::vk {

/// One geometry of a BLAS: axis-aligned boxes in object space, each one procedural primitive.
struct AabbGeometry {
  std::span<const VkAabbPositionsKHR> boxes;  ///< at least one box, min <= max, all finite
  bool opaque = true;                         ///< true: any-hit shaders are skipped
};

/// One geometry of a triangle BLAS: positions and a triangle list.
struct TriangleGeometry {
  std::span<const glm::vec3> vertices;     ///< positions, finite
  std::span<const std::uint32_t> indices;  ///< three per triangle, each < vertices.size()
  bool opaque = true;                      ///< true: any-hit shaders are skipped
};

namespace detail {

/// A BLAS's inputs on the device: boxes or vertices (and indices), described for a build.
/// Host-visible, so a refit rewrites them in place.
struct BlasInput {
  Buffer data;     ///< VkAabbPositionsKHR, or vertices
  Buffer indices;  ///< triangles only
  std::vector<VkAccelerationStructureGeometryKHR> geometries;
  std::vector<std::uint32_t> counts;  ///< primitives per geometry
};

/// The scene's box for Vulkan's (same six floats, same order).
PROCEDURAY_DECL Aabb to_aabb(const VkAabbPositionsKHR& b);

/// Throws UsageError for an empty list, InvalidGeometryError for a geometry without boxes or a box
/// that is not one (the scene's rule, proceduray::validate(Aabb)).
PROCEDURAY_DECL void check_aabbs(std::span<const AabbGeometry> geometries, std::string_view operation);

/// Throws UsageError for an empty list, InvalidGeometryError for a bad triangle list or a non-finite vertex.
PROCEDURAY_DECL void check_triangles(std::span<const TriangleGeometry> geometries, std::string_view operation);

/// Writes boxes into `input` (laid out by aabb_input for the same counts).
PROCEDURAY_DECL void write_aabbs(BlasInput& input, std::span<const AabbGeometry> geometries);

/// Writes vertices into `input` (laid out by triangle_input for the same counts).
PROCEDURAY_DECL void write_vertices(BlasInput& input, std::span<const TriangleGeometry> geometries);

/// Checks (unless `check` is off: a plan's geometry), uploads and describes procedural geometries.
PROCEDURAY_DECL BlasInput aabb_input(const Context& ctx, std::span<const AabbGeometry> geometries, std::string_view operation,
                                     bool check = true);

/// The same for triangle geometries.
PROCEDURAY_DECL BlasInput triangle_input(const Context& ctx, std::span<const TriangleGeometry> geometries,
                                         std::string_view operation, bool check = true);

}  // namespace detail

}  // namespace proceduray::vk

#include "proceduray/vk/blas_input-inl.hpp"  // the bodies (config.hpp)
