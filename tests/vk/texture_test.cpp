// vk/texture.hpp through the renderer: a TextureSlot array and a cube map sampled by a closest-hit
// and a miss shader. Every floor pixel is checked against the texel its own camera ray lands on,
// computed here; the sky against the cube face its direction points at; mipmaps by the grey a
// far, fine checker averages to.
#include "frame_pixels.hpp"
#include "renderer_scene.hpp"
#include "test_context.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace texture_test {
struct TexArgs {
  float repeat;         // copies of the texture across the floor
  std::uint32_t layer;  // which of `grounds`
};
PROCEDURAY_STRUCT(TexArgs, scalar, repeat, layer);
using TexInterface = proceduray::ShaderInterface<
    proceduray::Payload<renderer_scene::Colour>, proceduray::RootComponent<renderer_scene::Constants, renderer_scene::Tint>,
    proceduray::RootArguments<TexArgs>, proceduray::Attributes<>>;
}  // namespace texture_test

using namespace proceduray;
using texture_test::TexArgs;
namespace rs = renderer_scene;

namespace {

constexpr std::uint32_t width = 96;
constexpr std::uint32_t height = 64;
constexpr TextureSlot grounds{.binding = 4, .name = "grounds", .count = 2};
constexpr TextureSlot sky{.binding = 5, .name = "sky", .cube = true};
const glm::ivec3 face_colours[6] = {{255, 0, 0}, {0, 255, 255}, {0, 255, 0}, {255, 0, 255}, {0, 0, 255}, {255, 255, 0}};

/// A 4x4 texture of sixteen distinct colours, stored as given (not sRGB).
TextureData palette() {
  std::vector<std::uint8_t> rgb;
  for (int i = 0; i < 16; ++i) {
    rgb.push_back(static_cast<std::uint8_t>(16 * i + 8));
    rgb.push_back(static_cast<std::uint8_t>(255 - 16 * i));
    rgb.push_back(static_cast<std::uint8_t>((i % 4) * 80));
  }
  TextureData t = TextureData::from_pixels(4, 4, 3, rgb);
  t.srgb = false;
  return t;
}
glm::ivec3 palette_colour(int i) { return {16 * i + 8, 255 - 16 * i, (i % 4) * 80}; }

TextureData uniform(glm::ivec3 c, std::uint32_t size = 2) {
  std::vector<std::uint8_t> rgb;
  for (std::uint32_t i = 0; i < size * size; ++i) {
    for (int k = 0; k < 3; ++k) rgb.push_back(static_cast<std::uint8_t>(c[k]));
  }
  TextureData t = TextureData::from_pixels(size, size, 3, rgb);
  t.srgb = false;
  return t;
}

/// A size x size checker of single black and white texels.
TextureData checker(std::uint32_t size) {
  std::vector<std::uint8_t> grey;
  for (std::uint32_t y = 0; y < size; ++y)
    for (std::uint32_t x = 0; x < size; ++x) grey.push_back((x + y) % 2 ? 255 : 0);
  TextureData t = TextureData::from_pixels(size, size, 1, grey);
  t.srgb = false;
  return t;
}

TextureData sky_cube() {
  std::vector<TextureData> faces;
  for (const glm::ivec3& c : face_colours) faces.push_back(uniform(c));
  return make_cube(faces);
}

/// RendererScene's camera and constants over a floor whose hit shader samples `grounds`.
struct Textured {
  TestContext t;
  Scene<texture_test::TexInterface> scene;
  std::optional<vk::Renderer> renderer;
  explicit Textured(TexArgs args, bool set_all = true) {
    const auto primary = scene.add_ray<rs::Colour>("primary", {.miss = "cube_sky.rmiss"});
    const auto group = scene.add_hit_group("floor", {.kind = HitGroupKind::triangles, .closest_hit = "textured.rchit"});
    const GeometryId floor = scene.add_geometry(
        "floor", GeometryDesc::triangles({{{-6, -1, -6}, {6, -1, -6}, {6, -1, 6}, {-6, -1, 6}}, {0, 2, 1, 0, 3, 2}}));
    scene.set_global_signature(scene.add_global_signature(
        "global", {.bindings = {{BindingKind::acceleration_structure, 0, 0, 1, "tlas"},
                                {BindingKind::storage_image, 1, 0, 1, "image"}, rs::constants_slot, rs::tints_slot,
                                grounds, sky}}));
    scene.add_raygen("scene.rgen");
    scene.add_hit(primary, group, scene.add_local_signature<TexArgs>("args"), args, floor);
    renderer.emplace(t.ctx, scene, rs::RendererScene::options());
    rs::prepare(*renderer, width, height);
    if (!set_all) return;
    // Nearest: linear filtering blends a 2x2 face with its neighbours across the (seamless) cube edges.
    renderer->set_texture(sky, sky_cube(), {.filter = TextureFilter::nearest});
    renderer->set_texture(grounds, uniform({10, 200, 30}), {}, 1);
  }
};

/// The direction of pixel (x, y)'s camera ray (not normalised), as scene.rgen makes it.
glm::vec3 ray_of(int x, int y) {
  const Camera c = rs::constants(width, height).camera;
  const glm::vec2 uv = (glm::vec2(x, y) + 0.5f) / glm::vec2(width, height) * 2.0f - 1.0f;
  return glm::vec3(c.forward) + uv.x * glm::vec3(c.right) - uv.y * glm::vec3(c.up);
}
/// Where pixel (x, y)'s ray meets the floor, and at what distance; nullopt for the sky.
std::optional<std::pair<glm::vec3, float>> floor_hit(int x, int y) {
  const glm::vec3 d = glm::normalize(ray_of(x, y));
  const glm::vec3 eye(rs::constants(width, height).camera.eye);
  if (d.y >= 0.0f) return std::nullopt;
  const float t = (-1.0f - eye.y) / d.y;
  const glm::vec3 p = eye + t * d;
  if (std::abs(p.x) > 5.9f || std::abs(p.z) > 5.9f) return std::nullopt;
  return std::pair{p, t};
}

}  // namespace

TEST_CASE("texture: floor pixels show the texel their ray lands on, and the sky the cube face it points at") {
  Textured r({.repeat = 1.0f, .layer = 0});
  r.renderer->set_texture(grounds, palette(), {.filter = TextureFilter::nearest, .mipmaps = false});
  const vk::Frame f = r.renderer->render(width, height);
  std::size_t floor = 0, sky_pixels = 0, off = 0;
  for (int y = 0; y < static_cast<int>(height); ++y) {
    for (int x = 0; x < static_cast<int>(width); ++x) {
      const glm::ivec3 got = frame_pixels::rgb(f, {x, y});
      if (const auto hit = floor_hit(x, y)) {
        const glm::vec2 uv = glm::vec2(hit->first.x, hit->first.z) / 12.0f + 0.5f;
        const glm::vec2 texel = uv * 4.0f;
        const glm::vec2 edge = glm::abs(texel - glm::round(texel));
        if (edge.x < 0.05f || edge.y < 0.05f) continue;  // on a texel boundary either side is right
        ++floor;
        const int i = 4 * static_cast<int>(texel.y) + static_cast<int>(texel.x);  // row 0: the data's first
        if (!frame_pixels::near(got, palette_colour(i), 1)) ++off;
        continue;
      }
      const glm::vec3 d = ray_of(x, y);
      const glm::vec3 a = glm::abs(d);
      const float top = std::max({a.x, a.y, a.z});
      if (d.y > -0.05f && (top == a.z && a.z > 1.2f * std::max(a.x, a.y))) {  // clearly toward -Z or +Z
        ++sky_pixels;
        if (!frame_pixels::near(got, face_colours[d.z > 0 ? 4 : 5], 1)) ++off;
      }
    }
  }
  CHECK(floor > width * height / 4);
  CHECK(sky_pixels > 100);
  CHECK(off == 0);
}

TEST_CASE("texture: an array element is chosen by index, and each element is its own texture") {
  Textured r({.repeat = 1.0f, .layer = 1});
  r.renderer->set_texture(grounds, palette());
  const vk::Frame f = r.renderer->render(width, height);
  const auto hit = floor_hit(width / 2, height - 4);
  REQUIRE(hit.has_value());
  CHECK(frame_pixels::near(frame_pixels::rgb(f, {width / 2, height - 4}), glm::ivec3(10, 200, 30), 1));
}

TEST_CASE("texture: mipmaps average a fine checker to grey where a pixel covers many texels") {
  const TexArgs fine{.repeat = 8.0f, .layer = 0};
  // Far floor pixels: the footprint spans at least four texels (host-side, the shader's own rule).
  const auto far_pixels = [] {
    std::vector<glm::ivec2> out;
    const float texel = 12.0f / (8.0f * 64.0f);
    const float angle = rs::constants(width, height).camera.pixel_angle;
    for (int y = 0; y < static_cast<int>(height); ++y)
      for (int x = 0; x < static_cast<int>(width); ++x)
        if (const auto hit = floor_hit(x, y); hit && angle * hit->second / texel >= 4.0f) out.push_back({x, y});
    return out;
  }();
  REQUIRE(far_pixels.size() > 200);
  const auto share_grey = [&](bool mipmaps) {
    Textured r(fine);
    r.renderer->set_texture(grounds, checker(64), {.mipmaps = mipmaps});
    const vk::Frame f = r.renderer->render(width, height);
    std::size_t grey = 0;
    for (const glm::ivec2& p : far_pixels) grey += frame_pixels::near(frame_pixels::rgb(f, p), glm::ivec3(128), 16) ? 1 : 0;
    return static_cast<double>(grey) / static_cast<double>(far_pixels.size());
  };
  CHECK(share_grey(true) > 0.95);   // levels 2 and up hold the checker's mean
  CHECK(share_grey(false) < 0.5);   // one level: each sample is a black or a white texel (or a blend of few)
}

TEST_CASE("texture: bad textures and slots are refused with the fix, and a missing one before the trace") {
  Textured r({.repeat = 1.0f, .layer = 0}, false);
  CHECK_THROWS_WITH_AS(r.renderer->render(width, height),
                       doctest::Contains("texture 0 at set 0 binding 4 was never given; call set_texture(slot, texture, "
                                         "sampler, 0) first"),
                       UsageError);
  CHECK_THROWS_WITH_AS(r.renderer->set_texture(grounds, palette(), {}, 2),
                       doctest::Contains("Renderer::set_texture: element 2 of set 0 binding 4, which holds 2 textures"),
                       UsageError);
  CHECK_THROWS_WITH_AS(r.renderer->set_texture(grounds, sky_cube()),
                       doctest::Contains("set 0 binding 4 holds 2D textures (TextureSlot::cube), given a cube map"),
                       UsageError);
  CHECK_THROWS_WITH_AS(r.renderer->set_texture(sky, palette()), doctest::Contains("make one with make_cube or load_cube"),
                       UsageError);
  const TextureSlot nowhere{.binding = 2};  // the constants' uniform
  CHECK_THROWS_WITH_AS(r.renderer->set_texture(nowhere, palette()),
                       doctest::Contains("set 0 binding 2 is not a texture binding of the global signature"), UsageError);
  const std::uint32_t limit = r.t.ctx.properties().limits.maxImageDimension2D;
  TextureData wide{limit + 1, 1, 1, TexelFormat::rgba8, false, std::vector<std::byte>(std::size_t{limit + 1} * 4)};
  const std::string too_wide = "Renderer::set_texture: a " + std::to_string(limit + 1) + "x1 texture is larger than";
  CHECK_THROWS_WITH_AS(r.renderer->set_texture(grounds, wide), doctest::Contains(too_wide.c_str()), DeviceLimitError);
  TextureData short_pixels = palette();
  short_pixels.pixels.resize(10);
  CHECK_THROWS_WITH_AS(r.renderer->set_texture(grounds, short_pixels), doctest::Contains("is malformed"), UsageError);
  // Refused calls changed nothing: still nothing to trace with.
  CHECK_THROWS_AS(r.renderer->render(width, height), UsageError);
  r.renderer->set_texture(grounds, palette());
  r.renderer->set_texture(grounds, palette(), {}, 1);
  r.renderer->set_texture(sky, sky_cube());
  CHECK_NOTHROW(r.renderer->render(width, height));
}

TEST_CASE("bad input: a float texture with a NaN texel (it would sample white)") {
  Textured r({.repeat = 1.0f, .layer = 0}, false);
  std::vector<float> texels(4 * 4 * 4, 0.5f);
  texels[4 * (2 * 4 + 3) + 1] = std::numeric_limits<float>::quiet_NaN();  // texel (3, 2), green
  CHECK_THROWS_WITH_AS(r.renderer->set_texture(grounds, TextureData::from_pixels(4, 4, 4, texels)),
                       doctest::Contains("Renderer::set_texture: a 4x4 texture has texel (3, 2), channel G, = nan; float "
                                         "texels must be finite"),
                       UsageError);
  texels[4 * (2 * 4 + 3) + 1] = 0.5f;
  texels[0] = std::numeric_limits<float>::infinity();
  CHECK_THROWS_WITH_AS(r.renderer->set_texture(grounds, TextureData::from_pixels(4, 4, 4, texels)),
                       doctest::Contains("texel (0, 0), channel R, = inf"), UsageError);
  texels[0] = 0.5f;
  CHECK_NOTHROW(r.renderer->set_texture(grounds, TextureData::from_pixels(4, 4, 4, texels)));
}

TEST_CASE("bad input: a Texture and a Buffer outlive every copy of their Context, and still work") {
  auto ctx = std::make_unique<vk::Context>(vk::ContextOptions{.validation = true});
  const long alone = ctx->use_count();
  vk::Buffer buffer(*ctx, 64, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  std::optional<vk::Texture> texture(std::in_place, *ctx, palette());
  CHECK(ctx->use_count() > alone + 1);  // the buffer's and the texture's handles each hold a share
  CHECK(ctx->validation_messages().empty());
  // Before, the device went here, and the texture's vkDestroyImage below used it after its end.
  ctx.reset();
  const std::vector<std::uint32_t> values{1u, 2u, 3u, 4u, 5u, 6u, 7u, 8u, 9u, 10u, 11u, 12u, 13u, 14u, 15u, 16u};
  buffer.write(std::span<const std::uint32_t>(values));
  CHECK(std::memcmp(buffer.data(), values.data(), sizeof(std::uint32_t) * values.size()) == 0);
  texture.reset();
  CHECK(buffer.size() == 64);
}  // the buffer goes last and takes the device with it: ASan and LSan see no use after free, no leak
