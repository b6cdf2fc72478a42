// vk/scene_acceleration.hpp, vk/bindings.hpp and vk/scene_pipeline.hpp used alone, without the
// Renderer: the parts compose into the same frame, recorded into a command buffer the test owns.
#include "frame_pixels.hpp"
#include "renderer_scene.hpp"
#include "test_context.hpp"

using namespace proceduray;
using renderer_scene::RendererScene;

namespace {
constexpr std::uint32_t width = 64;
constexpr std::uint32_t height = 48;
glm::ivec2 where(glm::vec3 p) { return project(renderer_scene::constants(width, height).camera, p, width, height); }
}  // namespace

TEST_CASE("scene parts alone trace the renderer's frame into the caller's command buffer") {
  TestContext t;
  RendererScene s(UpdatePolicy::DynamicTransform);
  const auto& scene = s.table(t.ctx);
  Plan plan = compile(scene);
  const vk::RendererOptions options{.shader_dirs = RendererScene::options().shader_dirs};
  vk::SceneStages stages = vk::compile_scene_stages(plan, options);
  plan.settle_recursion(stages.traces, t.ctx.limits());
  vk::SceneAcceleration structures(t.ctx, plan);
  vk::Bindings bindings(t.ctx, plan.global_signature(), structures.tlas().structure());
  const auto pipeline =
      vk::make_scene_pipeline(t.ctx, plan, std::move(stages), bindings.layouts(), bindings.push_size(), options);
  const vk::SbtBuffer sbt(t.ctx, *pipeline, plan, plan.layout(t.ctx.limits()));
  const vk::StorageImage image(t.ctx, width, height);
  bindings.bind_image(image.view());
  CHECK_THROWS_WITH_AS(bindings.check_ready("test"), doctest::Contains("test: the uniform at set 0 binding 2 was never given"),
                       UsageError);
  bindings.set(renderer_scene::constants_slot, renderer_scene::constants(width, height));
  // One tint per TLAS instance: the shaders index them by gl_InstanceCustomIndexEXT.
  const std::vector<renderer_scene::Tint> white(plan.instances().size(), {glm::vec4(1.0f)});
  bindings.set_storage(renderer_scene::tints_slot, std::span<const renderer_scene::Tint>(white));
  bindings.check_ready("test");

  // Move ball 0 onto ball 1's left: the first record() refits the TLAS before the trace.
  const glm::vec3 moved{-0.2f, 1.2f, 0.0f};
  structures.set_transform(s.ball(), 0, glm::translate(glm::mat4(1.0f), moved));
  vk::FrameWork work;
  t.ctx.submit([&](VkCommandBuffer cmd) {
    work = structures.record(cmd);
    bindings.upload();
    const auto sets = bindings.sets();
    vk::record_trace(t.ctx, cmd, *pipeline, sets, sbt, width, height, bindings.push());
  });
  CHECK(work == vk::FrameWork{.tlas_updates = 1});
  const std::vector<std::uint8_t> rgba = image.read();
  const vk::Frame f{width, height, rgba};
  CHECK(frame_pixels::near(frame_pixels::rgba(f, where(moved)), frame_pixels::bytes(renderer_scene::ball_colours[0]), 1));
  CHECK(frame_pixels::near(frame_pixels::rgba(f, where(renderer_scene::ball_centres[1])),
                           frame_pixels::bytes(renderer_scene::ball_colours[1]), 1));
  // Nothing changed since: the next record() does no structure work.
  t.ctx.submit([&](VkCommandBuffer cmd) { work = structures.record(cmd); });
  CHECK(work == vk::FrameWork{});
  // The same frame through the Renderer, recorded into the caller's command buffer too.
  vk::Renderer renderer(t.ctx, scene, RendererScene::options());
  renderer_scene::prepare(renderer, width, height);
  renderer.set_transform(s.ball(), 0, glm::translate(glm::mat4(1.0f), moved));
  t.ctx.submit([&](VkCommandBuffer cmd) { work = renderer.record(cmd, width, height); });
  CHECK(work == vk::FrameWork{.tlas_updates = 1});
  CHECK(renderer.image().read() == rgba);
}

TEST_CASE("scene parts name the call the user made in their errors") {
  TestContext t;
  RendererScene s;
  const auto& scene = s.table(t.ctx);
  const Plan plan = compile(scene);
  vk::SceneAcceleration structures(t.ctx, plan);
  CHECK_THROWS_WITH_AS(structures.set_transform(s.ball(), 0, glm::mat4(1.0f)),
                       doctest::Contains("SceneAcceleration::set_transform: geometry \"ball\""), UsageError);
  CHECK_THROWS_WITH_AS(structures.set_mask(s.ball(), 9, 1), doctest::Contains("no instance 9"), InvalidGeometryError);
  vk::Renderer renderer(t.ctx, scene, RendererScene::options());
  CHECK_THROWS_WITH_AS(renderer.image(), doctest::Contains("Renderer::image: no frame was traced yet"), UsageError);
}
