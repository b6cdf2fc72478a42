// A ring of N frame slots, each with its own command buffer, fence, timestamp pair and readback
// buffer, all made once and reused: the frame loop allocates nothing in steady state, and the
// host records frame n+1 while the device still runs frame n.
//
//   proceduray::vk::FrameRing ring(ctx, 2);             // two frames in flight
//   proceduray::vk::FrameSlot& slot = ring.begin();      // waits for the frame that last used the slot
//   ring.stamp(slot, 0); /* record into slot.cmd */ ring.stamp(slot, 1);
//   std::uint64_t n = ring.submit(slot);                // frame number n, 1, 2, ...
//   ring.wait(ring.slot_of(n, "my read"));              // throws once a later frame reused the slot
//   ring.wait_all();                                    // before changing what frames in flight read
//
// A slot is reused N frames later: what it read back is valid until then. A frame number whose
// slot was reused, or that was never submitted, throws UsageError naming both frames.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/vk/buffer.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace proceduray::vk {

/// The most frames in flight a ring takes: more only adds latency and memory (two or three keep a
/// device busy; eight is generous).
inline constexpr std::uint32_t max_frames_in_flight = 8;

/// One frame's command buffer, fence, timestamps and readback memory.
struct FrameSlot {
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  DeviceHandle<VkFence> fence;
  std::uint32_t index = 0;      ///< position in the ring; its timestamps are queries 2*index, 2*index+1
  std::uint64_t frame = 0;      ///< the frame number last submitted from this slot; 0: never used
  bool pending = false;         ///< submitted and not yet waited for
  std::unique_ptr<Buffer> readback;  ///< host-cached; grows to the largest readback asked, never shrinks
};

/// N slots used round-robin.
class FrameRing {
 public:
  /// Throws UsageError for 0 frames in flight or more than max_frames_in_flight.
  FrameRing(const Context& ctx, std::uint32_t frames_in_flight, std::string_view op = "FrameRing");
  FrameRing(const FrameRing&) = delete;
  FrameRing& operator=(const FrameRing&) = delete;
  ~FrameRing() { wait_all_noexcept(); }

  std::uint32_t size() const noexcept { return static_cast<std::uint32_t>(m_slots.size()); }
  /// Frames submitted so far; the next is submitted() + 1.
  std::uint64_t submitted() const noexcept { return m_submitted; }

  /// The slot of the next frame: waits for the frame that used it last, resets and begins its
  /// command buffer, and resets its timestamps.
  FrameSlot& begin();
  /// Records timestamp `which` (0: before the trace, 1: after it) when the queue has timestamps.
  void stamp(const FrameSlot& slot, std::uint32_t which) const;
  /// Ends the slot's command buffer and submits it with the slot's fence; returns the frame number.
  std::uint64_t submit(FrameSlot& slot);
  /// Waits for the slot's frame (no-op when it was already waited for) and makes its readback
  /// memory visible to the host.
  void wait(FrameSlot& slot);
  /// Waits for every frame in flight: call before the host changes memory those frames read.
  void wait_all();
  /// True when some frame is submitted and not yet waited for.
  bool busy() const noexcept;

  /// The slot that holds frame `frame`; throws UsageError, naming `op`, for a frame never submitted
  /// or one whose slot a later frame reused.
  FrameSlot& slot_of(std::uint64_t frame, std::string_view op);
  /// GPU milliseconds between the slot's two timestamps (after wait); 0 without timestamps.
  double trace_ms(const FrameSlot& slot) const;
  /// The slot's readback buffer, grown to at least `bytes` (waits for nothing: call on a begun slot).
  Buffer& readback(FrameSlot& slot, VkDeviceSize bytes);

 private:
  void wait_all_noexcept() noexcept;

  const Context* m_ctx;
  DeviceHandle<VkCommandPool> m_pool;
  DeviceHandle<VkQueryPool> m_queries;  // two timestamps per slot; null when the queue has none
  std::vector<FrameSlot> m_slots;
  std::uint64_t m_submitted = 0;
};

// ---------------------------------------------------------------------------------------------

}  // namespace proceduray::vk

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
  m_pool = own(ctx.device(), pool, vkDestroyCommandPool);

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
    m_slots[i].fence = own(ctx.device(), fence, vkDestroyFence);
    m_slots[i].cmd = cmds[i];
    m_slots[i].index = i;
  }
  if (ctx.timestamp_period_ns() > 0) {
    auto info = make<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 2 * frames_in_flight;
    VkQueryPool queries = VK_NULL_HANDLE;
    check(vkCreateQueryPool(ctx.device(), &info, nullptr, &queries), "vkCreateQueryPool", "frame ring");
    m_queries = own(ctx.device(), queries, vkDestroyQueryPool);
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
  if (!slot.readback || slot.readback->size() < bytes) {
    slot.readback = std::make_unique<Buffer>(*m_ctx, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, Buffer::host_cached);
  }
  return *slot.readback;
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
