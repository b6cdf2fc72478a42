// vk/context.hpp: the device's properties and submit's wait.
#include "test_context.hpp"

#include <proceduray/vk/buffer.hpp>
#include <proceduray/vk/context.hpp>

#include <cstdint>
#include <cstring>

using namespace proceduray;

TEST_CASE("context picks a ray tracing device with sane SBT properties") {
  TestContext t;
  const SbtProperties p = t.ctx.sbt_properties();
  CHECK(p.handle_size >= 32);
  CHECK(p.base_alignment >= p.handle_alignment);
  CHECK(p.max_stride >= 4096);
  CHECK_FALSE(t.ctx.name().empty());
  CHECK(t.ctx.validation_enabled());
  CHECK(t.ctx.ray_tracing_properties().maxRayHitAttributeSize >= 32);
}

TEST_CASE("context submit runs the recorded commands and waits for them") {
  // The GPU fills a host-visible buffer; the host reads it the moment submit returns. Without the
  // wait the read races the device (lavapipe runs the queue on its own thread) and sees zeros.
  TestContext t;
  constexpr std::uint32_t words = 1u << 20;  // 4 MiB: long enough for a race to show
  vk::Buffer buffer(t.ctx, words * sizeof(std::uint32_t), VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::Buffer::host_visible);
  std::memset(buffer.data(), 0, words * sizeof(std::uint32_t));
  for (std::uint32_t round : {0xC0FFEEu, 0xBEEFu}) {
    t.ctx.submit([&](VkCommandBuffer cmd) {
      vkCmdFillBuffer(cmd, buffer.get(), 0, VK_WHOLE_SIZE, round);
      auto to_host = vk::make<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
      to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
      to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0, nullptr,
                           0, nullptr);
    });
    const auto* values = static_cast<const std::uint32_t*>(buffer.data());
    CHECK(values[0] == round);
    CHECK(values[words / 2] == round);
    CHECK(values[words - 1] == round);
  }
}

TEST_CASE("context counts its submits, one per submit call, none for a failed recording") {
  TestContext t;
  const std::uint64_t before = t.ctx.submit_count();
  t.ctx.submit([](VkCommandBuffer) {});
  t.ctx.submit([](VkCommandBuffer) {});
  CHECK(t.ctx.submit_count() == before + 2);
  CHECK_THROWS_AS(t.ctx.submit([](VkCommandBuffer) { throw UsageError("recording failed"); }), UsageError);
  CHECK(t.ctx.submit_count() == before + 2);
}
