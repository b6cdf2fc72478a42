// Overlapping AABBs (metaballs overlap by design): the closest-hit shader must see the attributes
// of the intersection it is the closest of, not those of another box's later report (a driver bug
// on some implementations, VK-GL-CTS#580). Checked per pixel against the closed form of five
// overlapping balls, each in its own AABB of one geometry, under orthographic rays.
#include "renderer_scene.hpp"
#include "test_context.hpp"
#include "test_paths.hpp"

#include <proceduray/proceduray.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>

namespace overlap_test {
namespace pr = proceduray;
using renderer_scene::BallHit;  // the renderer tests' attributes (a normal) and payload (a colour)
using renderer_scene::Colour;
using SceneInterface = proceduray::ShaderInterface<proceduray::Payload<Colour>, proceduray::RootComponent<>,
                                                   proceduray::RootArguments<>, proceduray::Attributes<BallHit>>;
using Scene = proceduray::Scene<SceneInterface>;

constexpr float radius = 0.5f;
// Each overlaps at least two others in the view, at different depths: the nearest changes across
// every overlap, so an attribute from the wrong report shows as the wrong normal.
constexpr std::array<glm::vec3, 5> centres{{{-0.45f, 0.0f, 0.3f}, {0.0f, 0.0f, 0.0f}, {0.45f, 0.0f, -0.3f},
                                           {0.0f, 0.45f, 0.25f}, {0.0f, -0.45f, -0.25f}}};

Scene balls() {
  Scene s;
  const auto primary = s.add_ray<Colour>("primary", {.miss = "sky.rmiss"});
  std::vector<pr::Aabb> boxes;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    boxes.push_back({centres[i] - glm::vec3(radius), centres[i] + glm::vec3(radius)});
    s.add_constant("ball" + std::to_string(i), centres[i]);
  }
  s.add_constant("ball_radius", radius);
  s.set_global_signature(pr::default_global_signature());
  s.add_raygen("ortho.rgen");  // tests/vk/shaders/outputs: rays along +z from z = -4 over [-1.5, 1.5]^2
  pr::add_object<BallHit>(s, "balls", {.geometry = pr::GeometryDesc::procedural(boxes), .intersection = "overlap.rint",
                                       .closest_hit = {{primary, "overlap.rchit"}}});
  return s;
}

pr::vk::RendererOptions options() {
  return {.shader_dirs = {test_source_dir() / "vk" / "shaders" / "overlap", test_source_dir() / "vk" / "shaders" / "outputs"}};
}

/// The nearest ball on the ray of (u, v) along +z from z = -4, in double: its normal, or nothing;
/// `clear` is false when two balls are within `eps` in t or the ray grazes one (too close to call).
struct Truth {
  bool hit = false, clear = true;
  glm::dvec3 normal{0.0};
};
Truth nearest(double u, double v) {
  Truth out;
  double best = std::numeric_limits<double>::infinity(), second = best;
  for (const glm::vec3& c : centres) {
    const double dx = u - c.x, dy = v - c.y, h = double{radius} * radius - dx * dx - dy * dy;
    if (std::abs(h) < 1e-3) out.clear = false;
    if (h < 0.0) continue;
    const double z = c.z - std::sqrt(h), t = z + 4.0;
    if (t < best) {
      second = best;
      best = t;
      out.normal = glm::dvec3(dx, dy, z - c.z) / double{radius};
    } else {
      second = std::min(second, t);
    }
  }
  out.hit = best < std::numeric_limits<double>::infinity();
  if (second - best < 1e-3) out.clear = false;
  return out;
}
}  // namespace overlap_test

using namespace proceduray;
using namespace overlap_test;

TEST_CASE("overlapping AABBs: each pixel's closest hit sees the attributes of its own intersection") {
  TestContext t;
  constexpr std::uint32_t size = 96;
  const overlap_test::Scene scene = balls();
  vk::Renderer renderer(t.ctx, scene, options());
  const vk::Frame f = renderer.render(size, size);
  std::size_t checked = 0, overlapped = 0;
  for (std::uint32_t y = 0; y < size; ++y) {
    for (std::uint32_t x = 0; x < size; ++x) {
      const double u = (x + 0.5) / size * 3.0 - 1.5, v = -((y + 0.5) / size * 3.0 - 1.5);
      const Truth truth = nearest(u, v);
      if (!truth.hit || !truth.clear) continue;
      std::size_t covering = 0;  // how many boxes the ray passes: > 1 is an overlap
      for (const glm::vec3& c : centres) covering += std::abs(u - c.x) <= radius && std::abs(v - c.y) <= radius;
      overlapped += covering > 1;
      ++checked;
      for (int k = 0; k < 3; ++k) {
        const int expected = static_cast<int>(std::lround(255.0 * std::clamp(truth.normal[k] * 0.5 + 0.5, 0.0, 1.0)));
        const int got = f.rgba[(std::size_t{y} * size + x) * 4 + k];
        CHECK_MESSAGE(std::abs(got - expected) <= 3, "pixel " << x << "," << y << " channel " << k);
      }
    }
  }
  CHECK(checked > size * size / 4);
  CHECK(overlapped > checked / 3);  // a third of them (42% here) pass more than one box
}
