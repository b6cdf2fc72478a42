// Records and runs one vkCmdTraceRaysKHR over a width x height grid.
//
//   proceduray::vk::trace(ctx, pipeline, set, sbt, 640, 480, proceduray::vk::bytes_of(camera));   // waits
//   ctx.submit([&](VkCommandBuffer cmd) { proceduray::vk::record_trace(ctx, cmd, pipeline, sets, sbt, 640, 480); });
//
// The size is checked against the device's dispatch limits before anything is recorded: a zero
// size throws proceduray::UsageError, one past the limits proceduray::DeviceLimitError.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/vk/sbt_buffer.hpp>

namespace proceduray::vk {

/// Throws UsageError for a zero size, DeviceLimitError for one this device cannot dispatch.
PROCEDURAY_DECL void check_trace_size(const Context& ctx, std::uint32_t width, std::uint32_t height);

/// Records the binds (pipeline, sets 0..n-1, push constants), the stack size and one trace into `cmd`;
/// `before` and `after` run right around vkCmdTraceRaysKHR (timestamps, say).
template <class Around = void (*)(VkCommandBuffer)>
void record_trace(const Context& ctx, VkCommandBuffer cmd, const Pipeline& pipeline,
                  std::span<const VkDescriptorSet> sets, const SbtBuffer& sbt, std::uint32_t width,
                  std::uint32_t height, std::span<const std::byte> push_constants = {},
                  Around before = [](VkCommandBuffer) {}, Around after = [](VkCommandBuffer) {}) {
  if (push_constants.size() != pipeline.push_constant_size()) {
    throw UsageError("trace: " + std::to_string(push_constants.size()) +
                     " bytes of push constants given but the pipeline declares " +
                     std::to_string(pipeline.push_constant_size()) + "; pass exactly that many bytes");
  }
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, pipeline.get());
  if (!sets.empty()) {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, pipeline.layout(), 0,
                            static_cast<std::uint32_t>(sets.size()), sets.data(), 0, nullptr);
  }
  if (!push_constants.empty()) {
    vkCmdPushConstants(cmd, pipeline.layout(), all_ray_tracing_stages, 0,
                       static_cast<std::uint32_t>(push_constants.size()), push_constants.data());
  }
  ctx.rt().cmd_set_ray_tracing_pipeline_stack_size(cmd, pipeline.stack_size());
  before(cmd);
  const auto& r = sbt.regions();
  ctx.rt().cmd_trace_rays(cmd, &r[0], &r[1], &r[2], &r[3], width, height, 1);
  after(cmd);
}

/// Checks the size, then records the binds and one trace, submits them and waits for the queue.
PROCEDURAY_DECL void trace(const Context& ctx, const Pipeline& pipeline, const DescriptorSet& set,
                           const SbtBuffer& sbt, std::uint32_t width, std::uint32_t height,
                           std::span<const std::byte> push_constants = {});

}  // namespace proceduray::vk

#include "proceduray/vk/trace-inl.hpp"  // the bodies (config.hpp)
