#include "test_context.hpp"

#include <proceduray/vk/descriptors.hpp>
#include <proceduray/vk/tlas.hpp>

using namespace proceduray;

TEST_CASE("descriptor set refuses writes of the wrong kind or to missing bindings") {
  TestContext t;
  vk::DescriptorSet set(t.ctx, {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, {1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}});
  const vk::Tlas tlas(t.ctx, {});
  CHECK_THROWS_WITH_AS(set.write(0, tlas.structure()), doctest::Contains("binding 0 cannot hold an acceleration structure"),
                       UsageError);
  const vk::Buffer buffer(t.ctx, 16, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  CHECK_NOTHROW(set.write(1, buffer));
  CHECK_THROWS_WITH_AS(set.write(0, buffer), doctest::Contains("binding 0 cannot hold a buffer"), UsageError);
  CHECK_THROWS_WITH_AS(set.write(7, buffer), doctest::Contains("binding 7 does not exist"), UsageError);
}

TEST_CASE("descriptor set refuses a binding listed twice") {
  TestContext t;
  CHECK_THROWS_WITH_AS(vk::DescriptorSet(t.ctx, {{2, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, {2, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}}),
                       doctest::Contains("binding 2 is listed twice"), UsageError);
}
