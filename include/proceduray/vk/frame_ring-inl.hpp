// The bodies of proceduray/vk/frame_ring.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/frame_ring.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk {

PROCEDURAY_DECL FrameRing::FrameRing(const Context& ctx, std::uint32_t frames_in_flight, std::string_view op) : m_ctx(&ctx) {
  if (frames_in_flight == 0 || frames_in_flight > max_frames_in_flight) {
    throw UsageError(std::string(op) + ": " + std::to_string(frames_in_flight) +
                     " frames in flight asked; give 1.." + std::to_string(max_frames_in_flight) +
                     " (1 waits for every frame, 2 or 3 overlap the host with the device)");
  }
  auto pool_info = make<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
  pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool_info.queueFamilyIndex = ctx.queue_family();
  VkCommandPool pool = VK_NULL_HANDLE;
  check(vkCreateCommandPool(ctx.device(), &pool_info, nullptr, &pool), "vkCreateCommandPool", "frame ring");
  m_pool = own(ctx, pool, vkDestroyCommandPool);

  std::vector<VkCommandBuffer> cmds(frames_in_flight);
  auto alloc = make<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
  alloc.commandPool = pool;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = frames_in_flight;
  check(vkAllocateCommandBuffers(ctx.device(), &alloc, cmds.data()), "vkAllocateCommandBuffers", "frame ring");

  m_slots.resize(frames_in_flight);
  for (std::uint32_t i = 0; i < frames_in_flight; ++i) {
    auto fence_info = make<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
    VkFence fence = VK_NULL_HANDLE;
    check(vkCreateFence(ctx.device(), &fence_info, nullptr, &fence), "vkCreateFence", "frame ring");
    m_slots[i].fence = own(ctx, fence, vkDestroyFence);
    m_slots[i].cmd = cmds[i];
    m_slots[i].index = i;
  }
  if (ctx.timestamp_period_ns() > 0) {
    auto info = make<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 2 * frames_in_flight;
    VkQueryPool queries = VK_NULL_HANDLE;
    check(vkCreateQueryPool(ctx.device(), &info, nullptr, &queries), "vkCreateQueryPool", "frame ring");
    m_queries = own(ctx, queries, vkDestroyQueryPool);
  }
}

PROCEDURAY_DECL FrameSlot& FrameRing::begin() {
  FrameSlot& slot = m_slots[m_submitted % m_slots.size()];
  wait(slot);
  check(vkResetCommandBuffer(slot.cmd, 0), "vkResetCommandBuffer", "frame ring");
  auto info = make<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(slot.cmd, &info), "vkBeginCommandBuffer", "frame ring");
  if (m_queries) vkCmdResetQueryPool(slot.cmd, m_queries.get(), 2 * slot.index, 2);
  return slot;
}

PROCEDURAY_DECL void FrameRing::stamp(const FrameSlot& slot, std::uint32_t which) const {
  if (!m_queries) return;
  vkCmdWriteTimestamp(slot.cmd, which == 0 ? VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT : VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT,
                      m_queries.get(), 2 * slot.index + which);
}

PROCEDURAY_DECL std::uint64_t FrameRing::submit(FrameSlot& slot) {
  check(vkEndCommandBuffer(slot.cmd), "vkEndCommandBuffer", "frame ring");
  const VkFence fence = slot.fence.get();
  check(vkResetFences(m_ctx->device(), 1, &fence), "vkResetFences", "frame ring");
  auto info = make<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
  info.commandBufferCount = 1;
  info.pCommandBuffers = &slot.cmd;
  check(vkQueueSubmit(m_ctx->queue(), 1, &info, fence), "vkQueueSubmit", "frame ring");
  slot.pending = true;
  slot.frame = ++m_submitted;
  return slot.frame;
}

PROCEDURAY_DECL void FrameRing::wait(FrameSlot& slot) {
  if (!slot.pending) return;
  const VkFence fence = slot.fence.get();
  check(vkWaitForFences(m_ctx->device(), 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences", "frame ring");
  slot.pending = false;
  if (slot.readback) slot.readback->invalidate();
}

PROCEDURAY_DECL void FrameRing::wait_all() {
  for (FrameSlot& slot : m_slots) wait(slot);
}

PROCEDURAY_DECL void FrameRing::wait_all_noexcept() noexcept {
  for (FrameSlot& slot : m_slots) {
    if (!slot.pending) continue;
    const VkFence fence = slot.fence.get();
    vkWaitForFences(m_ctx->device(), 1, &fence, VK_TRUE, UINT64_MAX);
    slot.pending = false;
  }
}

PROCEDURAY_DECL bool FrameRing::busy() const noexcept {
  for (const FrameSlot& slot : m_slots) {
    if (slot.pending) return true;
  }
  return false;
}

PROCEDURAY_DECL FrameSlot& FrameRing::slot_of(std::uint64_t frame, std::string_view op) {
  if (frame == 0 || frame > m_submitted) {
    throw UsageError(std::string(op) + ": frame " + std::to_string(frame) + " was never submitted (" +
                     std::to_string(m_submitted) + " so far); pass a ticket that submit() returned");
  }
  FrameSlot& slot = m_slots[(frame - 1) % m_slots.size()];
  if (slot.frame != frame) {
    throw UsageError(std::string(op) + ": frame " + std::to_string(frame) + " is gone: its slot was reused by frame " +
                     std::to_string(slot.frame) + " (" + std::to_string(m_slots.size()) +
                     " frames in flight); read a frame before submitting " + std::to_string(m_slots.size()) +
                     " more, or raise RendererOptions::frames_in_flight");
  }
  return slot;
}

PROCEDURAY_DECL double FrameRing::trace_ms(const FrameSlot& slot) const {
  if (!m_queries) return 0;
  std::uint64_t stamps[2] = {};
  check(vkGetQueryPoolResults(m_ctx->device(), m_queries.get(), 2 * slot.index, 2, sizeof stamps, stamps,
                              sizeof stamps[0], VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
        "vkGetQueryPoolResults", "trace timestamps");
  return static_cast<double>(stamps[1] - stamps[0]) * m_ctx->timestamp_period_ns() * 1e-6;
}

PROCEDURAY_DECL Buffer& FrameRing::readback(FrameSlot& slot, VkDeviceSize bytes) {
  // Outgrown buffers go once the ring is a full turn past them: no view of them is valid then.
  const std::uint64_t next = m_submitted + 1;
  std::erase_if(m_retired, [&](const Retired& r) { return next >= r.at + m_slots.size(); });
  if (!slot.readback || slot.readback->size() < bytes) {
    auto grown = std::make_unique<Buffer>(*m_ctx, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, Buffer::host_cached);
    if (slot.readback) m_retired.push_back({std::move(slot.readback), next});
    slot.readback = std::move(grown);
  }
  return *slot.readback;
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
