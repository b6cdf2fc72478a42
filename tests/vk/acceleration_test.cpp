// vk/acceleration.hpp: the structure handle, build_blas and compaction.
#include "test_context.hpp"

#include <proceduray/vk/acceleration.hpp>

#include <limits>

using namespace proceduray;

TEST_CASE("build_blas builds an AABB structure with a device address") {
  TestContext t;
  const VkAabbPositionsKHR boxes[] = {{-1, -1, -1, 1, 1, 1}, {2, 2, 2, 3, 3, 3}};
  const vk::AabbGeometry geometry{boxes};
  const auto blas = vk::build_blas(t.ctx, {&geometry, 1});
  CHECK(blas.get() != VK_NULL_HANDLE);
  CHECK(blas.address() != 0);
  CHECK(blas.size() > 0);
}

TEST_CASE("build_blas rejects inverted and non-finite boxes") {
  TestContext t;
  const VkAabbPositionsKHR inverted{1, 0, 0, -1, 1, 1};
  const vk::AabbGeometry g1{{&inverted, 1}};
  CHECK_THROWS_WITH_AS(vk::build_blas(t.ctx, {&g1, 1}), doctest::Contains("box 0"), InvalidGeometryError);
  const VkAabbPositionsKHR nan{0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 1, 1};
  const vk::AabbGeometry g2{{&nan, 1}};
  CHECK_THROWS_WITH_AS(vk::build_blas(t.ctx, {&g2, 1}), doctest::Contains("finite"), InvalidGeometryError);
  const vk::AabbGeometry empty{};
  CHECK_THROWS_WITH_AS(vk::build_blas(t.ctx, {&empty, 1}), doctest::Contains("no boxes"), InvalidGeometryError);
}
