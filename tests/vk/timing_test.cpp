// vk/timing.hpp: warm-up, GPU-timestamp medians and Mrays/s, as examples and users share them.
#include "frame_pixels.hpp"
#include "renderer_scene.hpp"
#include "test_context.hpp"

#include <proceduray/vk/timing.hpp>

#include <doctest/doctest.h>

#include <vector>

using namespace proceduray;
using renderer_scene::RendererScene;

TEST_CASE("timing stats give min, median and max, and an even count's median is the mean of the middle two") {
  const std::vector<double> odd{3.0, 1.0, 9.0, 2.0, 5.0};
  const vk::Stats a = vk::stats(odd);
  CHECK(a.min == 1.0);
  CHECK(a.median == 3.0);
  CHECK(a.max == 9.0);
  CHECK(a.count == 5);
  const std::vector<double> even{4.0, 1.0, 2.0, 100.0};
  CHECK(vk::stats(even).median == 3.0);  // one slow frame moves no median
  CHECK_THROWS_WITH_AS(vk::stats(std::vector<double>{}), doctest::Contains("stats: no samples"), UsageError);
}

TEST_CASE("timing time_frames warms up, times the frames asked for and reads back only the last") {
  TestContext t;
  RendererScene s;
  vk::Renderer renderer(t.ctx, s.table(t.ctx), RendererScene::options());
  renderer_scene::prepare(renderer, 32, 24);
  std::vector<std::uint32_t> updates;
  const vk::FrameTimes times = vk::time_frames(renderer, 32, 24, {.frames = 3, .warm_up = 2, .read_last = true},
                                               [&](std::uint32_t frame) { updates.push_back(frame); });
  CHECK(updates == std::vector<std::uint32_t>{0, 1, 2, 3, 4});  // warm-up frames first, every frame updated
  CHECK(times.trace_ms.count == 3);
  CHECK(times.trace_ms.min > 0.0);
  CHECK(times.trace_ms.min <= times.trace_ms.median);
  CHECK(times.trace_ms.median <= times.trace_ms.max);
  CHECK(times.wall_ms.median >= times.host_ms.median);
  CHECK(times.mrays_per_s(2.0) == doctest::Approx(2.0 * 32 * 24 / (times.trace_ms.median * 1e3)));
  // The last frame's pixels: the left ball's red where it projects (the scene's own check).
  REQUIRE(times.last.rgba.size() == 32u * 24u * 4u);
  const vk::Frame again = renderer.render(32, 24);
  CHECK(again.rgba == times.last.rgba);
  const vk::FrameTimes quiet = vk::time_frames(renderer, 32, 24, {.frames = 2, .warm_up = 0});
  CHECK(quiet.last.rgba.empty());  // no readback unless asked
  CHECK_THROWS_WITH_AS(vk::time_frames(renderer, 32, 24, {.frames = 0}),
                       doctest::Contains("time_frames: 0 frames to time at 32x24"), UsageError);
  CHECK(t.ctx.validation_messages().empty());
}
