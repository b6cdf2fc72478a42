#include "test_context.hpp"

#include <proceduray/vk/acceleration.hpp>

#include <glm/gtc/matrix_transform.hpp>

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

TEST_CASE("build_tlas rejects a missing BLAS and singular or non-finite transforms") {
  TestContext t;
  const VkAabbPositionsKHR box{-1, -1, -1, 1, 1, 1};
  const vk::AabbGeometry geometry{{&box, 1}};
  const auto blas = vk::build_blas(t.ctx, {&geometry, 1});
  vk::Instance none{};
  CHECK_THROWS_WITH_AS(vk::build_tlas(t.ctx, {&none, 1}), doctest::Contains("has no BLAS"), UsageError);
  vk::Instance flat{.blas = &blas, .transform = glm::scale(glm::mat4(1), glm::vec3(1, 0, 1))};
  CHECK_THROWS_WITH_AS(vk::build_tlas(t.ctx, {&flat, 1}), doctest::Contains("build_tlas: instance 0 transform is singular"), InvalidGeometryError);
  vk::Instance inf{.blas = &blas};
  inf.transform[3][0] = std::numeric_limits<float>::infinity();
  CHECK_THROWS_WITH_AS(vk::build_tlas(t.ctx, {&inf, 1}), doctest::Contains("build_tlas: instance 0 transform has a non-finite element"), InvalidGeometryError);
  vk::Instance big{.blas = &blas, .sbt_offset = 1u << 24};
  CHECK_THROWS_WITH_AS(vk::build_tlas(t.ctx, {&big, 1}), doctest::Contains("24 bits"), DeviceLimitError);
}

TEST_CASE("build_tlas applies the scene's transform rule: a 1e-11 uniform scale is singular, 1e-3 is not") {
  TestContext t;
  const VkAabbPositionsKHR box{-1, -1, -1, 1, 1, 1};
  const vk::AabbGeometry geometry{{&box, 1}};
  const auto blas = vk::build_blas(t.ctx, {&geometry, 1});
  const vk::Instance tiny{.blas = &blas, .transform = glm::scale(glm::mat4(1), glm::vec3(1e-11f))};
  CHECK_FALSE(detail::valid_transform(instance_transform(tiny.transform)));  // the rule Scene::add_geometry applies
  CHECK_THROWS_WITH_AS(vk::build_tlas(t.ctx, {&tiny, 1}), doctest::Contains("build_tlas: instance 0 transform is singular"),
                       InvalidGeometryError);
  const vk::Instance small{.blas = &blas, .transform = glm::scale(glm::mat4(1), glm::vec3(1e-3f))};
  CHECK(detail::valid_transform(instance_transform(small.transform)));
  CHECK_NOTHROW(vk::build_tlas(t.ctx, {&small, 1}));
}

TEST_CASE("build_tlas accepts an empty instance list") {
  TestContext t;
  const auto tlas = vk::build_tlas(t.ctx, {});
  CHECK(tlas.get() != VK_NULL_HANDLE);
}
