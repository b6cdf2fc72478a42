// The bodies of proceduray/vk/acceleration.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/acceleration.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk {

PROCEDURAY_DECL AccelerationStructure::AccelerationStructure(const Context& ctx, VkAccelerationStructureTypeKHR type,
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
  m_handle = own(ctx, raw, ctx.rt().destroy_acceleration_structure);
  auto where = make<VkAccelerationStructureDeviceAddressInfoKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR);
  where.accelerationStructure = raw;
  m_address = ctx.rt().get_acceleration_structure_device_address(ctx.device(), &where);
}

}  // namespace proceduray::vk

namespace proceduray::vk::detail {

PROCEDURAY_DECL VkBuildAccelerationStructureFlagsKHR build_flags(const BuildOptions& options, bool may_compact) {
  VkBuildAccelerationStructureFlagsKHR flags = options.fast_trace ? VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR
                                                                  : VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_BUILD_BIT_KHR;
  if (options.allow_update) flags |= VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_UPDATE_BIT_KHR;
  else if (options.compact && may_compact) flags |= VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR;
  return flags;
}

PROCEDURAY_DECL void after_build_barrier(VkCommandBuffer cmd, VkPipelineStageFlags readers) {
  auto barrier = make<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  barrier.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
  barrier.dstAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, readers, 0, 1, &barrier, 0, nullptr,
                       0, nullptr);
}

PROCEDURAY_DECL VkAccelerationStructureBuildGeometryInfoKHR geometry_info(const BuildCommand& c) {
  auto info = make<VkAccelerationStructureBuildGeometryInfoKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR);
  info.type = c.type;
  info.flags = c.flags;
  info.mode = c.mode;
  info.srcAccelerationStructure = c.mode == VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR ? c.dst : VK_NULL_HANDLE;
  info.dstAccelerationStructure = c.dst;
  info.geometryCount = static_cast<std::uint32_t>(c.geometries.size());
  info.pGeometries = c.geometries.data();
  info.scratchData.deviceAddress = c.scratch;
  return info;
}

PROCEDURAY_DECL VkAccelerationStructureBuildSizesInfoKHR build_sizes(const Context& ctx, const BuildCommand& c) {
  const auto info = geometry_info(c);
  auto sizes = make<VkAccelerationStructureBuildSizesInfoKHR>(VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR);
  ctx.rt().get_acceleration_structure_build_sizes(ctx.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info,
                                                  c.counts.data(), &sizes);
  return sizes;
}

PROCEDURAY_DECL void record_builds(const Context& ctx, VkCommandBuffer cmd, std::span<const BuildCommand> builds,
                                   VkPipelineStageFlags readers) {
  if (builds.empty()) return;
  std::vector<VkAccelerationStructureBuildGeometryInfoKHR> infos;
  std::vector<std::vector<VkAccelerationStructureBuildRangeInfoKHR>> ranges(builds.size());
  std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> range_ptrs;
  for (std::size_t b = 0; b < builds.size(); ++b) {
    infos.push_back(geometry_info(builds[b]));
    for (std::uint32_t count : builds[b].counts) ranges[b].push_back({count, 0, 0, 0});
    range_ptrs.push_back(ranges[b].data());
  }
  ctx.rt().cmd_build_acceleration_structures(cmd, static_cast<std::uint32_t>(infos.size()), infos.data(),
                                             range_ptrs.data());
  after_build_barrier(cmd, readers);
}

PROCEDURAY_DECL std::vector<AccelerationStructure> compact_all(const Context& ctx, std::span<const AccelerationStructure> built,
                                                               VkAccelerationStructureTypeKHR type, VkQueryPool pool) {
  const auto n = static_cast<std::uint32_t>(built.size());
  std::vector<VkDeviceSize> sizes(n);
  check(vkGetQueryPoolResults(ctx.device(), pool, 0, n, n * sizeof(VkDeviceSize), sizes.data(), sizeof(VkDeviceSize),
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
        "vkGetQueryPoolResults", "compacted acceleration structure sizes");
  std::vector<AccelerationStructure> compacted;
  for (VkDeviceSize size : sizes) compacted.emplace_back(ctx, type, size);
  ctx.submit([&](VkCommandBuffer cmd) {
    for (std::uint32_t i = 0; i < n; ++i) {
      auto copy = make<VkCopyAccelerationStructureInfoKHR>(VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR);
      copy.src = built[i].get();
      copy.dst = compacted[i].get();
      copy.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR;
      ctx.rt().cmd_copy_acceleration_structure(cmd, &copy);
    }
    // The copies write in the build stage: a TLAS build and traces read them.
    after_build_barrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR |
                                 VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR);
  });
  return compacted;
}

PROCEDURAY_DECL std::vector<AccelerationStructure> build_structures(const Context& ctx, std::vector<BuildCommand> commands) {
  if (commands.empty()) return {};
  const VkAccelerationStructureTypeKHR type = commands.front().type;
  std::vector<AccelerationStructure> built;
  std::vector<VkDeviceSize> scratch_sizes;
  for (const BuildCommand& c : commands) {
    const auto sizes = build_sizes(ctx, c);
    built.emplace_back(ctx, type, sizes.accelerationStructureSize);
    scratch_sizes.push_back(sizes.buildScratchSize);
  }
  const BatchScratch scratch(ctx, scratch_sizes);
  for (std::size_t i = 0; i < commands.size(); ++i) {
    commands[i].dst = built[i].get();
    commands[i].scratch = scratch.scratch(i);
  }
  const bool compact = (commands.front().flags & VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR) != 0;
  const auto n = static_cast<std::uint32_t>(commands.size());
  DeviceHandle<VkQueryPool> pool;
  if (compact) {
    auto query_info = make<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    query_info.queryType = VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR;
    query_info.queryCount = n;
    VkQueryPool raw = VK_NULL_HANDLE;
    check(vkCreateQueryPool(ctx.device(), &query_info, nullptr, &raw), "vkCreateQueryPool");
    pool = own(ctx, raw, vkDestroyQueryPool);
  }
  ctx.submit([&](VkCommandBuffer cmd) {
    if (compact) vkCmdResetQueryPool(cmd, pool.get(), 0, n);
    record_builds(ctx, cmd, commands, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR |
                                          VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR);
    if (!compact) return;
    std::vector<VkAccelerationStructureKHR> handles;
    for (const AccelerationStructure& s : built) handles.push_back(s.get());
    ctx.rt().cmd_write_acceleration_structures_properties(
        cmd, n, handles.data(), VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR, pool.get(), 0);
  });
  if (!compact) return built;
  return compact_all(ctx, built, type, pool.get());
}

}  // namespace proceduray::vk::detail

namespace proceduray::vk {

PROCEDURAY_DECL std::vector<AccelerationStructure> build_blases(const Context& ctx, std::span<const BlasGeometries> blases,
                                                                const BuildOptions& options) {
  std::vector<detail::BlasInput> inputs;  // checked and uploaded first: nothing is built if one is bad
  for (std::size_t b = 0; b < blases.size(); ++b) {
    const std::string operation = "build_blases: BLAS " + std::to_string(b);
    if (!blases[b].boxes.empty() && !blases[b].triangles.empty()) {
      throw UsageError(operation + " has both boxes and triangles; a BLAS holds one kind: give each its own");
    }
    inputs.push_back(blases[b].triangles.empty() ? detail::aabb_input(ctx, blases[b].boxes, operation, !options.planned)
                                                 : detail::triangle_input(ctx, blases[b].triangles, operation, !options.planned));
  }
  std::vector<detail::BuildCommand> commands;
  for (const detail::BlasInput& in : inputs) {
    commands.push_back({.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
                        .flags = detail::build_flags(options, true), .geometries = in.geometries, .counts = in.counts});
  }
  return detail::build_structures(ctx, std::move(commands));
}

PROCEDURAY_DECL AccelerationStructure build_blas(const Context& ctx, std::span<const AabbGeometry> geometries,
                                                 const BuildOptions& options) {
  const detail::BlasInput in = detail::aabb_input(ctx, geometries, "build_blas", !options.planned);
  return std::move(detail::build_structures(
      ctx, {{.flags = detail::build_flags(options, true), .geometries = in.geometries, .counts = in.counts}})[0]);
}

PROCEDURAY_DECL AccelerationStructure build_blas(const Context& ctx, std::span<const TriangleGeometry> geometries,
                                                 const BuildOptions& options) {
  const detail::BlasInput in = detail::triangle_input(ctx, geometries, "build_blas", !options.planned);
  return std::move(detail::build_structures(
      ctx, {{.flags = detail::build_flags(options, true), .geometries = in.geometries, .counts = in.counts}})[0]);
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
