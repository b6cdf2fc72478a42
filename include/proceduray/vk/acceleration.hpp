// Acceleration structures: the handle and its storage, how one is built on the device (sized,
// given scratch, built, compacted), and bottom-level builds over boxes or triangles.
//
//   VkAabbPositionsKHR box{-1, -1, -1, 1, 1, 1};
//   const proceduray::vk::AabbGeometry boxes{.boxes = {&box, 1}};
//   auto blas = proceduray::vk::build_blas(ctx, {&boxes, 1});                              // boxes
//
//   const glm::vec3 quad[] = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
//   const std::uint32_t tris[] = {0, 1, 2, 0, 2, 3};
//   const proceduray::vk::TriangleGeometry mesh{.vertices = quad, .indices = tris};
//   auto plane = proceduray::vk::build_blas(ctx, {&mesh, 1}, {.compact = false});        // triangles
//   blas.address();                                 // for a TLAS instance (vk/tlas.hpp)
//
// build_blas records the build, submits it and waits: the result is ready to trace when it returns.
// Static BLASes are compacted by default (BuildOptions::compact): the copy is what stays.
// Geometry is checked by blas_input.hpp (InvalidGeometryError, UsageError); the TLAS is in tlas.hpp.
#pragma once

#include <proceduray/vk/blas_input.hpp>
#include <proceduray/vk/buffer.hpp>

#include <cstdint>
#include <span>
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

/// How a structure is built.
struct BuildOptions {
  bool compact = true;        ///< compact after building (BLAS only; ignored with allow_update); default on
  bool allow_update = false;  ///< keep it refittable with update(); default off
  bool fast_trace = true;     ///< prefer trace speed over build speed; default on
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

inline VkBuildAccelerationStructureFlagsKHR build_flags(const BuildOptions& options, bool may_compact) {
  VkBuildAccelerationStructureFlagsKHR flags = options.fast_trace ? VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR
                                                                  : VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_BUILD_BIT_KHR;
  if (options.allow_update) flags |= VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_UPDATE_BIT_KHR;
  else if (options.compact && may_compact) flags |= VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR;
  return flags;
}

/// A scratch buffer whose device address honours minAccelerationStructureScratchOffsetAlignment (128 on the H100).
struct Scratch {
  Buffer buffer;
  VkDeviceAddress address = 0;
  Scratch() = default;
  Scratch(const Context& ctx, VkDeviceSize size) {
    const VkDeviceSize align = ctx.scratch_alignment();
    buffer = Buffer(ctx, size + align, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                    Buffer::device_local);
    address = (buffer.address() + align - 1) / align * align;
  }
};

/// Copies `source` into a structure of its compacted size and returns the copy.
inline AccelerationStructure compact(const Context& ctx, const AccelerationStructure& source,
                                     VkAccelerationStructureTypeKHR type) {
  auto query_info = make<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
  query_info.queryType = VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR;
  query_info.queryCount = 1;
  VkQueryPool raw_pool = VK_NULL_HANDLE;
  check(vkCreateQueryPool(ctx.device(), &query_info, nullptr, &raw_pool), "vkCreateQueryPool");
  auto pool = own(ctx.device(), raw_pool, vkDestroyQueryPool);
  VkAccelerationStructureKHR handle = source.get();
  ctx.submit([&](VkCommandBuffer cmd) {
    vkCmdResetQueryPool(cmd, raw_pool, 0, 1);
    ctx.rt().cmd_write_acceleration_structures_properties(
        cmd, 1, &handle, VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR, raw_pool, 0);
  });
  VkDeviceSize compacted = 0;
  check(vkGetQueryPoolResults(ctx.device(), raw_pool, 0, 1, sizeof compacted, &compacted, sizeof compacted,
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
        "vkGetQueryPoolResults", "compacted acceleration structure size");
  AccelerationStructure result(ctx, type, compacted);
  auto copy = make<VkCopyAccelerationStructureInfoKHR>(VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR);
  copy.src = source.get();
  copy.dst = result.get();
  copy.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR;
  ctx.submit([&](VkCommandBuffer cmd) { ctx.rt().cmd_copy_acceleration_structure(cmd, &copy); });
  return result;
}

/// Makes a recorded build's writes visible to `readers` (later builds that reference it, traces).
inline void after_build_barrier(VkCommandBuffer cmd, VkPipelineStageFlags readers) {
  auto barrier = make<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  barrier.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
  barrier.dstAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, readers, 0, 1, &barrier, 0, nullptr,
                       0, nullptr);
}

/// Sizes the structure, creates it and a scratch buffer, builds it and waits; compacts when the flags allow.
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
  Scratch scratch(ctx, sizes.buildScratchSize);
  build.dstAccelerationStructure = result.get();
  build.scratchData.deviceAddress = scratch.address;
  std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges(primitive_counts.size());
  for (std::size_t i = 0; i < ranges.size(); ++i) ranges[i].primitiveCount = primitive_counts[i];
  const VkAccelerationStructureBuildRangeInfoKHR* range_ptr = ranges.data();
  ctx.submit([&](VkCommandBuffer cmd) { ctx.rt().cmd_build_acceleration_structures(cmd, 1, &build, &range_ptr); });
  if ((flags & VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR) != 0) return compact(ctx, result, type);
  return result;
}

}  // namespace detail

/// Builds a BLAS of procedural geometries (geometry i gets gl_GeometryIndexEXT == i).
inline AccelerationStructure build_blas(const Context& ctx, std::span<const AabbGeometry> geometries,
                                        const BuildOptions& options = {}) {
  const detail::BlasInput in = detail::aabb_input(ctx, geometries, "build_blas");
  return detail::build_acceleration_structure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, in.geometries,
                                              in.counts, detail::build_flags(options, true));
}

/// Builds a BLAS of triangle geometries (geometry i gets gl_GeometryIndexEXT == i).
inline AccelerationStructure build_blas(const Context& ctx, std::span<const TriangleGeometry> geometries,
                                        const BuildOptions& options = {}) {
  const detail::BlasInput in = detail::triangle_input(ctx, geometries, "build_blas");
  return detail::build_acceleration_structure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, in.geometries,
                                              in.counts, detail::build_flags(options, true));
}

}  // namespace proceduray::vk
