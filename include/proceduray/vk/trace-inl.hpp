// The bodies of proceduray/vk/trace.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/trace.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk {

PROCEDURAY_DECL void check_trace_size(const Context& ctx, std::uint32_t width, std::uint32_t height) {
  const auto& limits = ctx.properties().limits;
  const std::uint64_t max_x = std::uint64_t{limits.maxComputeWorkGroupCount[0]} * limits.maxComputeWorkGroupSize[0];
  const std::uint64_t max_y = std::uint64_t{limits.maxComputeWorkGroupCount[1]} * limits.maxComputeWorkGroupSize[1];
  const std::uint64_t max_rays = ctx.ray_tracing_properties().maxRayDispatchInvocationCount;
  const std::uint64_t rays = std::uint64_t{width} * height;
  if (width == 0 || height == 0 || width > max_x || height > max_y || rays > max_rays) {
    const std::string message = "trace: size " + std::to_string(width) + "x" + std::to_string(height) +
                                " cannot be dispatched on " + ctx.name() + "; width must be 1.." +
                                std::to_string(max_x) + ", height 1.." + std::to_string(max_y) +
                                " and width*height at most " + std::to_string(max_rays) +
                                " (maxComputeWorkGroupCount x maxComputeWorkGroupSize, maxRayDispatchInvocationCount)";
    if (width == 0 || height == 0) throw UsageError(message);
    throw DeviceLimitError(message);
  }
}

PROCEDURAY_DECL void trace(const Context& ctx, const Pipeline& pipeline, const DescriptorSet& set,
                           const SbtBuffer& sbt, std::uint32_t width, std::uint32_t height,
                           std::span<const std::byte> push_constants) {
  check_trace_size(ctx, width, height);
  const VkDescriptorSet raw = set.get();
  ctx.submit([&](VkCommandBuffer cmd) {
    record_trace(ctx, cmd, pipeline, {&raw, 1}, sbt, width, height, push_constants);
  });
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
