// vk/tlas.hpp: instance checks (the scene's rules), build_tlas and Tlas.
#include "test_context.hpp"

#include <proceduray/vk/tlas.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <limits>

using namespace proceduray;

TEST_CASE("build_tlas rejects a missing BLAS and singular or non-finite transforms") {
  TestContext t;
  const VkAabbPositionsKHR box{-1, -1, -1, 1, 1, 1};
  const vk::AabbGeometry geometry{{&box, 1}};
  const auto blas = vk::build_blas(t.ctx, {&geometry, 1});
  vk::Instance none{};
  CHECK_THROWS_WITH_AS(vk::build_tlas(t.ctx, {&none, 1}), doctest::Contains("has no BLAS"), UsageError);
  vk::Instance flat{.blas = &blas, .transform = proceduray::instance_transform(glm::scale(glm::mat4(1), glm::vec3(1, 0, 1)))};
  CHECK_THROWS_WITH_AS(vk::build_tlas(t.ctx, {&flat, 1}), doctest::Contains("build_tlas: instance 0 transform is singular"), InvalidGeometryError);
  vk::Instance inf{.blas = &blas};
  inf.transform[0][3] = std::numeric_limits<float>::infinity();  // row 0, column 3: the x translation
  CHECK_THROWS_WITH_AS(vk::build_tlas(t.ctx, {&inf, 1}), doctest::Contains("build_tlas: instance 0 transform has a non-finite element"), InvalidGeometryError);
  vk::Instance big{.blas = &blas, .sbt_offset = 1u << 24};
  CHECK_THROWS_WITH_AS(vk::build_tlas(t.ctx, {&big, 1}), doctest::Contains("24 bits"), DeviceLimitError);
}

TEST_CASE("build_tlas applies the scene's transform rule: a 1e-11 uniform scale is singular, 1e-3 is not") {
  TestContext t;
  const VkAabbPositionsKHR box{-1, -1, -1, 1, 1, 1};
  const vk::AabbGeometry geometry{{&box, 1}};
  const auto blas = vk::build_blas(t.ctx, {&geometry, 1});
  const vk::Instance tiny{.blas = &blas, .transform = proceduray::instance_transform(glm::scale(glm::mat4(1), glm::vec3(1e-11f)))};
  CHECK_FALSE(detail::valid_transform(tiny.transform));  // the rule Scene::add_geometry applies
  CHECK_THROWS_WITH_AS(vk::build_tlas(t.ctx, {&tiny, 1}), doctest::Contains("build_tlas: instance 0 transform is singular"),
                       InvalidGeometryError);
  const vk::Instance small{.blas = &blas, .transform = proceduray::instance_transform(glm::scale(glm::mat4(1), glm::vec3(1e-3f)))};
  CHECK(detail::valid_transform(small.transform));
  CHECK_NOTHROW(vk::build_tlas(t.ctx, {&small, 1}));
}

TEST_CASE("build_tlas accepts an empty instance list") {
  TestContext t;
  const auto tlas = vk::build_tlas(t.ctx, {});
  CHECK(tlas.get() != VK_NULL_HANDLE);
}

TEST_CASE("tlas update refuses a TLAS built without allow_update and a changed instance count") {
  TestContext t;
  const VkAabbPositionsKHR box{-1, -1, -1, 1, 1, 1};
  const vk::AabbGeometry geometry{{&box, 1}};
  const auto blas = vk::build_blas(t.ctx, {&geometry, 1});
  std::vector<vk::Instance> instances{{.blas = &blas}, {.blas = &blas, .sbt_offset = 1}};
  vk::Tlas fixed(t.ctx, instances);
  CHECK_FALSE(fixed.updatable());
  CHECK_THROWS_WITH_AS(fixed.update(t.ctx, instances), doctest::Contains("built without BuildOptions::allow_update"),
                       UsageError);
  vk::Tlas moving(t.ctx, instances, {.allow_update = true});
  CHECK(moving.updatable());
  CHECK(moving.instance_count() == 2);
  const VkAccelerationStructureKHR handle = moving.get();
  instances[0].transform = proceduray::instance_transform(glm::translate(glm::mat4(1), {3, 0, 0}));
  moving.update(t.ctx, instances);
  CHECK(moving.get() == handle);  // refitted in place
  CHECK_THROWS_WITH_AS(moving.update(t.ctx, {instances.data(), 1}), doctest::Contains("1 instances given, the TLAS has 2"),
                       UsageError);
  instances[1].transform = proceduray::instance_transform(glm::scale(glm::mat4(1), glm::vec3(0)));
  CHECK_THROWS_WITH_AS(moving.update(t.ctx, instances), doctest::Contains("Tlas::update: instance 1 transform"),
                       InvalidGeometryError);
}
