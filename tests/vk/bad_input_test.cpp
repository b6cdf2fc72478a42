// The bad-input table of the Vulkan layer: calls on a renderer (or a context) with a wrong value,
// each refused with an error that names the operation, the value and the fix, before any device
// work can read or write out of bounds. tests/scene/bad_input_test.cpp holds the pure cases.
#include "features_scene.hpp"
#include "renderer_scene.hpp"
#include "scoped_env.hpp"
#include "test_context.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <string>
#include <vector>

using namespace proceduray;
using renderer_scene::RendererScene;
using Contains = doctest::Contains;

namespace bad_input_vk {
struct Other {  // a registered type no binding of the scene holds
  glm::vec4 a;
  glm::vec4 b;
};
PROCEDURAY_STRUCT(Other, scalar, a, b);
}  // namespace bad_input_vk

namespace {
constexpr std::uint32_t width = 32, height = 24;
using bad_input_vk::Other;

/// A renderer of RendererScene's table, balls under `policy`, on a validated context.
struct Built {
  TestContext t;
  RendererScene s;
  vk::Renderer r;
  explicit Built(UpdatePolicy policy = UpdatePolicy::Static)
      : s(policy), r(t.ctx, s.table(t.ctx), RendererScene::options()) {}
};

/// RendererScene's table with the tints storage buffer indexed per TLAS instance (3 instances).
renderer_scene::Scene per_instance_scene(RendererScene& s, const vk::Context& ctx) {
  auto scene = s.table(ctx);
  constexpr StorageSlot<renderer_scene::Tint> tints{.binding = 3, .name = "tints", .per_instance = true};
  scene.set_global_signature(scene.add_global_signature(
      "per_instance", {.bindings = {{BindingKind::acceleration_structure, 0, 0, 1, "tlas"},
                                    {BindingKind::storage_image, 1, 0, 1, "image"}, renderer_scene::constants_slot, tints}}));
  return scene;
}
}  // namespace

TEST_CASE("bad input: a uniform set through a slot of another type") {
  Built b;
  auto& [t, s, r] = b;
  constexpr UniformSlot<Other> wrong{.binding = 2};
  CHECK_THROWS_WITH_AS(r.set(wrong, Other{}),
                       Contains("Renderer::set: set 0 binding 2 holds Constants in the global signature, not Other"),
                       UsageError);
}

TEST_CASE("bad input: a uniform set at a binding that is not a uniform") {
  Built b;
  auto& [t, s, r] = b;
  constexpr UniformSlot<Other> nowhere{.binding = 9};
  CHECK_THROWS_WITH_AS(r.set(nowhere, Other{}), Contains("set 0 binding 9 is not a uniform buffer of the global signature"),
                       UsageError);
}

TEST_CASE("bad input: a storage buffer set through a slot of another type") {
  Built b;
  auto& [t, s, r] = b;
  constexpr StorageSlot<Other> wrong{.binding = 3};
  const std::vector<Other> values(4);
  CHECK_THROWS_WITH_AS(r.set_storage(wrong, std::span<const Other>(values)),
                       Contains("Renderer::set_storage: set 0 binding 3 holds Tint in the global signature, not Other"),
                       UsageError);
}

TEST_CASE("bad input: a per-instance storage buffer with fewer elements than instances") {
  TestContext t;
  RendererScene s;
  const auto scene = per_instance_scene(s, t.ctx);
  vk::Renderer r(t.ctx, scene, RendererScene::options());
  constexpr StorageSlot<renderer_scene::Tint> tints{.binding = 3, .name = "tints", .per_instance = true};
  const std::vector<renderer_scene::Tint> two(2);
  CHECK_THROWS_WITH_AS(r.set_storage(tints, std::span<const renderer_scene::Tint>(two)),
                       Contains("set 0 binding 3 is indexed per TLAS instance but got 2 elements for 3 instances"),
                       UsageError);
  const std::vector<renderer_scene::Tint> three(3);
  r.set_storage(tints, std::span<const renderer_scene::Tint>(three));  // one per instance: accepted
}

TEST_CASE("bad input: adding an instance a per-instance buffer is too short for, or no record serves, and removing twice") {
  TestContext t;
  RendererScene s;
  const auto scene = per_instance_scene(s, t.ctx);
  vk::Renderer r(t.ctx, scene, RendererScene::options());
  constexpr StorageSlot<renderer_scene::Tint> tints{.binding = 3, .name = "tints", .per_instance = true};
  const GeometryId floor = scene.geometry_id("floor");
  const glm::mat4 up = glm::translate(glm::mat4(1.0f), {0.0f, 0.5f, 0.0f});
  r.set_storage(tints, std::span<const renderer_scene::Tint>(std::vector<renderer_scene::Tint>(3)));
  CHECK_THROWS_WITH_AS(r.add_instance(floor, up),
                       Contains("Renderer::add_instance: per-instance storage buffer at set 0 binding 3 holds 3 elements, "
                                "and the new instance's custom index is 3"),
                       UsageError);
  CHECK(r.instances(floor) == std::vector<std::uint32_t>{0});  // refused: nothing changed
  r.set_storage(tints, std::span<const renderer_scene::Tint>(std::vector<renderer_scene::Tint>(4)));
  CHECK(r.add_instance(floor, up) == 1);
  CHECK_THROWS_WITH_AS(r.set_storage(tints, std::span<const renderer_scene::Tint>(std::vector<renderer_scene::Tint>(3))),
                       Contains("got 3 elements for 4 instances"), UsageError);
  r.set_storage(tints, std::span<const renderer_scene::Tint>(std::vector<renderer_scene::Tint>(8)));
  // The balls' instances each have entries of their own: a new one would have no hit record.
  CHECK_THROWS_WITH_AS(r.add_instance(s.ball(), up),
                       Contains("geometry \"ball\" has no hit records a new instance could use: every instance has "
                                "entries of its own"),
                       UsageError);
  CHECK_THROWS_WITH_AS(r.add_instance(floor, up, 0x100), Contains("mask 0x100"), UsageError);
  glm::mat4 projective(1.0f);
  projective[0][3] = 1.0f;
  CHECK_THROWS_WITH_AS(r.add_instance(floor, projective), Contains("not (0, 0, 0, 1)"), UsageError);
  r.remove_instance(floor, 1);
  CHECK_THROWS_WITH_AS(r.remove_instance(floor, 1),
                       Contains("Renderer::remove_instance: instance 1 of geometry \"floor\" was removed"), UsageError);
  CHECK_THROWS_WITH_AS(r.remove_instance(floor, 2), Contains("has 2 instance slots, no instance 2"), InvalidGeometryError);
  CHECK(r.instances(floor) == std::vector<std::uint32_t>{0});
}

TEST_CASE("bad input: an empty storage buffer") {
  Built b;
  auto& [t, s, r] = b;
  CHECK_THROWS_WITH_AS(r.set_storage(renderer_scene::tints_slot, std::span<const renderer_scene::Tint>()),
                       Contains("no elements given for set 0 binding 3"), UsageError);
}

TEST_CASE("bad input: rendering before a uniform was given") {
  Built b;
  auto& [t, s, r] = b;
  CHECK_THROWS_WITH_AS(r.render(width, height), Contains("Renderer::render: the uniform at set 0 binding 2 was never given a value"),
                       UsageError);
}

TEST_CASE("bad input: an instance mask over 8 bits") {
  Built b;
  auto& [t, s, r] = b;
  const int mask = 0x100;  // as an int: would have been truncated to 0, and the ball would vanish
  CHECK_THROWS_WITH_AS(r.set_mask(s.ball(), 0, mask),
                       Contains("Renderer::set_mask: mask 0x100 of geometry \"ball\" instance 0 has more than Vulkan's 8"),
                       UsageError);
}

TEST_CASE("bad input: a projective matrix for an instance") {
  Built b(UpdatePolicy::DynamicTransform);
  auto& [t, s, r] = b;
  glm::mat4 m(1.0f);
  m[2][3] = -1.0f;  // a perspective's last row
  CHECK_THROWS_WITH_AS(r.set_transform(s.ball(), 0, m),
                       Contains("Renderer::set_transform: geometry \"ball\" instance 0 matrix has last row (0.000000, "
                                "0.000000, -1.000000, 1.000000), not (0, 0, 0, 1)"),
                       UsageError);
  const std::vector<glm::mat4> both = {glm::mat4(1.0f), m};
  CHECK_THROWS_WITH_AS(r.set_transforms(s.ball(), both), Contains("instance 1 matrix has last row"), UsageError);
}

TEST_CASE("bad input: a NaN instance transform") {
  Built b(UpdatePolicy::DynamicTransform);
  auto& [t, s, r] = b;
  glm::mat4 m(1.0f);
  m[3][0] = std::numeric_limits<float>::quiet_NaN();
  CHECK_THROWS_AS(r.set_transform(s.ball(), 0, m), InvalidGeometryError);
}

TEST_CASE("bad input: moving a geometry added to the scene after the renderer was made") {
  TestContext t;
  RendererScene s(UpdatePolicy::DynamicTransform);
  auto scene = s.table(t.ctx);
  vk::Renderer r(t.ctx, scene, RendererScene::options());
  GeometryDesc later = GeometryDesc::procedural({Aabb{}});
  later.update = UpdatePolicy::DynamicTransform;
  const GeometryId id = scene.add_geometry("later", later);
  CHECK_THROWS_WITH_AS(r.set_transform(id, 0, glm::mat4(1.0f)),
                       Contains("Renderer::set_transform: geometry #2 is not in the compiled scene"), UnknownIdError);
}

TEST_CASE("bad input: a geometry id of another scene given to a renderer") {
  TestContext t;
  RendererScene s(UpdatePolicy::DynamicTransform), other(UpdatePolicy::DynamicTransform);
  vk::Renderer r(t.ctx, s.table(t.ctx), RendererScene::options());
  CHECK_THROWS_WITH_AS(r.set_transform(other.ball(), 0, glm::mat4(1.0f)),
                       Contains("Renderer::set_transform: geometry #1 was issued by scene #"), UnknownIdError);
}

TEST_CASE("bad input: a Static geometry moved") {
  Built b;  // balls Static
  auto& [t, s, r] = b;
  CHECK_THROWS_WITH_AS(r.set_transform(s.ball(), 0, glm::mat4(1.0f)),
                       Contains("Renderer::set_transform: geometry \"ball\" is Static, so its instances were built not "
                                "to move; declare it with update = UpdatePolicy::DynamicTransform"),
                       UsageError);
}

TEST_CASE("bad input: a second raygen") {
  TestContext t;
  RendererScene s;
  auto scene = s.table(t.ctx);
  scene.add_raygen("other.rgen");
  CHECK_THROWS_WITH_AS(vk::Renderer(t.ctx, scene, RendererScene::options()),
                       Contains("Renderer: the scene has 2 raygen entries (first \"scene.rgen\", second \"other.rgen\"); a "
                                "Renderer traces one raygen"),
                       UsageError);
}

TEST_CASE("bad input: a shader file that is not in any shader folder") {
  TestContext t;
  RendererScene s;
  auto scene = s.scene();
  scene.add_raygen("missing.rgen");
  scene.add_hit(scene.ray_id("primary"), scene.hit_group_id("floor"), scene.geometry_id("floor"));
  scene.add_hit(scene.ray_id("primary"), scene.hit_group_id("ball"), s.ball());
  CHECK_THROWS_WITH_AS(vk::Renderer(t.ctx, scene, RendererScene::options()),
                       Contains("Renderer: shader 'missing.rgen' is not in any shader folder"), UsageError);
}

TEST_CASE("bad input: a declared recursion depth below what the shaders nest") {
  TestContext t;
  features_scene::FeaturesScene too_small({.recursion_depth = 1});
  CHECK_THROWS_WITH_AS(vk::Renderer(t.ctx, too_small.table(t.ctx), features_scene::FeaturesScene::options()),
                       Contains("the shaders nest rays 2 deep"), UsageError);
}

TEST_CASE("bad input: shaders nesting deeper than the device allows") {
  // A context capped at depth 1 stands for a device whose limit the shaders' chain exceeds.
  vk::Context limited{{.validation = true, .max_ray_recursion_depth = 1}};
  features_scene::FeaturesScene scene({.recursion_depth = 0});  // derived: 2
  CHECK_THROWS_WITH_AS(vk::Renderer(limited, scene.table(limited), features_scene::FeaturesScene::options()),
                       Contains("Renderer: the shaders nest rays 2 deep (raygen 'scene.rgen' > ray \"primary\" > "
                                "closest_hit 'floor.rchit' > ray \"shadow\"), "),
                       DeviceLimitError);
  CHECK(limited.validation_messages().empty());
}

TEST_CASE("bad input: a declared recursion depth past the device's") {
  TestContext t;
  features_scene::FeaturesScene scene({.recursion_depth = 1000});
  CHECK_THROWS_WITH_AS(vk::Renderer(t.ctx, scene.table(t.ctx), features_scene::FeaturesScene::options()),
                       Contains("the scene's max recursion depth is 1000"), DeviceLimitError);
}

TEST_CASE("bad input: a zero-sized frame") {
  Built b;
  auto& [t, s, r] = b;
  renderer_scene::prepare(r, width, height);
  CHECK_THROWS_WITH_AS(r.render(0, height), Contains("trace: size 0x24 cannot be dispatched on"), UsageError);
}

TEST_CASE("bad input: VK_INSTANCE_LAYERS naming the validation layer the context also enables") {
  // The loader warns that the layer is named twice; that is not a message about our use of Vulkan.
  ScopedEnv env("VK_INSTANCE_LAYERS", "VK_LAYER_KHRONOS_validation");
  vk::Context ctx{{.validation = true}};
  CHECK(ctx.validation_messages().empty());
}

TEST_CASE("bad input: changing the scene under a live renderer changes nothing it draws") {
  // The renderer keeps the Plan it was compiled from (a value) and read the scene's geometry only
  // while it was built: later edits cannot make it read past what it built.
  TestContext t;
  RendererScene s;
  auto scene = s.table(t.ctx);
  vk::Renderer r(t.ctx, scene, RendererScene::options());
  renderer_scene::prepare(r, width, height);
  const vk::Frame before = r.render(width, height);
  scene.add_raygen("other.rgen");
  scene.set_max_recursion_depth(4);
  const GeometryId extra = scene.add_geometry("extra", GeometryDesc::procedural({Aabb{}}));
  scene.add_hit(scene.ray_id("primary"), scene.hit_group_id("ball"), extra);
  const vk::Frame after = r.render(width, height);
  CHECK(after.rgba == before.rgba);
  CHECK(r.plan().records(SbtRegionKind::raygen).size() == 1);
  CHECK(r.plan().instances().size() == 3);
  CHECK_THROWS_AS(r.set_mask(extra, 0, 0xFF), UnknownIdError);  // not in what the renderer built
}
