// examples/05_textured_scene: the ground shows its PNG's texels where each ray lands, the torus's
// normals are interpolated from its vertices (not its faces), the sky is the environment map in
// each pixel's direction, and beads appear and go as instances are added and removed.
#include "vk/test_context.hpp"

#include <05_textured_scene/textured_scene.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

using namespace proceduray;

namespace {

constexpr std::uint32_t width = 160;
constexpr std::uint32_t height = 96;

struct Textured {
  textured::TexturedScene scene;
  vk::Renderer renderer;
  explicit Textured(const vk::Context& ctx) : renderer(ctx, scene, scene.renderer_options()) {
    textured::set_textures(renderer);
  }
  vk::Frame render(std::uint32_t flags) {
    renderer.set(textured::constants_slot, textured::default_constants(width, height, flags));
    return renderer.render(width, height);
  }
};

glm::ivec3 at(const vk::Frame& f, int x, int y) {
  const std::size_t i = (std::size_t(y) * width + std::size_t(x)) * 4;
  return {f.rgba[i], f.rgba[i + 1], f.rgba[i + 2]};
}
bool near(glm::ivec3 a, glm::ivec3 b, int tolerance) {
  return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::ivec3(tolerance)));
}
glm::ivec3 bytes(glm::vec3 c) { return glm::ivec3(glm::round(glm::clamp(c, 0.0f, 1.0f) * 255.0f)); }
float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

const Camera camera = textured::default_constants(width, height).camera;
glm::vec3 ray_of(int x, int y) {
  const glm::vec2 uv = (glm::vec2(x, y) + 0.5f) / glm::vec2(width, height) * 2.0f - 1.0f;
  return glm::normalize(glm::vec3(camera.forward) + uv.x * glm::vec3(camera.right) - uv.y * glm::vec3(camera.up));
}

}  // namespace

TEST_CASE("textured scene: ground pixels show the PNG's texel where their ray lands") {
  TestContext t;
  Textured s(t.ctx);
  const vk::Frame ids = s.render(textured::flag_ids);
  const vk::Frame albedo = s.render(textured::flag_albedo);
  const textured::Constants c = textured::default_constants(width, height);
  std::size_t checked = 0, off = 0;
  for (int y = 0; y < static_cast<int>(height); ++y) {
    for (int x = 0; x < static_cast<int>(width); ++x) {
      if (at(ids, x, y).r != textured::ground_id) continue;
      const glm::vec3 d = ray_of(x, y);
      const float t_hit = -c.camera.eye.y / d.y;
      const glm::vec3 p = glm::vec3(c.camera.eye) + t_hit * d;
      const float texel_world = 1.0f / (c.ground_scale * 64.0f);
      if (c.camera.pixel_angle * t_hit / texel_world > 1.0f) continue;  // level 0 only: the texels as drawn
      const glm::vec2 texel = glm::fract(glm::vec2(p.x, p.z) * c.ground_scale) * 64.0f;
      const glm::ivec2 k(glm::floor(texel));
      const glm::vec2 in_tile = glm::mod(texel, 8.0f);  // grout at 0..1, stone 1..8
      if (in_tile.x < 1.6f || in_tile.y < 1.6f || in_tile.x > 7.4f || in_tile.y > 7.4f) continue;
      const glm::vec3 stone = ((k.x / 8 + k.y / 8) % 2 == 0) ? glm::vec3(196, 170, 130) : glm::vec3(120, 130, 150);
      const glm::vec3 linear(srgb_to_linear(stone.r / 255.0f), srgb_to_linear(stone.g / 255.0f),
                             srgb_to_linear(stone.b / 255.0f));
      ++checked;
      if (!near(at(albedo, x, y), bytes(linear), 3)) ++off;
    }
  }
  CHECK(checked > 500);
  CHECK(off == 0);
}

TEST_CASE("textured scene: the torus's interpolated normals differ from its face normals and vary smoothly") {
  TestContext t;
  Textured s(t.ctx);
  const vk::Frame ids = s.render(textured::flag_ids);
  const vk::Frame smooth = s.render(textured::flag_normals);
  const vk::Frame flat = s.render(textured::flag_normals | textured::flag_flat);
  std::size_t torus = 0, differ = 0, flat_same = 0, smooth_same = 0;
  for (int y = 0; y < static_cast<int>(height); ++y) {
    for (int x = 0; x + 1 < static_cast<int>(width); ++x) {
      if (at(ids, x, y).r != textured::torus_id || at(ids, x + 1, y).r != textured::torus_id) continue;
      ++torus;
      if (!near(at(smooth, x, y), at(flat, x, y), 4)) ++differ;
      if (at(flat, x, y) == at(flat, x + 1, y)) ++flat_same;      // faces: constant across a triangle
      if (at(smooth, x, y) == at(smooth, x + 1, y)) ++smooth_same;  // vertices: changes pixel to pixel
    }
  }
  REQUIRE(torus > 300);
  CHECK(differ > torus / 2);
  CHECK(flat_same > 2 * smooth_same);
}

TEST_CASE("textured scene: the sky is the environment map in each pixel's direction") {
  TestContext t;
  Textured s(t.ctx);
  const vk::Frame ids = s.render(textured::flag_ids);
  const vk::Frame colour = s.render(0);
  std::size_t checked = 0, off = 0;
  for (int y = 0; y < static_cast<int>(height); ++y) {
    for (int x = 0; x < static_cast<int>(width); ++x) {
      if (at(ids, x, y).r != textured::sky_id) continue;
      const glm::vec3 d = ray_of(x, y);
      // The cube map holds the function at texel centres; linear filtering between them differs by little.
      if (textured::sun_glow(d) > 1e-3f) continue;  // the sun's edge is sharper than a texel
      ++checked;
      if (!near(at(colour, x, y), bytes(textured::sky_colour(d)), 4)) ++off;
    }
  }
  CHECK(checked > 1000);
  CHECK(off == 0);
}

TEST_CASE("textured scene: beads appear as instances are added and are gone once removed") {
  TestContext t;
  Textured s(t.ctx);
  const auto bead_at = [&](const vk::Frame& ids, std::uint32_t slot) {
    const glm::ivec2 p = project(camera, textured::bead_centre(slot), width, height);
    return at(ids, p.x, p.y).r == textured::bead_id;
  };
  CHECK_FALSE(bead_at(s.render(textured::flag_ids), 0));  // none declared
  textured::Beads beads;
  beads.step(s.renderer, s.scene.beads(), 0);
  vk::Frame ids = s.render(textured::flag_ids);
  CHECK(ids.work == vk::FrameWork{.tlas_builds = 1});
  CHECK(bead_at(ids, 0));
  for (std::uint32_t f = 1; f < 6; ++f) beads.step(s.renderer, s.scene.beads(), f);
  CHECK(beads.slots() == std::vector<std::uint32_t>{2, 3, 4, 5});
  ids = s.render(textured::flag_ids);
  for (std::uint32_t slot : {2u, 3u, 4u, 5u}) {
    CAPTURE(slot);
    CHECK(bead_at(ids, slot));
  }
  CHECK_FALSE(bead_at(ids, 0));  // removed
  CHECK_FALSE(bead_at(ids, 1));
  CHECK_FALSE(bead_at(ids, 6));  // never added
}
