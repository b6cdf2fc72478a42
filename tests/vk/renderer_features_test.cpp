// vk/renderer.hpp's engine features, checked by pixel classes of features_scene.hpp: layers and
// instance masks, update policies and the work each frame reports, any-hit cut-outs with
// ignore/terminate paths, shadow rays that skip closest hits, and a callable shader.
#include "features_scene.hpp"
#include "frame_pixels.hpp"
#include "test_context.hpp"

#include <functional>

using namespace proceduray;
using features_scene::Config;
using features_scene::FeaturesScene;

namespace {

constexpr std::uint32_t width = 160;
constexpr std::uint32_t height = 120;

glm::ivec3 pixel(const vk::Frame& f, glm::ivec2 p) { return frame_pixels::rgb(f, p); }
/// Colours compared as RGB: the scene's RGBA constants convert to their first three channels.
glm::ivec3 bytes(glm::vec3 c) { return frame_pixels::bytes(c); }
using frame_pixels::near;
glm::ivec2 where(glm::vec3 p) { return project(features_scene::constants(width, height).camera, p, width, height); }

/// Pixels whose colour is within 2 levels of `c`.
std::size_t count(const vk::Frame& f, glm::vec3 c) {
  std::size_t n = 0;
  for (int y = 0; y < static_cast<int>(f.height); ++y)
    for (int x = 0; x < static_cast<int>(f.width); ++x) n += near(pixel(f, {x, y}), bytes(c)) ? 1 : 0;
  return n;
}
/// Mean pixel position of colour `c` (x, y); (-1, -1) when absent.
glm::vec2 centroid(const vk::Frame& f, glm::vec3 c) {
  glm::vec2 sum(0.0f);
  std::size_t n = 0;
  for (int y = 0; y < static_cast<int>(f.height); ++y)
    for (int x = 0; x < static_cast<int>(f.width); ++x)
      if (near(pixel(f, {x, y}), bytes(c))) {
        sum += glm::vec2(x, y);
        ++n;
      }
  return n == 0 ? glm::vec2(-1.0f) : sum / static_cast<float>(n);
}

const glm::vec3 tinted = glm::vec3(features_scene::floor_colour) * glm::vec3(Config{}.tint);
const glm::vec3 shadowed = tinted * 0.35f;
const glm::vec3 cut_shadowed = tinted * 0.5f;  // the cut-out's shadow any-hit stopped the shadow ray
/// A floor point in front of ball i, inside its shadow (the light is up and behind).
glm::vec3 shadow_point(std::size_t i) { return {features_scene::centres[i].x, 0.0f, 1.1f}; }
/// A floor point in front of ball i that no shadow reaches.
glm::vec3 open_point(std::size_t i) { return {features_scene::centres[i].x, 0.0f, 2.8f}; }

struct Rendered {
  TestContext t;
  FeaturesScene scene;
  vk::Renderer renderer;
  explicit Rendered(Config config = {})
      : scene(config), renderer(t.ctx, scene.table(t.ctx), FeaturesScene::options()) {
    features_scene::prepare(renderer, width, height);
  }
  vk::Frame frame() { return renderer.render(width, height); }
};

}  // namespace

TEST_CASE("features masks hide exactly the masked instances and shadow-less objects cast no shadow") {
  Rendered hidden;
  const vk::Frame f = hidden.frame();
  const glm::vec3 blue = features_scene::colours[1];
  CHECK(count(f, blue) == 0);                                   // B: not on the primary rays' layer
  CHECK(count(f, features_scene::colours[0]) > 100);            // A, C, D: visible
  CHECK(count(f, features_scene::colours[2]) > 100);
  CHECK(near(pixel(f, where(features_scene::centres[1])), bytes(tinted)));  // the floor shows where B is
  CHECK(near(pixel(f, where(shadow_point(0))), bytes(shadowed)));  // A casts a shadow
  CHECK(near(pixel(f, where(shadow_point(1))), bytes(shadowed)));  // hidden B still does (casts_shadow)
  CHECK(near(pixel(f, where(shadow_point(2))), bytes(tinted)));    // C is not on the shadow layer: none
  CHECK(near(pixel(f, where(open_point(2))), bytes(tinted)));
  Rendered shown({.show_b = true});
  const vk::Frame g = shown.frame();
  CHECK(count(g, blue) > 100);
  CHECK(near(pixel(g, where(features_scene::centres[1])), bytes(blue)));
  // Only B's pixels differ: every pixel that changed is blue in the second image.
  std::size_t changed = 0, changed_blue = 0;
  for (int y = 0; y < static_cast<int>(height); ++y)
    for (int x = 0; x < static_cast<int>(width); ++x)
      if (pixel(f, {x, y}) != pixel(g, {x, y})) {
        ++changed;
        changed_blue += near(pixel(g, {x, y}), bytes(blue)) ? 1 : 0;
      }
  CHECK(changed > 100);
  CHECK(changed_blue == changed);
}

TEST_CASE("features set_mask changes what rays see with a TLAS rebuild and no BLAS work") {
  Rendered r;
  const glm::vec3 blue = features_scene::colours[1], green = features_scene::colours[2];
  CHECK(count(r.frame(), blue) == 0);
  r.renderer.set_mask(r.scene.ball(1), 0, all_layers);  // B joins the primary rays' layer
  r.renderer.set_mask(r.scene.ball(2), 0, 0);           // C leaves every layer
  const vk::Frame f = r.frame();
  CHECK(f.work == vk::FrameWork{.tlas_builds = 1});
  CHECK(count(f, blue) > 100);
  CHECK(count(f, green) == 0);
  CHECK(near(pixel(f, where(shadow_point(2))), bytes(tinted)));  // C still casts no shadow
  r.renderer.set_mask(r.scene.ball(1), 0, all_layers);  // unchanged: no work
  CHECK(r.frame().work == vk::FrameWork{});
  CHECK_THROWS_WITH_AS(r.renderer.set_mask(r.scene.ball(1), 1, 0), doctest::Contains("no instance 1"), SceneError);
}

TEST_CASE("features set_visible hides an instance and its shadow with a TLAS update, and shows it as it was") {
  Rendered r;
  const glm::vec3 red = features_scene::colours[0];
  const vk::Frame before = r.frame();
  REQUIRE(count(before, red) > 100);
  REQUIRE(near(pixel(before, where(shadow_point(0))), bytes(shadowed)));
  r.renderer.set_visible(r.scene.ball(0), 0, false);
  const vk::Frame hidden = r.frame();
  CHECK(hidden.work == vk::FrameWork{.tlas_updates = 1});  // no build of anything
  CHECK(count(hidden, red) == 0);
  CHECK(near(pixel(hidden, where(features_scene::centres[0])), bytes(tinted)));  // the floor behind it
  CHECK(near(pixel(hidden, where(shadow_point(0))), bytes(tinted)));             // and no shadow
  CHECK(count(hidden, features_scene::colours[2]) == count(before, features_scene::colours[2]));  // others stay
  r.renderer.set_visible(r.scene.ball(0), 0, false);  // already hidden: no work
  CHECK(r.frame().work == vk::FrameWork{});
  r.renderer.set_visible(r.scene.ball(0), 0, true);
  const vk::Frame shown = r.frame();
  CHECK(shown.work == vk::FrameWork{.tlas_updates = 1});
  CHECK(shown.rgba == before.rgba);  // the updated TLAS finds the same hits
  CHECK_THROWS_WITH_AS(r.renderer.set_visible(r.scene.ball(0), 5, false),
                       doctest::Contains("Renderer::set_visible"), SceneError);
}

TEST_CASE("features add_instance and remove_instance: copies appear and go with TLAS builds, the others unchanged") {
  Rendered r;
  const glm::vec3 red = features_scene::colours[0];
  const vk::Frame before = r.frame();
  const std::size_t reds = count(before, red);
  REQUIRE(reds > 100);
  const auto placed = [](glm::vec3 at) {
    return glm::scale(glm::translate(glm::mat4(1.0f), at), glm::vec3(features_scene::radius));
  };
  // Two spots on open floor in front of the balls, clear of the slab and of every shadow.
  const glm::vec3 spots[] = {{0.0f, features_scene::radius, 2.2f}, {1.2f, features_scene::radius, 3.4f}};
  for (const glm::vec3& p : spots) REQUIRE(near(pixel(before, where(p)), bytes(tinted)));

  // The first add passes the TLAS's capacity: a larger TLAS replaces it and the descriptor follows.
  const std::uint32_t first = r.renderer.add_instance(r.scene.ball(0), placed(spots[0]));
  const vk::Frame one = r.frame();
  CHECK(one.work == vk::FrameWork{.tlas_builds = 1});
  CHECK(near(pixel(one, where(spots[0])), bytes(red)));  // through ball a's shared record: its colour
  CHECK(count(one, red) > reds + 50);
  // The second fits: the TLAS is rebuilt in place.
  const std::uint32_t second = r.renderer.add_instance(r.scene.ball(0), placed(spots[1]));
  CHECK(second == first + 1);
  const vk::Frame two = r.frame();
  CHECK(two.work == vk::FrameWork{.tlas_builds = 1});
  CHECK(near(pixel(two, where(spots[1])), bytes(red)));
  CHECK(r.renderer.instances(r.scene.ball(0)) == std::vector<std::uint32_t>{0, first, second});
  for (std::size_t i = 1; i < 4; ++i) {  // every other ball looks as it did
    CHECK(count(two, features_scene::colours[i]) == count(before, features_scene::colours[i]));
  }

  r.renderer.remove_instance(r.scene.ball(0), second);
  r.renderer.remove_instance(r.scene.ball(0), first);
  const vk::Frame back = r.frame();
  CHECK(back.work == vk::FrameWork{.tlas_builds = 1});  // both removals in one build
  CHECK(back.rgba == before.rgba);
  r.renderer.remove_instance(r.scene.ball(0), 0);  // the declared one too: red is gone, its shadow with it
  const vk::Frame none = r.frame();
  CHECK(count(none, red) == 0);
  CHECK(near(pixel(none, where(shadow_point(0))), bytes(tinted)));
  CHECK(r.renderer.instances(r.scene.ball(0)).empty());
  CHECK_THROWS_WITH_AS(r.renderer.set_visible(r.scene.ball(0), 0, true), doctest::Contains("was removed"), UsageError);
  // Removed to none, the BLAS keeps its records: an instance can come back.
  // The slot freed last (the declared one's) comes back with its next generation.
  CHECK(r.renderer.add_instance(r.scene.ball(0), placed(features_scene::centres[0])) == (1u << 24 | 0u));
  CHECK(r.frame().rgba == before.rgba);
}

TEST_CASE("features a closest-hit that traces rays: the depth is derived, and a smaller declared one refused") {
  TestContext t;
  // floor.rchit calls traceRayEXT (shadow rays); depth 1 would make lavapipe die at the nested trace.
  FeaturesScene too_small({.recursion_depth = 1});
  CHECK_THROWS_WITH_AS(vk::Renderer(t.ctx, too_small.table(t.ctx), FeaturesScene::options()),
                       doctest::Contains("Renderer: the shaders nest rays 2 deep (raygen 'scene.rgen' > ray \"primary\" > "
                                         "closest_hit 'floor.rchit' > ray \"shadow\") but the scene declares max "
                                         "recursion depth 1"),
                       UsageError);
  for (const std::uint32_t depth : {0u, 2u}) {  // 0: undeclared, derived from the shaders
    CAPTURE(depth);
    FeaturesScene scene({.recursion_depth = depth});
    vk::Renderer renderer(t.ctx, scene.table(t.ctx), FeaturesScene::options());
    features_scene::prepare(renderer, width, height);
    const vk::Frame f = renderer.render(width, height);
    CHECK(near(pixel(f, where(shadow_point(0))), bytes(shadowed)));  // the nested shadow ray ran
  }
}

TEST_CASE("features any-hit cut-out shows the background through its holes and its shadow has holes") {
  Rendered cut;
  Rendered solid({.cutout_opaque = true});
  const vk::Frame f = cut.frame();
  const vk::Frame g = solid.frame();
  const glm::vec3 yellow = features_scene::colours[3];
  const std::size_t solid_count = count(g, yellow);
  const std::size_t cut_count = count(f, yellow);
  CHECK(solid_count > 200);
  CHECK(cut_count < solid_count * 8 / 10);
  CHECK(cut_count > solid_count * 2 / 10);
  // Every ball pixel the cut-out lost shows what is behind: floor (lit or shadowed) or sky.
  std::size_t through = 0, behind = 0;
  for (int y = 0; y < static_cast<int>(height); ++y)
    for (int x = 0; x < static_cast<int>(width); ++x) {
      const glm::ivec2 p{x, y};
      if (!near(pixel(g, p), bytes(yellow)) || near(pixel(f, p), bytes(yellow))) continue;
      ++through;
      const glm::ivec3 c = pixel(f, p);
      behind += near(c, bytes(tinted)) || near(c, bytes(shadowed)) || near(c, bytes(cut_shadowed)) ||
                        near(c, bytes(features_scene::sky_colour))
                    ? 1
                    : 0;
    }
  CHECK(through > solid_count / 10);
  CHECK(behind == through);
  // Shadow rays ignore hits in the holes (any-hit) and stop at the first solid stripe (terminate).
  // The opaque ball's shadow is 0.35 dark; the cut-out's, where its shadow any-hit terminated, 0.5.
  std::size_t dark_solid = 0, dark_cut = 0, opaque_dark_cut = 0, lit_through = 0;
  const glm::ivec2 lo = where({features_scene::centres[3].x - 0.7f, 0.0f, 1.6f});
  const glm::ivec2 hi = where({features_scene::centres[3].x + 0.7f, 0.0f, 0.6f});
  for (int y = hi.y; y <= lo.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) {
      const bool was_dark = near(pixel(g, {x, y}), bytes(shadowed));
      dark_solid += was_dark ? 1 : 0;
      dark_cut += near(pixel(f, {x, y}), bytes(cut_shadowed)) ? 1 : 0;
      opaque_dark_cut += near(pixel(f, {x, y}), bytes(shadowed)) ? 1 : 0;
      lit_through += was_dark && near(pixel(f, {x, y}), bytes(tinted)) ? 1 : 0;
    }
  CHECK(dark_solid > 20);
  CHECK(dark_cut > 0);
  CHECK(opaque_dark_cut == 0);  // every shadow ray that hit the cut-out ran its shadow any-hit
  CHECK(lit_through > 0);
  CHECK(dark_cut < dark_solid);
}

TEST_CASE("features callable shader changes the colour it is asked to") {
  Rendered tinted_floor;
  const vk::Frame f = tinted_floor.frame();
  CHECK(near(pixel(f, where(open_point(1))), bytes(tinted)));
  const glm::vec4 other{0.25f, 1.0f, 0.5f, 0.0f};
  Rendered retinted({.tint = other});
  const vk::Frame g = retinted.frame();
  CHECK(near(pixel(g, where(open_point(1))), bytes(glm::vec3(features_scene::floor_colour) * glm::vec3(other))));
  CHECK(near(pixel(g, where(features_scene::centres[0])), bytes(features_scene::colours[0])));  // balls untouched
}

TEST_CASE("features DynamicTransform moves instances with TLAS refits and no BLAS builds") {
  Rendered r;
  const vk::Frame first = r.frame();
  CHECK(first.work == vk::FrameWork{});
  const glm::vec3 red = features_scene::colours[0];
  const glm::vec2 before = centroid(first, red);
  for (int step = 1; step <= 3; ++step) {
    const glm::vec3 centre = features_scene::centres[0] + glm::vec3(0.0f, 0.5f * static_cast<float>(step), 0.0f);
    r.renderer.set_transform(r.scene.ball(0), 0, glm::scale(glm::translate(glm::mat4(1.0f), centre),
                                                            glm::vec3(features_scene::radius)));
    const vk::Frame f = r.frame();
    CHECK(f.work == vk::FrameWork{.tlas_updates = 1});
    CHECK(near(pixel(f, where(centre)), bytes(red)));
    CHECK(centroid(f, red).y < before.y - 2.0f * static_cast<float>(step));  // up the screen as it rises
  }
  CHECK(r.frame().work == vk::FrameWork{});
  // All instances of a geometry at once: one refit; a bad matrix or count moves nothing.
  const glm::vec3 high = features_scene::centres[0] + glm::vec3(0.0f, 2.0f, 0.0f);
  const glm::mat4 one[] = {glm::scale(glm::translate(glm::mat4(1.0f), high), glm::vec3(features_scene::radius))};
  r.renderer.set_transforms(r.scene.ball(0), one);
  const vk::Frame all = r.frame();
  CHECK(all.work == vk::FrameWork{.tlas_updates = 1});
  CHECK(near(pixel(all, where(high)), bytes(red)));
  const glm::mat4 singular[] = {glm::scale(glm::mat4(1.0f), glm::vec3(0.0f))};  // affine, rank 0
  CHECK_THROWS_WITH_AS(r.renderer.set_transforms(r.scene.ball(0), singular),
                       doctest::Contains("Renderer::set_transforms: geometry \"a\" instance 0 transform is singular"),
                       InvalidGeometryError);
  CHECK_THROWS_WITH_AS(r.renderer.set_transforms(r.scene.ball(0), {}),
                       doctest::Contains("has 1 instances, 0 transforms given; give one per instance"),
                       InvalidGeometryError);
  CHECK_THROWS_WITH_AS(r.renderer.set_transforms(r.scene.ball(2), one), doctest::Contains("geometry \"c\" is Static"),
                       UsageError);
  CHECK(r.frame().work == vk::FrameWork{});
}

TEST_CASE("features DynamicGeometry AABB changes show next frame: refit for the same count and rebuild otherwise") {
  Rendered r;
  const glm::vec3 magenta = features_scene::slab_colour;
  const glm::vec3 left = (features_scene::left_box.min + features_scene::left_box.max) * 0.5f;
  const glm::vec3 right = (features_scene::right_box.min + features_scene::right_box.max) * 0.5f;
  const vk::Frame first = r.frame();
  CHECK(near(pixel(first, where(left)), bytes(magenta)));
  CHECK_FALSE(near(pixel(first, where(right)), bytes(magenta)));

  features_scene::prepare(r.renderer, width, height, {features_scene::right_box});
  r.renderer.set_aabbs(r.scene.slab(), {&features_scene::right_box, 1});
  const vk::Frame moved = r.frame();
  CHECK(moved.work == vk::FrameWork{.blas_refits = 1, .tlas_updates = 1});
  CHECK(near(pixel(moved, where(right)), bytes(magenta)));
  CHECK_FALSE(near(pixel(moved, where(left)), bytes(magenta)));

  const Aabb both[] = {features_scene::left_box, features_scene::right_box};
  features_scene::prepare(r.renderer, width, height, {both[0], both[1]});
  r.renderer.set_aabbs(r.scene.slab(), both);
  const vk::Frame two = r.frame();
  CHECK(two.work == vk::FrameWork{.blas_builds = 1, .tlas_builds = 1});
  CHECK(near(pixel(two, where(right)), bytes(magenta)));
  CHECK(near(pixel(two, where(left)), bytes(magenta)));
  CHECK(r.frame().work == vk::FrameWork{});
}

TEST_CASE("features bad updates are refused with the fix") {
  Rendered r;
  const Aabb box{};
  CHECK_THROWS_WITH_AS(r.renderer.set_aabbs(r.scene.ball(2), {&box, 1}),
                       doctest::Contains("geometry \"c\" is Static, so its BLAS was built not to change; declare it "
                                         "with update = UpdatePolicy::DynamicGeometry"),
                       UsageError);
  CHECK_THROWS_WITH_AS(r.renderer.set_aabbs(r.scene.ball(0), {&box, 1}),
                       doctest::Contains("geometry \"a\" is DynamicTransform"), UsageError);
  CHECK_THROWS_WITH_AS(r.renderer.set_aabbs(r.scene.slab(), {}), doctest::Contains("given no boxes"),
                       InvalidGeometryError);
  const Aabb inverted{glm::vec3(1.0f), glm::vec3(-1.0f)};
  CHECK_THROWS_WITH_AS(r.renderer.set_aabbs(r.scene.slab(), {&inverted, 1}),
                       doctest::Contains("Renderer::set_aabbs: geometry \"slab\" AABB 0 has min"), InvalidGeometryError);
  CHECK_THROWS_WITH_AS(r.renderer.set_mesh(r.scene.slab(), {}), doctest::Contains("is procedural; change its boxes"),
                       UsageError);
  CHECK_THROWS_WITH_AS(r.renderer.set_vertices(r.scene.floor(), {}), doctest::Contains("geometry \"floor\" is Static"),
                       UsageError);
  CHECK_THROWS_WITH_AS(r.renderer.set_transform(r.scene.ball(3), 0, glm::mat4(1.0f)),
                       doctest::Contains("geometry \"d\" is Static"), UsageError);
  // A refused change leaves the renderer as it was.
  CHECK(r.frame().work == vk::FrameWork{});
}
