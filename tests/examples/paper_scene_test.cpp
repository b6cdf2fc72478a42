// examples/02_paper_scene: the report's figure 3, checked by object ids and pixel classes.
#include "vk/test_context.hpp"

#include <02_paper_scene/paper_scene.hpp>

using namespace proceduray;

namespace {

constexpr std::uint32_t width = 128;
constexpr std::uint32_t height = 96;

/// A renderer of the paper scene at the test size.
struct Paper {
  paper::PaperScene scene;
  vk::Renderer renderer;
  explicit Paper(const vk::Context& ctx) : renderer(ctx, scene.build(ctx.limits()), scene.renderer_options()) {}

  vk::Frame render(float time, std::uint32_t flags) {
    paper::SceneConstants c = paper::default_constants(width, height, time);
    c.flags = flags;
    renderer.set(paper::constants_slot, c);
    return renderer.render(width, height);
  }
};

glm::ivec3 at(const vk::Frame& f, glm::ivec2 p) {
  if (p.x < 0 || p.y < 0 || p.x >= static_cast<int>(width) || p.y >= static_cast<int>(height)) {
    FAIL("pixel (" << p.x << ", " << p.y << ") is outside the image");
  }
  const std::size_t i = (std::size_t(p.y) * width + std::size_t(p.x)) * 4;
  return {f.rgba[i], f.rgba[i + 1], f.rgba[i + 2]};
}

glm::ivec2 pixel_of(glm::vec3 world) {
  return project(paper::default_constants(width, height, 0.0f).camera, world, width, height);
}

int luminance(glm::ivec3 c) { return c.r + c.g + c.b; }

}  // namespace

TEST_CASE("paper scene shows each object in its screen region") {
  TestContext t;
  Paper p(t.ctx);
  const vk::Frame ids = p.render(0.0f, paper::flag_object_ids);
  CHECK(at(ids, pixel_of(paper::pacman_placements[0].translation)).r == paper::pacman0_id);
  CHECK(at(ids, pixel_of(paper::pacman_placements[1].translation)).r == paper::pacman1_id);
  CHECK(at(ids, pixel_of(paper::julia_placement.translation)).r == paper::julia_id);
  CHECK(at(ids, pixel_of(paper::mandelbulb_placement.translation)).r == paper::mandelbulb_id);
  CHECK(at(ids, pixel_of({0.0f, 0.0f, 3.5f})).r == paper::plane_id);
  CHECK(at(ids, {width / 2, 0}).r == paper::sky_id);
  // Marched objects report their steps (g channel); the analytic Pac-man takes none.
  CHECK(at(ids, pixel_of(paper::mandelbulb_placement.translation)).g > 0);
  CHECK(at(ids, pixel_of(paper::pacman_placements[0].translation)).g == 0);
}

TEST_CASE("paper scene ground under an object is darker with shadows on") {
  TestContext t;
  Paper p(t.ctx);
  const vk::Frame ids = p.render(0.0f, paper::flag_object_ids);
  const vk::Frame lit = p.render(0.0f, 0);
  const vk::Frame shadowed = p.render(0.0f, paper::flag_shadows);
  std::size_t darker = 0, brighter = 0, objects_changed = 0;
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const int before = luminance(at(lit, {x, y})), after = luminance(at(shadowed, {x, y}));
      if (at(ids, {x, y}).r == paper::plane_id) {
        darker += after < before - 30;
        brighter += after > before;
      } else {
        objects_changed += after != before;
      }
    }
  }
  CHECK(darker > 100);  // the four objects cast shadows on the ground
  CHECK(brighter == 0);  // a shadow ray only ever removes light
  CHECK(objects_changed > 0);  // self-shadowing on the objects' far sides
  // Open ground in front of the objects sees the light either way.
  const glm::ivec2 open = pixel_of({0.0f, 0.0f, 4.0f});
  CHECK(std::abs(luminance(at(shadowed, open)) - luminance(at(lit, open))) <= 3);
}

TEST_CASE("paper scene reflections change reflective surfaces only") {
  TestContext t;
  Paper p(t.ctx);
  const vk::Frame ids = p.render(0.0f, paper::flag_object_ids);
  const vk::Frame plain = p.render(0.0f, paper::flag_shadows);
  const vk::Frame mirrored = p.render(0.0f, paper::flag_shadows | paper::flag_reflections);
  std::size_t sky_changed = 0, plane_changed = 0;
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const glm::ivec2 px(x, y);
      const bool changed = at(plain, px) != at(mirrored, px);
      if (at(ids, px).r == paper::sky_id) sky_changed += changed;
      if (at(ids, px).r == paper::plane_id) plane_changed += changed;
    }
  }
  CHECK(sky_changed == 0);        // the sky reflects nothing
  CHECK(plane_changed > 100);     // the ground mirrors the objects (reflectance 0.15)
}

TEST_CASE("paper scene renders are identical and animation moves only animated objects") {
  TestContext t;
  Paper p(t.ctx);
  const vk::Frame first = p.render(0.0f, paper::flag_object_ids);
  CHECK(p.render(0.0f, paper::flag_object_ids).rgba == first.rgba);
  const vk::Frame later = p.render(1.5f, paper::flag_object_ids);
  std::size_t changed = 0, changed_elsewhere = 0;
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const glm::ivec3 a = at(first, {x, y}), b = at(later, {x, y});
      if (a == b) continue;
      ++changed;
      const auto animated = [](int id) { return id == paper::julia_id || id == paper::mandelbulb_id; };
      changed_elsewhere += !(animated(a.r) || animated(b.r));
    }
  }
  CHECK(changed > 20);
  CHECK(changed_elsewhere == 0);
}
