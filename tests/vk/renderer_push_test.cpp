// vk/renderer.hpp's push constants: typed, declared in GLSL from the scene, recorded with each
// trace (no buffer, no rebuild), and refused clearly when missing, mistyped or too large.
#include "frame_pixels.hpp"
#include "renderer_scene.hpp"
#include "test_context.hpp"
#include "test_paths.hpp"

#include <proceduray/proceduray.hpp>

#include <optional>

using namespace proceduray;

namespace renderer_push_test {
struct Colour {
  glm::vec3 rgb;
};
PROCEDURAY_STRUCT(Colour, scalar, rgb);
struct Knobs {
  glm::vec4 tint;
  float exposure;
};
PROCEDURAY_STRUCT(Knobs, scalar, tint, exposure);
struct Other {
  glm::vec4 tint;
  float exposure;
};
PROCEDURAY_STRUCT(Other, scalar, tint, exposure);
struct Huge {
  glm::mat4 a, b, c, d, e, f, g, h;  // 512 bytes: past every device's maxPushConstantsSize we run on (256)
};
PROCEDURAY_STRUCT(Huge, scalar, a, b, c, d, e, f, g, h);
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<Colour>, proceduray::RootComponent<Knobs, Other, Huge>, proceduray::RootArguments<>,
                                   proceduray::Attributes<>>;
using TestScene = proceduray::Scene<TestSceneInterface>;
}  // namespace renderer_push_test

using namespace renderer_push_test;

namespace {
constexpr PushConstantSlot<Knobs> knobs{.name = "knobs"};

/// One ray type, no geometry (every ray misses), the global signature's push constants `push`.
struct PushScene {
  TestScene scene;
  explicit PushScene(PushConstantBlock push) {
    scene.add_ray<Colour>("primary", {.miss = "push.rmiss"});
    scene.set_global_signature({.bindings = {{BindingKind::acceleration_structure, 0, 0, 1, "tlas"},
                                             {BindingKind::storage_image, 1, 0, 1, "image"}},
                                .push_constants = push});
    scene.add_raygen("push.rgen");
  }
  const TestScene& build(const vk::Context&) const { return scene; }
  static vk::RendererOptions options() { return {.shader_dirs = {test_source_dir() / "vk" / "shaders" / "push"}}; }
};
}  // namespace

TEST_CASE("renderer push constants reach every stage and change without rebuilding") {
  TestContext t;
  PushScene s(knobs);
  vk::Renderer renderer(t.ctx, s.build(t.ctx), PushScene::options());
  CHECK(renderer.pipeline().push_constant_size() == sizeof(Knobs));
  CHECK_THROWS_WITH_AS(renderer.render(8, 8), doctest::Contains("never given a value; call set_push(slot, value) first"),
                       UsageError);
  renderer.set_push(knobs, Knobs{{1.0f, 0.0f, 0.0f, 1.0f}, 1.0f});
  const vk::Frame red = renderer.render(8, 8);
  CHECK(frame_pixels::near(frame_pixels::rgb(red, {3, 3}), glm::ivec3(255, 0, 0)));
  renderer.set_push(knobs, Knobs{{0.0f, 0.6f, 1.0f, 1.0f}, 0.5f});  // tint from the miss shader, exposure from raygen
  const vk::Frame dim = renderer.render(8, 8);
  CHECK(frame_pixels::near(frame_pixels::rgb(dim, {5, 1}), frame_pixels::bytes(glm::vec3(0.0f, 0.3f, 0.5f))));
  CHECK(dim.work == vk::FrameWork{});
}

TEST_CASE("renderer push constants refuse another slot untyped blocks and oversized ones") {
  TestContext t;
  {
    PushScene s(knobs);
    vk::Renderer renderer(t.ctx, s.build(t.ctx), PushScene::options());
    constexpr PushConstantSlot<Other> other{.name = "knobs"};
    CHECK_THROWS_WITH_AS(renderer.set_push(other, Other{}),
                         doctest::Contains("the slot holds Other \"knobs\" but the global signature declares Knobs \"knobs\""),
                         UsageError);
  }
  {
    renderer_scene::RendererScene s;  // a global signature without push constants
    vk::Renderer renderer(t.ctx, s.table(t.ctx), renderer_scene::RendererScene::options());
    CHECK_THROWS_WITH_AS(renderer.set_push(knobs, Knobs{}),
                         doctest::Contains("declares no typed push constants (0 untyped bytes); declare them with "
                                           "GlobalSignatureDesc::push_constants = a PushConstantSlot<Knobs>"),
                         UsageError);
  }
  {
    constexpr PushConstantSlot<Huge> huge{.name = "huge"};
    PushScene s(huge);
    const std::uint32_t limit = t.ctx.properties().limits.maxPushConstantsSize;
    REQUIRE(sizeof(Huge) > limit);
    CHECK_THROWS_WITH_AS(vk::Renderer(t.ctx, s.build(t.ctx), PushScene::options()),
                         doctest::Contains("Plan::layout: the push constant block (bytes) the global signature declares "
                                           "is 512, "),
                         DeviceLimitError);
  }
}
