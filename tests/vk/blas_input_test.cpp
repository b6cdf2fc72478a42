// vk/blas_input.hpp: geometry checks (the scene's rules) and how inputs are laid out for a build.
#include "test_context.hpp"

#include <proceduray/vk/blas_input.hpp>

#include <cstdint>
#include <limits>
#include <vector>

using namespace proceduray;

TEST_CASE("blas_input checks triangle lists: counts, indices in range, finite vertices") {
  const glm::vec3 tri[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::uint32_t good[] = {0, 1, 2};
  const vk::TriangleGeometry ok{tri, good};
  CHECK_NOTHROW(vk::detail::check_triangles({&ok, 1}, "op"));
  CHECK_THROWS_WITH_AS(vk::detail::check_triangles({}, "op"), doctest::Contains("op: no geometries given"), UsageError);
  const std::uint32_t two[] = {0, 1};
  const vk::TriangleGeometry short_list{tri, two};
  CHECK_THROWS_WITH_AS(vk::detail::check_triangles({&short_list, 1}, "op"),
                       doctest::Contains("op: triangle geometry 0 has 2 indices"), InvalidGeometryError);
  const std::uint32_t past[] = {0, 1, 3};
  const vk::TriangleGeometry out_of_range{tri, past};
  CHECK_THROWS_WITH_AS(vk::detail::check_triangles({&out_of_range, 1}, "op"), doctest::Contains("indexes vertex 3"),
                       InvalidGeometryError);
  const glm::vec3 nan[] = {{0, 0, 0}, {1, 0, 0}, {0, std::numeric_limits<float>::quiet_NaN(), 0}};
  const vk::TriangleGeometry not_finite{nan, good};
  CHECK_THROWS_WITH_AS(vk::detail::check_triangles({&not_finite, 1}, "op"), doctest::Contains("non-finite vertex"),
                       InvalidGeometryError);
}

TEST_CASE("blas_input checks boxes and names the geometry and box") {
  const VkAabbPositionsKHR good{-1, -1, -1, 1, 1, 1}, inverted{1, 0, 0, -1, 1, 1};
  const std::vector<vk::AabbGeometry> geometries{{{&good, 1}}, {{&inverted, 1}}};
  CHECK_NOTHROW(vk::detail::check_aabbs({geometries.data(), 1}, "op"));
  CHECK_THROWS_WITH_AS(vk::detail::check_aabbs(geometries, "op"), doctest::Contains("op: geometry 1 box 0"),
                       InvalidGeometryError);
  CHECK_THROWS_WITH_AS(vk::detail::check_aabbs({}, "op"), doctest::Contains("no geometries given"), UsageError);
}

TEST_CASE("blas_input lays geometries out back to back, one description and count each") {
  TestContext t;
  const VkAabbPositionsKHR boxes[] = {{0, 0, 0, 1, 1, 1}, {1, 1, 1, 2, 2, 2}, {2, 2, 2, 3, 3, 3}};
  const std::vector<vk::AabbGeometry> geometries{{{boxes, 2}, true}, {{boxes + 2, 1}, false}};
  const vk::detail::BlasInput in = vk::detail::aabb_input(t.ctx, geometries, "test");
  REQUIRE(in.geometries.size() == 2);
  CHECK(in.counts == std::vector<std::uint32_t>{2, 1});
  CHECK(in.geometries[0].geometry.aabbs.data.deviceAddress == in.data.address());
  CHECK(in.geometries[1].geometry.aabbs.data.deviceAddress == in.data.address() + 2 * sizeof(VkAabbPositionsKHR));
  CHECK(in.geometries[0].flags == VK_GEOMETRY_OPAQUE_BIT_KHR);
  CHECK(in.geometries[1].flags == 0);
  const auto* written = static_cast<const VkAabbPositionsKHR*>(in.data.data());
  CHECK(written[2].minX == 2.0f);

  const glm::vec3 quad[] = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
  const std::uint32_t tris[] = {0, 1, 2, 0, 2, 3};
  const vk::TriangleGeometry mesh{quad, tris};
  const vk::detail::BlasInput tin = vk::detail::triangle_input(t.ctx, {&mesh, 1}, "test");
  CHECK(tin.counts == std::vector<std::uint32_t>{2});
  CHECK(tin.geometries[0].geometry.triangles.maxVertex == 3);
  CHECK(tin.geometries[0].geometry.triangles.indexData.deviceAddress == tin.indices.address());
}
