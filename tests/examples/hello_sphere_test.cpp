// examples/01_hello_sphere: the first image, checked by its pixels.
#include "vk/test_context.hpp"

#include <01_hello_sphere/hello_sphere.hpp>

#include <cstring>

using namespace proceduray;
using hello_sphere::Layout;

namespace {

constexpr std::uint32_t width = 160;
constexpr std::uint32_t height = 90;

struct Pixel {
  int r, g, b;
};

Pixel at(const std::vector<std::uint8_t>& rgba, glm::ivec2 p) {
  REQUIRE(p.x >= 0);
  REQUIRE(p.y >= 0);
  REQUIRE(p.x < static_cast<int>(width));
  REQUIRE(p.y < static_cast<int>(height));
  const std::size_t i = (std::size_t(p.y) * width + std::size_t(p.x)) * 4;
  return {rgba[i], rgba[i + 1], rgba[i + 2]};
}

int to_byte(float v) { return static_cast<int>(v * 255.0f + 0.5f); }

bool is_background(Pixel p) {
  return std::abs(p.r - to_byte(Layout::background.r)) <= 1 && std::abs(p.g - to_byte(Layout::background.g)) <= 1 &&
         std::abs(p.b - to_byte(Layout::background.b)) <= 1;
}

glm::ivec2 centre_pixel(int instance) {
  return proceduray::project(hello_sphere::make_camera(width, height), Layout::centres[instance], width, height);
}

}  // namespace

TEST_CASE("hello sphere shows two spheres over the miss record's background") {
  TestContext t;
  hello_sphere::HelloSphere scene(t.ctx);
  const auto rgba = scene.render(width, height);
  REQUIRE(rgba.size() == std::size_t{width} * height * 4);
  // Corners see no geometry: the colour comes from the miss record.
  CHECK(is_background(at(rgba, {0, 0})));
  CHECK(is_background(at(rgba, {width - 1, height - 1})));
  // Sphere centres are hit, and each shows its instance's colour.
  const Pixel red = at(rgba, centre_pixel(0));
  const Pixel blue = at(rgba, centre_pixel(1));
  CHECK_FALSE(is_background(red));
  CHECK_FALSE(is_background(blue));
  CHECK(red.r > 2 * red.g);
  CHECK(red.r > 2 * red.b);
  CHECK(blue.b > 2 * blue.r);
  CHECK(blue.b > 2 * blue.g);
}

TEST_CASE("hello sphere colours come from each instance's hit record") {
  TestContext t;
  const glm::vec4 green{0.1f, 0.8f, 0.1f, 1.0f};
  const glm::vec4 white{0.9f, 0.9f, 0.9f, 1.0f};
  hello_sphere::HelloSphere scene(t.ctx, {green, white});
  const auto rgba = scene.render(width, height);
  const Pixel a = at(rgba, centre_pixel(0));
  const Pixel b = at(rgba, centre_pixel(1));
  CHECK(a.g > 3 * a.r);
  CHECK(a.g > 3 * a.b);
  CHECK(std::abs(b.r - b.g) <= 2);  // white stays grey under white light
  CHECK(std::abs(b.g - b.b) <= 2);
  CHECK(b.r > 100);

  // The record bytes sit right after each hit group's handle, where layout_sbt put them.
  const auto& sbt = scene.sbt();
  const auto bytes = sbt.bytes();
  for (std::uint32_t i = 0; i < 2; ++i) {
    glm::vec4 stored;
    std::memcpy(&stored, bytes.data() + sbt.layout().arguments_offset(SbtRegionKind::hit, i), sizeof stored);
    CHECK(stored == (i == 0 ? green : white));
  }
}

TEST_CASE("hello sphere rays inside the box but outside the sphere miss") {
  TestContext t;
  hello_sphere::HelloSphere scene(t.ctx);
  const auto rgba = scene.render(width, height);
  const auto camera = hello_sphere::make_camera(width, height);
  // A point at 1.25 radii along the box's diagonal is inside the AABB's silhouette, outside the sphere.
  const glm::vec3 corner = Layout::centres[0] + Layout::radii[0] * glm::vec3(-0.85f, 0.85f, 0.0f);
  CHECK(is_background(at(rgba, proceduray::project(camera, corner, width, height))));
  const glm::vec3 inside = Layout::centres[0] + Layout::radii[0] * glm::vec3(-0.5f, 0.5f, 0.0f);
  CHECK_FALSE(is_background(at(rgba, proceduray::project(camera, inside, width, height))));
}

TEST_CASE("hello sphere renders are byte identical") {
  TestContext t;
  hello_sphere::HelloSphere scene(t.ctx);
  const auto first = scene.render(width, height);
  const auto second = scene.render(width, height);
  CHECK(first == second);
  hello_sphere::HelloSphere again(t.ctx);
  CHECK(again.render(width, height) == first);
}

TEST_CASE("hello sphere rejects an empty image size") {
  TestContext t;
  hello_sphere::HelloSphere scene(t.ctx);
  CHECK_THROWS_WITH_AS(scene.render(0, 90), doctest::Contains("size 0x90"), proceduray::UsageError);
}
