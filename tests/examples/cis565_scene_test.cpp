// examples/04_cis565_scene: a newcomer's scene on the library's Whitted shading, data-driven
// metaballs and generated trace functions, checked by object ids and pixel comparisons.
#include "vk/test_context.hpp"

#include <04_cis565_scene/cis565_scene.hpp>

#include <doctest/doctest.h>

#include <cstdint>
#include <set>
#include <utility>

using namespace proceduray;

namespace {

constexpr std::uint32_t width = 96;
constexpr std::uint32_t height = 64;

struct Cis565 {
  cis565::Cis565Scene scene;
  vk::Renderer renderer;
  explicit Cis565(const vk::Context& ctx, std::uint32_t limit = 5)
      : scene(limit), renderer(ctx, scene, scene.renderer_options()) {}

  vk::Frame render(float time, std::uint32_t depth, std::uint32_t flags) {
    renderer.set(cis565::constants_slot, cis565::default_constants(width, height, time, depth, flags));
    return renderer.render(width, height);
  }
};

glm::ivec3 at(const vk::Frame& f, glm::ivec2 p) {
  REQUIRE(p.x >= 0);
  REQUIRE(p.y >= 0);
  REQUIRE(p.x < static_cast<int>(width));
  REQUIRE(p.y < static_cast<int>(height));
  const std::size_t i = (std::size_t(p.y) * width + std::size_t(p.x)) * 4;
  return {f.rgba[i], f.rgba[i + 1], f.rgba[i + 2]};
}

glm::ivec2 pixel_of(glm::vec3 world) {
  return project(cis565::default_constants(width, height, 0.0f, 1).camera, world, width, height);
}

int luminance(glm::ivec3 c) { return c.r + c.g + c.b; }

}  // namespace

TEST_CASE("cis565 scene shows the ground, each sphere and the blob where they project") {
  TestContext t;
  Cis565 s(t.ctx);
  const vk::Frame ids = s.render(0.0f, 1, cis565::flag_ids);
  for (std::uint32_t i = 0; i < cis565::spheres.size(); ++i) {
    CAPTURE(i);
    CHECK(at(ids, pixel_of(cis565::spheres[i].centre)).r == int(cis565::sphere0_id + i));
  }
  CHECK(at(ids, pixel_of(cis565::blob_position)).r == cis565::blob_id);
  CHECK(at(ids, pixel_of({0.0f, 0.0f, 4.0f})).r == cis565::ground_id);
  CHECK(at(ids, {int(width) / 2, 0}).r == cis565::sky_id);
}

TEST_CASE("cis565 scene blob moves with time: data-driven metaballs inside the box derived from the same data") {
  TestContext t;
  Cis565 s(t.ctx);
  std::set<std::pair<int, int>> at0, at3;
  const vk::Frame a = s.render(0.0f, 1, cis565::flag_ids), b = s.render(3.0f, 1, cis565::flag_ids);
  for (int y = 0; y < int(height); ++y) {
    for (int x = 0; x < int(width); ++x) {
      if (at(a, {x, y}).r == cis565::blob_id) at0.insert({x, y});
      if (at(b, {x, y}).r == cis565::blob_id) at3.insert({x, y});
    }
  }
  CHECK(at0.size() > 20);
  CHECK(at3.size() > 20);
  CHECK(at0 != at3);
  // Every blob pixel lies inside the projection of metaballs_bounds (the BLAS box): nothing is cut.
  const Aabb box = metaballs_bounds(cis565::default_blob());
  int min_x = int(width), max_x = -1;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 c((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                      (corner & 4) ? box.max.z : box.min.z);
    const glm::ivec2 p = project(cis565::default_constants(width, height, 0.0f, 1).camera, cis565::blob_position + c,
                                 width, height);
    min_x = std::min(min_x, p.x);
    max_x = std::max(max_x, p.x);
  }
  for (const auto& [x, y] : at3) {
    CHECK(x >= min_x - 1);
    CHECK(x <= max_x + 1);
  }
}

TEST_CASE("cis565 scene shadows darken ground pixels, never brighten one, and leave open ground alone") {
  TestContext t;
  Cis565 s(t.ctx);
  const vk::Frame ids = s.render(0.0f, 1, cis565::flag_ids);
  const vk::Frame lit = s.render(0.0f, 1, 0u), shadowed = s.render(0.0f, 1, cis565::flag_shadows);
  int darker = 0, brighter = 0;
  for (int y = 0; y < int(height); ++y) {
    for (int x = 0; x < int(width); ++x) {
      if (at(ids, {x, y}).r != cis565::ground_id) continue;
      const int before = luminance(at(lit, {x, y})), after = luminance(at(shadowed, {x, y}));
      darker += after < before - 30;
      brighter += after > before;
    }
  }
  CHECK(darker > 40);  // the spheres' and the blob's shadows (two lights: two shadows each)
  CHECK(brighter == 0);
  const glm::ivec2 open = pixel_of({-3.0f, 0.0f, 4.0f});  // toward both lights: nothing in the way
  REQUIRE(at(ids, open).r == cis565::ground_id);
  CHECK(luminance(at(shadowed, open)) == luminance(at(lit, open)));
}

TEST_CASE("cis565 scene reflections: deeper paths change the mirror, never the matte sphere") {
  TestContext t;
  Cis565 s(t.ctx);
  const glm::ivec2 mirror = pixel_of(cis565::spheres[1].centre), matte = pixel_of(cis565::spheres[0].centre);
  const vk::Frame d1 = s.render(0.0f, 1, cis565::flag_shadows), d3 = s.render(0.0f, 3, cis565::flag_shadows);
  CHECK(at(d1, mirror) != at(d3, mirror));  // depth 1: no reflection ray; depth 3: the scene in the mirror
  CHECK(at(d1, matte) == at(d3, matte));    // reflectance 0: no reflection ray at any depth
  // A depth past the scene's limit is held to it: the same image as at the limit, no crash.
  Cis565 shallow(t.ctx, 2);
  const vk::Frame at_limit = shallow.render(0.0f, 2, cis565::flag_shadows);
  const vk::Frame past = shallow.render(0.0f, 9, cis565::flag_shadows);
  CHECK(past.rgba == at_limit.rgba);
}

TEST_CASE("cis565 scene bad input: depth limits outside 1..8 and no lights are refused") {
  CHECK_THROWS_WITH_AS(cis565::Cis565Scene(0), doctest::Contains("depth limit 0 is outside 1..8"), UsageError);
  CHECK_THROWS_WITH_AS(cis565::Cis565Scene(9), doctest::Contains("depth limit 9 is outside 1..8"), UsageError);
  CHECK_THROWS_WITH_AS(make_lights(std::span<const Light>{}), doctest::Contains("make_lights: 0 lights"), UsageError);
}
