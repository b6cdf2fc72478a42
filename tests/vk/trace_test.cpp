#include "test_context.hpp"

#include <proceduray/vk/trace.hpp>

using namespace proceduray;

TEST_CASE("check_trace_size rejects zero and sizes past the dispatch limit") {
  TestContext t;
  CHECK_NOTHROW(vk::check_trace_size(t.ctx, 1, 1));
  CHECK_THROWS_WITH_AS(vk::check_trace_size(t.ctx, 0, 10), doctest::Contains("size 0x10"), UsageError);
  CHECK_THROWS_WITH_AS(vk::check_trace_size(t.ctx, 10, 0), doctest::Contains("size 10x0"), UsageError);
  const auto max_rays = t.ctx.ray_tracing_properties().maxRayDispatchInvocationCount;
  CHECK_THROWS_WITH_AS(vk::check_trace_size(t.ctx, 0xFFFFFFFFu, 0xFFFFFFFFu),
                       doctest::Contains(std::to_string(max_rays).c_str()), DeviceLimitError);
}
