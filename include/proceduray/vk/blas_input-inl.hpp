// The bodies of proceduray/vk/blas_input.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/blas_input.hpp"

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
