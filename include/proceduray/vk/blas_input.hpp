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

#if PROCEDURAY_BODIES

namespace proceduray::vk::detail {

PROCEDURAY_DECL Aabb to_aabb(const VkAabbPositionsKHR& b) { return {{b.minX, b.minY, b.minZ}, {b.maxX, b.maxY, b.maxZ}}; }

PROCEDURAY_DECL void check_aabbs(std::span<const AabbGeometry> geometries, std::string_view operation) {
  if (geometries.empty()) {
    throw UsageError(std::string(operation) + ": no geometries given; pass at least one AabbGeometry");
  }
  for (std::size_t g = 0; g < geometries.size(); ++g) {
    if (geometries[g].boxes.empty()) {
      throw InvalidGeometryError(std::string(operation) + ": geometry " + std::to_string(g) +
                                 " has no boxes; give it at least one AABB");
    }
    for (std::size_t i = 0; i < geometries[g].boxes.size(); ++i) {
      const Aabb box = to_aabb(geometries[g].boxes[i]);
      if (!proceduray::detail::valid_box(box)) {
        proceduray::validate(box, std::string(operation) + ": geometry " + std::to_string(g) + " box " +
                                      std::to_string(i));  // throws
      }
    }
  }
}

PROCEDURAY_DECL void check_triangles(std::span<const TriangleGeometry> geometries, std::string_view operation) {
  if (geometries.empty()) {
    throw UsageError(std::string(operation) + ": no geometries given; pass at least one TriangleGeometry");
  }
  for (std::size_t g = 0; g < geometries.size(); ++g) {
    const TriangleGeometry& t = geometries[g];
    auto which = [&] { return std::string(operation) + ": triangle geometry " + std::to_string(g); };
    if (t.indices.empty() || t.indices.size() % 3 != 0) {
      throw InvalidGeometryError(which() + " has " + std::to_string(t.indices.size()) +
                                 " indices; a triangle list needs a non-zero multiple of 3");
    }
    for (std::uint32_t i : t.indices) {
      if (i >= t.vertices.size()) {
        throw InvalidGeometryError(which() + " indexes vertex " + std::to_string(i) + " but has " +
                                   std::to_string(t.vertices.size()) + " vertices; fix the index buffer");
      }
    }
    for (const glm::vec3& v : t.vertices) {
      if (!proceduray::detail::finite(v)) {
        throw InvalidGeometryError(which() + " has a non-finite vertex; give finite positions");
      }
    }
  }
}

PROCEDURAY_DECL void write_aabbs(BlasInput& input, std::span<const AabbGeometry> geometries) {
  VkDeviceSize offset = 0;
  for (const AabbGeometry& g : geometries) {
    input.data.write(g.boxes, offset);
    offset += g.boxes.size_bytes();
  }
}

PROCEDURAY_DECL void write_vertices(BlasInput& input, std::span<const TriangleGeometry> geometries) {
  VkDeviceSize offset = 0;
  for (const TriangleGeometry& t : geometries) {
    input.data.write(t.vertices, offset);
    offset += t.vertices.size_bytes();
  }
}

PROCEDURAY_DECL BlasInput aabb_input(const Context& ctx, std::span<const AabbGeometry> geometries, std::string_view operation,
                                     bool check) {
  if (check) check_aabbs(geometries, operation);
  std::size_t total = 0;
  for (const AabbGeometry& g : geometries) total += g.boxes.size();
  BlasInput in;
  in.data = Buffer(ctx, total * sizeof(VkAabbPositionsKHR),
                   VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                       VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT);
  write_aabbs(in, geometries);
  VkDeviceSize offset = 0;
  for (const AabbGeometry& g : geometries) {
    auto geometry = make<VkAccelerationStructureGeometryKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
    geometry.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
    geometry.flags = g.opaque ? VK_GEOMETRY_OPAQUE_BIT_KHR : 0;
    geometry.geometry.aabbs = make<VkAccelerationStructureGeometryAabbsDataKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR);
    geometry.geometry.aabbs.data.deviceAddress = in.data.address() + offset;
    geometry.geometry.aabbs.stride = sizeof(VkAabbPositionsKHR);
    in.geometries.push_back(geometry);
    in.counts.push_back(static_cast<std::uint32_t>(g.boxes.size()));
    offset += g.boxes.size_bytes();
  }
  return in;
}

PROCEDURAY_DECL BlasInput triangle_input(const Context& ctx, std::span<const TriangleGeometry> geometries,
                                         std::string_view operation, bool check) {
  if (check) check_triangles(geometries, operation);
  std::size_t vertex_count = 0, index_count = 0;
  for (const TriangleGeometry& t : geometries) {
    vertex_count += t.vertices.size();
    index_count += t.indices.size();
  }
  constexpr VkBufferUsageFlags usage = VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                                       VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
  BlasInput in;
  in.data = Buffer(ctx, vertex_count * sizeof(glm::vec3), usage);
  in.indices = Buffer(ctx, index_count * sizeof(std::uint32_t), usage);
  write_vertices(in, geometries);
  VkDeviceSize vertex_offset = 0, index_offset = 0;
  for (const TriangleGeometry& t : geometries) {
    in.indices.write(t.indices, index_offset);
    auto geometry = make<VkAccelerationStructureGeometryKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
    geometry.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
    geometry.flags = t.opaque ? VK_GEOMETRY_OPAQUE_BIT_KHR : 0;
    auto& tri = geometry.geometry.triangles;
    tri = make<VkAccelerationStructureGeometryTrianglesDataKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR);
    tri.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
    tri.vertexData.deviceAddress = in.data.address() + vertex_offset;
    tri.vertexStride = sizeof(glm::vec3);
    tri.maxVertex = static_cast<std::uint32_t>(t.vertices.size() - 1);
    tri.indexType = VK_INDEX_TYPE_UINT32;
    tri.indexData.deviceAddress = in.indices.address() + index_offset;
    in.geometries.push_back(geometry);
    in.counts.push_back(static_cast<std::uint32_t>(t.indices.size() / 3));
    vertex_offset += t.vertices.size_bytes();
    index_offset += t.indices.size_bytes();
  }
  return in;
}

}  // namespace proceduray::vk::detail
#endif  // PROCEDURAY_BODIES
