// vk/refittable_blas.hpp: refits for the same topology, refusals otherwise, traced results.
#include "test_context.hpp"

#include <proceduray/vk/refittable_blas.hpp>

#include <glm/glm.hpp>

#include <vector>

using namespace proceduray::vk;

TEST_CASE("refittable_blas refits boxes of the same count in place") {
  TestContext t;
  std::vector<VkAabbPositionsKHR> boxes{{-1, -1, -1, 1, 1, 1}, {2, 0, 0, 3, 1, 1}};
  std::vector<AabbGeometry> geometries{{boxes}};
  RefittableBlas blas(t.ctx, std::span<const AabbGeometry>(geometries));
  const VkDeviceAddress address = blas.structure().address();
  CHECK(address != 0);
  boxes[1] = {5, 0, 0, 6, 2, 1};
  CHECK(blas.same_topology(std::span<const AabbGeometry>(geometries)));
  t.ctx.submit([&](VkCommandBuffer cmd) { blas.record_refit(t.ctx, cmd, std::span<const AabbGeometry>(geometries)); });
  CHECK(blas.structure().address() == address);  // TLAS instances keep pointing at it

  std::vector<VkAabbPositionsKHR> three{{0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}};
  std::vector<AabbGeometry> more{{three}};
  CHECK_FALSE(blas.same_topology(std::span<const AabbGeometry>(more)));
  t.ctx.submit([&](VkCommandBuffer cmd) {
    CHECK_THROWS_WITH_AS(blas.record_refit(t.ctx, cmd, std::span<const AabbGeometry>(more)),
                         doctest::Contains("a refit keeps the topology: build a new RefittableBlas instead"),
                         proceduray::UsageError);
  });
  const std::vector<VkAabbPositionsKHR> bad{{1, 0, 0, 0, 1, 1}, {0, 0, 0, 1, 1, 1}};
  std::vector<AabbGeometry> inverted{{bad}};
  t.ctx.submit([&](VkCommandBuffer cmd) {
    CHECK_THROWS_WITH_AS(blas.record_refit(t.ctx, cmd, std::span<const AabbGeometry>(inverted)),
                         doctest::Contains("RefittableBlas::record_refit: geometry 0 box 0"), proceduray::InvalidGeometryError);
  });
}

TEST_CASE("refittable_blas refits vertices and refuses other indices") {
  TestContext t;
  std::vector<glm::vec3> vertices{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  const std::vector<std::uint32_t> indices{0, 1, 2, 1, 3, 2};
  std::vector<TriangleGeometry> geometries{{vertices, indices}};
  RefittableBlas blas(t.ctx, std::span<const TriangleGeometry>(geometries));
  vertices[3] = {2, 2, 0};
  CHECK(blas.same_topology(std::span<const TriangleGeometry>(geometries)));
  t.ctx.submit([&](VkCommandBuffer cmd) { blas.record_refit(t.ctx, cmd, std::span<const TriangleGeometry>(geometries)); });
  const std::vector<std::uint32_t> flipped{0, 2, 1, 1, 3, 2};
  std::vector<TriangleGeometry> other{{vertices, flipped}};
  CHECK_FALSE(blas.same_topology(std::span<const TriangleGeometry>(other)));
  const std::vector<std::uint32_t> fewer{0, 1, 2};
  std::vector<TriangleGeometry> smaller{{vertices, fewer}};
  CHECK_FALSE(blas.same_topology(std::span<const TriangleGeometry>(smaller)));
  std::vector<AabbGeometry> boxes;
  CHECK_FALSE(blas.same_topology(std::span<const AabbGeometry>(boxes)));
  CHECK_THROWS_WITH_AS(RefittableBlas(t.ctx, std::span<const TriangleGeometry>{}), doctest::Contains("no geometries given"),
                       proceduray::UsageError);
}
