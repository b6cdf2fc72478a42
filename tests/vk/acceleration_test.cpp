// vk/acceleration.hpp: the structure handle, build_blas and compaction.
#include "test_context.hpp"

#include "renderer_scene.hpp"

#include <proceduray/vk/acceleration.hpp>
#include <proceduray/vk/scene_acceleration.hpp>

#include <cstdint>
#include <limits>
#include <vector>

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

namespace {
/// Three BLASes of two kinds and several sizes, for the batch tests.
struct ThreeBlases {
  std::vector<VkAabbPositionsKHR> few{{-1, -1, -1, 1, 1, 1}, {2, 2, 2, 3, 3, 3}};
  std::vector<VkAabbPositionsKHR> many;
  std::vector<glm::vec3> quad{{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
  std::vector<std::uint32_t> tris{0, 1, 2, 0, 2, 3};
  std::vector<vk::AabbGeometry> boxes_a, boxes_b;
  std::vector<vk::TriangleGeometry> mesh;
  ThreeBlases() {
    for (int i = 0; i < 40; ++i) many.push_back({float(i), 0, 0, float(i) + 0.5f, 1, 1});
    boxes_a = {{few}};
    boxes_b = {{many}, {few, false}};
    mesh = {{quad, tris}};
  }
  std::vector<vk::BlasGeometries> batch() const { return {{.boxes = boxes_a}, {.boxes = boxes_b}, {.triangles = mesh}}; }
};
}  // namespace

TEST_CASE("build_blases builds and compacts K BLASes in two submits, to the sizes of one-by-one builds") {
  TestContext t;
  const ThreeBlases in;
  std::uint64_t before = t.ctx.submit_count();
  const std::vector<vk::AccelerationStructure> batch = vk::build_blases(t.ctx, in.batch());
  CHECK(t.ctx.submit_count() - before == 2);  // was 3 per BLAS: build, size query, compaction
  REQUIRE(batch.size() == 3);

  before = t.ctx.submit_count();
  const auto a = vk::build_blas(t.ctx, std::span<const vk::AabbGeometry>(in.boxes_a));
  const auto b = vk::build_blas(t.ctx, std::span<const vk::AabbGeometry>(in.boxes_b));
  const auto m = vk::build_blas(t.ctx, std::span<const vk::TriangleGeometry>(in.mesh));
  CHECK(t.ctx.submit_count() - before == 6);
  CHECK(batch[0].size() == a.size());
  CHECK(batch[1].size() == b.size());
  CHECK(batch[2].size() == m.size());
  for (const auto& s : batch) CHECK(s.address() != 0);

  before = t.ctx.submit_count();
  const auto uncompacted = vk::build_blases(t.ctx, in.batch(), {.compact = false});
  CHECK(t.ctx.submit_count() - before == 1);
  for (std::size_t i = 0; i < 3; ++i) CHECK(uncompacted[i].size() >= batch[i].size());
  CHECK(vk::build_blases(t.ctx, {}).empty());
}

TEST_CASE("build_blases names the BLAS whose input is bad and builds nothing") {
  TestContext t;
  const ThreeBlases in;
  const std::uint64_t before = t.ctx.submit_count();
  std::vector<vk::BlasGeometries> both = in.batch();
  both[1].triangles = in.mesh;
  CHECK_THROWS_WITH_AS(vk::build_blases(t.ctx, both), doctest::Contains("build_blases: BLAS 1 has both boxes and triangles"),
                       UsageError);
  const VkAabbPositionsKHR inverted{1, 0, 0, -1, 1, 1};
  const vk::AabbGeometry bad{{&inverted, 1}};
  std::vector<vk::BlasGeometries> with_bad = in.batch();
  with_bad[2] = {.boxes = {&bad, 1}};
  CHECK_THROWS_WITH_AS(vk::build_blases(t.ctx, with_bad), doctest::Contains("build_blases: BLAS 2: geometry 0 box 0"),
                       InvalidGeometryError);
  CHECK(t.ctx.submit_count() == before);
}

TEST_CASE("build_blases: a scene's Static BLASes cost two submits in all, with the bytes of one-by-one builds") {
  // SceneAcceleration builds its Static BLASes with build_blases: K of them, then the TLAS.
  TestContext t;
  renderer_scene::RendererScene s;  // a Static floor (triangles) and Static balls (boxes): 2 BLASes
  const auto& scene = s.table(t.ctx);
  const Plan plan = compile(scene);
  REQUIRE(plan.blases().size() == 2);
  const std::uint64_t before = t.ctx.submit_count();
  const vk::SceneAcceleration structures(t.ctx, plan);
  CHECK(t.ctx.submit_count() - before == 3);  // 2 for every BLAS, 1 for the TLAS (one by one: 2 * 3 + 1)

  VkDeviceSize one_by_one = 0;
  for (const PlannedBlas& blas : plan.blases()) {
    std::vector<vk::AabbGeometry> boxes;
    std::vector<vk::TriangleGeometry> meshes;
    for (std::uint32_t g : blas.geometries) {
      const GeometryDesc& desc = scene.geometry(GeometryId(g)).desc;
      const bool opaque = plan.geometries()[g].opaque;
      if (blas.kind == GeometryKind::procedural) {
        boxes.push_back({{reinterpret_cast<const VkAabbPositionsKHR*>(desc.aabbs.data()), desc.aabbs.size()}, opaque});
      } else {
        meshes.push_back({desc.mesh.vertices, desc.mesh.indices, opaque});
      }
    }
    one_by_one += boxes.empty() ? vk::build_blas(t.ctx, std::span<const vk::TriangleGeometry>(meshes)).size()
                                : vk::build_blas(t.ctx, std::span<const vk::AabbGeometry>(boxes)).size();
  }
  CHECK(structures.blas_bytes() == one_by_one);
}
