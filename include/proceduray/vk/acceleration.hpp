// Bottom-level (AABB) and top-level acceleration structures, built on the device and waited for.
//
//   VkAabbPositionsKHR box{-1, -1, -1, 1, 1, 1};
//   auto blas = proceduray::vk::build_blas(ctx, {{.boxes = {&box, 1}}});
//   std::vector<proceduray::vk::Instance> instances{
//       {.blas = &blas, .transform = glm::translate(glm::mat4(1), {-1.5f, 0, 0}), .sbt_offset = 0},
//       {.blas = &blas, .transform = glm::translate(glm::mat4(1), {+1.5f, 0, 0}), .sbt_offset = 1}};
//   auto tlas = proceduray::vk::build_tlas(ctx, instances);
//
// build_* record the build, submit it and wait: the result is ready to trace when they return.
#pragma once

#include <proceduray/vk/buffer.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace proceduray::vk {

/// An acceleration structure and the buffer that stores it.
class AccelerationStructure {
 public:
  AccelerationStructure() = default;
  AccelerationStructure(const Context& ctx, VkAccelerationStructureTypeKHR type, VkDeviceSize size);

  VkAccelerationStructureKHR get() const noexcept { return m_handle.get(); }
  VkDeviceAddress address() const noexcept { return m_address; }
  VkDeviceSize size() const noexcept { return m_storage.size(); }

 private:
  Buffer m_storage;  // declared before the handle: the handle is destroyed first
  DeviceHandle<VkAccelerationStructureKHR> m_handle;
  VkDeviceAddress m_address = 0;
};

/// One geometry of a BLAS: axis-aligned boxes in object space, each one procedural primitive.
struct AabbGeometry {
  std::span<const VkAabbPositionsKHR> boxes;  ///< at least one box, min <= max, all finite
  bool opaque = true;                         ///< true: any-hit shaders are skipped
};

/// One instance of a BLAS in the TLAS.
struct Instance {
  const AccelerationStructure* blas = nullptr;  ///< required
  glm::mat4 transform{1.0f};                    ///< object to world; the last row must be (0, 0, 0, 1)
  std::uint32_t custom_index = 0;               ///< gl_InstanceCustomIndexEXT, 24 bits
  std::uint32_t sbt_offset = 0;                 ///< instanceShaderBindingTableRecordOffset, 24 bits
  std::uint8_t mask = 0xFF;                     ///< visibility mask tested against the ray's cull mask
  VkGeometryInstanceFlagsKHR flags = 0;         ///< e.g. VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR
};

inline AccelerationStructure::AccelerationStructure(const Context& ctx, VkAccelerationStructureTypeKHR type,
                                                    VkDeviceSize size)
    : m_storage(ctx, size,
                VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                Buffer::device_local) {
  auto info = make<VkAccelerationStructureCreateInfoKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR);
  info.buffer = m_storage.get();
  info.size = size;
  info.type = type;
  VkAccelerationStructureKHR raw = VK_NULL_HANDLE;
  check(ctx.rt().create_acceleration_structure(ctx.device(), &info, nullptr, &raw), "vkCreateAccelerationStructureKHR");
  m_handle = own(ctx.device(), raw, ctx.rt().destroy_acceleration_structure);
  auto where = make<VkAccelerationStructureDeviceAddressInfoKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR);
  where.accelerationStructure = raw;
  m_address = ctx.rt().get_acceleration_structure_device_address(ctx.device(), &where);
}

namespace detail {

/// Sizes the structure, creates it and a scratch buffer, builds it and waits.
inline AccelerationStructure build_acceleration_structure(const Context& ctx, VkAccelerationStructureTypeKHR type,
                                                          std::span<const VkAccelerationStructureGeometryKHR> geometries,
                                                          std::span<const std::uint32_t> primitive_counts,
                                                          VkBuildAccelerationStructureFlagsKHR flags) {
  auto build = make<VkAccelerationStructureBuildGeometryInfoKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR);
  build.type = type;
  build.flags = flags;
  build.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  build.geometryCount = static_cast<std::uint32_t>(geometries.size());
  build.pGeometries = geometries.data();
  auto sizes = make<VkAccelerationStructureBuildSizesInfoKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR);
  ctx.rt().get_acceleration_structure_build_sizes(ctx.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &build,
                                                  primitive_counts.data(), &sizes);
  AccelerationStructure result(ctx, type, sizes.accelerationStructureSize);
  // Scratch addresses must be multiples of minAccelerationStructureScratchOffsetAlignment (128 on the H100).
  const VkDeviceSize align = ctx.scratch_alignment();
  Buffer scratch(ctx, sizes.buildScratchSize + align,
                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT, Buffer::device_local);
  build.dstAccelerationStructure = result.get();
  build.scratchData.deviceAddress = (scratch.address() + align - 1) / align * align;
  std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges(primitive_counts.size());
  for (std::size_t i = 0; i < ranges.size(); ++i) ranges[i].primitiveCount = primitive_counts[i];
  const VkAccelerationStructureBuildRangeInfoKHR* range_ptr = ranges.data();
  ctx.submit([&](VkCommandBuffer cmd) { ctx.rt().cmd_build_acceleration_structures(cmd, 1, &build, &range_ptr); });
  return result;
}

inline bool finite(float v) { return std::isfinite(v); }

}  // namespace detail

/// Builds a BLAS of procedural geometries (geometry i gets gl_GeometryIndexEXT == i).
inline AccelerationStructure build_blas(const Context& ctx, std::span<const AabbGeometry> geometries,
                                        VkBuildAccelerationStructureFlagsKHR flags =
                                            VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR) {
  if (geometries.empty()) {
    throw std::invalid_argument("build_blas: no geometries given; pass at least one AabbGeometry");
  }
  std::size_t total = 0;
  for (std::size_t g = 0; g < geometries.size(); ++g) {
    if (geometries[g].boxes.empty()) {
      throw std::invalid_argument("build_blas: geometry " + std::to_string(g) + " has no boxes; give it at least one AABB");
    }
    for (std::size_t i = 0; i < geometries[g].boxes.size(); ++i) {
      const VkAabbPositionsKHR& b = geometries[g].boxes[i];
      const float v[] = {b.minX, b.minY, b.minZ, b.maxX, b.maxY, b.maxZ};
      bool ok = b.minX <= b.maxX && b.minY <= b.maxY && b.minZ <= b.maxZ;
      for (float x : v) ok = ok && detail::finite(x);
      if (!ok) {
        throw std::invalid_argument("build_blas: geometry " + std::to_string(g) + " box " + std::to_string(i) + " (" +
                                    std::to_string(b.minX) + ", " + std::to_string(b.minY) + ", " +
                                    std::to_string(b.minZ) + ") - (" + std::to_string(b.maxX) + ", " +
                                    std::to_string(b.maxY) + ", " + std::to_string(b.maxZ) +
                                    ") is not a box; each min must be <= its max and all bounds finite");
      }
    }
    total += geometries[g].boxes.size();
  }
  Buffer boxes(ctx, total * sizeof(VkAabbPositionsKHR),
               VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                   VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT);
  std::vector<VkAccelerationStructureGeometryKHR> described;
  std::vector<std::uint32_t> counts;
  VkDeviceSize offset = 0;
  for (const AabbGeometry& g : geometries) {
    boxes.write(g.boxes, offset);
    auto geometry = make<VkAccelerationStructureGeometryKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
    geometry.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
    geometry.flags = g.opaque ? VK_GEOMETRY_OPAQUE_BIT_KHR : 0;
    geometry.geometry.aabbs = make<VkAccelerationStructureGeometryAabbsDataKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR);
    geometry.geometry.aabbs.data.deviceAddress = boxes.address() + offset;
    geometry.geometry.aabbs.stride = sizeof(VkAabbPositionsKHR);
    described.push_back(geometry);
    counts.push_back(static_cast<std::uint32_t>(g.boxes.size()));
    offset += g.boxes.size_bytes();
  }
  return detail::build_acceleration_structure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, described, counts,
                                              flags);
}

/// Builds a TLAS over `instances` (an empty list gives a TLAS that every ray misses).
inline AccelerationStructure build_tlas(const Context& ctx, std::span<const Instance> instances,
                                        VkBuildAccelerationStructureFlagsKHR flags =
                                            VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR) {
  std::vector<VkAccelerationStructureInstanceKHR> packed(instances.size());
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const Instance& in = instances[i];
    const std::string which = "build_tlas: instance " + std::to_string(i);
    if (in.blas == nullptr || in.blas->get() == VK_NULL_HANDLE) {
      throw std::invalid_argument(which + " has no BLAS; set Instance::blas to a built structure");
    }
    if (in.custom_index >= (1u << 24) || in.sbt_offset >= (1u << 24)) {
      throw std::invalid_argument(which + " custom_index " + std::to_string(in.custom_index) + " or sbt_offset " +
                                  std::to_string(in.sbt_offset) + " does not fit in 24 bits");
    }
    const glm::mat4& m = in.transform;
    bool finite = true;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) finite = finite && detail::finite(m[c][r]);
    if (!finite || std::abs(glm::determinant(glm::mat3(m))) < 1e-30f) {
      throw std::invalid_argument(which + " transform is " + (finite ? "singular" : "not finite") +
                                  "; give every instance an invertible, finite object-to-world matrix");
    }
    VkAccelerationStructureInstanceKHR& out = packed[i];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) out.transform.matrix[r][c] = m[c][r];  // glm is column-major, Vulkan row-major 3x4
    out.instanceCustomIndex = in.custom_index;
    out.mask = in.mask;
    out.instanceShaderBindingTableRecordOffset = in.sbt_offset;
    out.flags = in.flags;
    out.accelerationStructureReference = in.blas->address();
  }
  Buffer buffer(ctx, std::max<VkDeviceSize>(1, packed.size()) * sizeof(VkAccelerationStructureInstanceKHR),
                VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                    VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT);
  buffer.write(std::span<const VkAccelerationStructureInstanceKHR>(packed));
  auto geometry = make<VkAccelerationStructureGeometryKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
  geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  geometry.geometry.instances = make<VkAccelerationStructureGeometryInstancesDataKHR>(
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR);
  geometry.geometry.instances.data.deviceAddress = buffer.address();
  const std::uint32_t count = static_cast<std::uint32_t>(packed.size());
  return detail::build_acceleration_structure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, {&geometry, 1},
                                              {&count, 1}, flags);
}

}  // namespace proceduray::vk
