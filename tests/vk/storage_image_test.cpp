#include "test_context.hpp"

#include <proceduray/vk/storage_image.hpp>

using namespace proceduray;

TEST_CASE("storage image reads back width x height RGBA8 pixels") {
  TestContext t;
  vk::StorageImage image(t.ctx, 7, 3);
  CHECK(image.read().size() == 7 * 3 * 4);
}

TEST_CASE("storage image rejects sizes outside the device's limit") {
  TestContext t;
  CHECK_THROWS_WITH_AS(vk::StorageImage(t.ctx, 0, 4), doctest::Contains("size 0x4"), std::invalid_argument);
  const auto limit = t.ctx.properties().limits.maxImageDimension2D;
  CHECK_THROWS_WITH_AS(vk::StorageImage(t.ctx, limit + 1, 4), doctest::Contains(std::to_string(limit).c_str()),
                       std::invalid_argument);
}
