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
  /// A buffer it outgrows is kept, unchanged, until the ring has gone round once more, so a view
  /// of an earlier frame read a little too late (after a submit at a larger size) still reads
  /// that frame's pixels rather than freed memory.
  Buffer& readback(FrameSlot& slot, VkDeviceSize bytes);
  /// Outgrown readback buffers still kept (see readback()).
  std::size_t retired() const noexcept { return m_retired.size(); }

 private:
  void wait_all_noexcept() noexcept;
  /// A readback buffer outgrown at submit `at` (the frame number the slot's next frame gets).
  struct Retired {
    std::unique_ptr<Buffer> buffer;
    std::uint64_t at = 0;
  };

  const Context* m_ctx;
  DeviceHandle<VkCommandPool> m_pool;
  DeviceHandle<VkQueryPool> m_queries;  // two timestamps per slot; null when the queue has none
  std::vector<FrameSlot> m_slots;
  std::vector<Retired> m_retired;
  std::uint64_t m_submitted = 0;
};

// ---------------------------------------------------------------------------------------------

}  // namespace proceduray::vk

#include "proceduray/vk/frame_ring-inl.hpp"  // the bodies (config.hpp)
