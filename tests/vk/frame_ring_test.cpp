// vk/frame_ring.hpp: slots reused round-robin, frame numbers, reused slots refused.
#include "test_context.hpp"

#include <proceduray/vk/frame_ring.hpp>

#include <cstring>

using namespace proceduray;

namespace {

/// Records a fill of the slot's readback buffer with `value` (a frame that "reads back" a number).
void fill(vk::FrameRing& ring, vk::FrameSlot& slot, std::uint32_t value) {
  vk::Buffer& buffer = ring.readback(slot, 64);
  vkCmdFillBuffer(slot.cmd, buffer.get(), 0, 64, value);
  auto to_host = vk::make<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(slot.cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0, nullptr,
                       0, nullptr);
}

std::uint32_t first_word(const vk::FrameSlot& slot) {
  std::uint32_t v = 0;
  std::memcpy(&v, slot.readback->data(), 4);
  return v;
}

}  // namespace

TEST_CASE("frame ring bad input: 0 frames in flight or more than the limit are refused naming the range") {
  TestContext t;
  CHECK_THROWS_WITH_AS(vk::FrameRing(t.ctx, 0), doctest::Contains("0 frames in flight asked; give 1..8"), UsageError);
  CHECK_THROWS_WITH_AS(vk::FrameRing(t.ctx, vk::max_frames_in_flight + 1),
                       doctest::Contains("9 frames in flight asked; give 1..8"), UsageError);
  CHECK_NOTHROW(vk::FrameRing(t.ctx, vk::max_frames_in_flight));
}

TEST_CASE("frame ring numbers frames, reuses slots round-robin and keeps each frame's readback until reuse") {
  TestContext t;
  for (std::uint32_t n : {1u, 2u, 3u}) {
    CAPTURE(n);
    vk::FrameRing ring(t.ctx, n);
    CHECK(ring.size() == n);
    std::vector<std::uint64_t> numbers;
    for (std::uint32_t i = 0; i < 2 * n + 1; ++i) {
      vk::FrameSlot& slot = ring.begin();
      CHECK(slot.index == i % n);
      ring.stamp(slot, 0);
      fill(ring, slot, 100 + i);
      ring.stamp(slot, 1);
      numbers.push_back(ring.submit(slot));
      CHECK(numbers.back() == i + 1);
      CHECK(ring.busy());
      // Every frame still in its slot reads what it wrote: frames in flight do not overwrite each other.
      for (std::uint64_t f = numbers.back() > n ? numbers.back() - n + 1 : 1; f <= numbers.back(); ++f) {
        vk::FrameSlot& held = ring.slot_of(f, "test");
        ring.wait(held);
        CHECK(first_word(held) == 100 + f - 1);
        CHECK(ring.trace_ms(held) >= 0.0);
      }
    }
    ring.wait_all();
    CHECK_FALSE(ring.busy());
    CHECK(ring.submitted() == 2 * n + 1);
  }
}

TEST_CASE("frame ring bad input: a frame whose slot was reused, or never submitted, is refused naming both frames") {
  TestContext t;
  vk::FrameRing ring(t.ctx, 2);
  for (std::uint32_t i = 0; i < 3; ++i) {
    vk::FrameSlot& slot = ring.begin();
    fill(ring, slot, i);
    ring.submit(slot);
  }
  CHECK_THROWS_WITH_AS(ring.slot_of(1, "Renderer::rgba"),
                       doctest::Contains("Renderer::rgba: frame 1 is gone: its slot was reused by frame 3 (2 frames in "
                                         "flight); read a frame before submitting 2 more"),
                       UsageError);
  CHECK_THROWS_WITH_AS(ring.slot_of(4, "Renderer::wait"),
                       doctest::Contains("frame 4 was never submitted (3 so far)"), UsageError);
  CHECK_THROWS_WITH_AS(ring.slot_of(0, "Renderer::wait"), doctest::Contains("frame 0 was never submitted"), UsageError);
  CHECK(ring.slot_of(2, "x").frame == 2);
  CHECK(ring.slot_of(3, "x").frame == 3);
}

TEST_CASE("frame ring keeps an outgrown readback buffer, unchanged, for one more turn of the ring") {
  TestContext t;
  vk::FrameRing ring(t.ctx, 2);
  auto frame = [&](VkDeviceSize bytes, std::uint32_t value) {
    vk::FrameSlot& slot = ring.begin();
    vk::Buffer& buffer = ring.readback(slot, bytes);
    vkCmdFillBuffer(slot.cmd, buffer.get(), 0, VK_WHOLE_SIZE, value);
    return ring.submit(slot);
  };
  frame(64, 1);
  frame(64, 2);
  vk::FrameSlot& one = ring.slot_of(1, "test");
  ring.wait(one);
  const auto* old = static_cast<const std::uint32_t*>(one.readback->data());
  REQUIRE(old[0] == 1u);
  frame(256, 3);  // frame 1's slot, grown: the 64-byte buffer is kept
  CHECK(ring.retired() == 1);
  ring.wait_all();
  CHECK(old[0] == 1u);  // still frame 1's words
  frame(256, 4);  // frame 2's slot grows too
  CHECK(ring.retired() == 2);
  frame(256, 5);  // a turn past frame 3: no view of frame 1 can be valid, its buffer goes
  CHECK(ring.retired() == 1);
  frame(256, 6);
  CHECK(ring.retired() == 0);
  ring.wait_all();
}
