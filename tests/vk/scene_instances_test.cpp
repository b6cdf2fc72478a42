// vk/scene_instances.hpp: what hiding, showing, masking and moving instances ask of the TLAS, without
// a trace (the pixels are renderer_features_test's).
#include "renderer_scene.hpp"
#include "test_context.hpp"

using namespace proceduray;
using renderer_scene::RendererScene;

namespace {

/// The plan's instances as SceneAcceleration lists them, pointing at no BLAS (none is read here).
std::vector<vk::Instance> instances_of(const Plan& plan) {
  std::vector<vk::Instance> list;
  const auto planned = plan.instances();
  for (std::uint32_t k = 0; k < planned.size(); ++k) {
    list.push_back({.blas = nullptr, .transform = planned[k].transform, .custom_index = k,
                    .sbt_offset = planned[k].sbt_offset, .mask = planned[k].mask});
  }
  return list;
}

}  // namespace

TEST_CASE("scene instances: hiding and showing is a TLAS update, and a mask set meanwhile waits") {
  TestContext t;
  RendererScene s;  // Static balls: visibility needs no motion
  const Plan plan = compile(s.table(t.ctx));
  vk::SceneInstances in(plan, instances_of(plan));
  const std::uint32_t k = plan.tlas_index(s.ball(), 1);
  const std::uint32_t other = plan.tlas_index(s.ball(), 0);
  const std::uint8_t mask = in.list()[k].mask;
  REQUIRE(mask != 0);
  CHECK(in.take() == vk::TlasWork::none);
  CHECK(in.visible(s.ball(), 1, "test"));

  in.set_visible(s.ball(), 1, false, "test");
  CHECK_FALSE(in.visible(s.ball(), 1, "test"));
  CHECK(in.list()[k].mask == 0);  // no ray's cull mask meets it
  CHECK(in.list()[other].mask == mask);
  CHECK(in.take() == vk::TlasWork::update);
  CHECK(in.take() == vk::TlasWork::none);  // taken
  in.set_visible(s.ball(), 1, false, "test");  // already hidden: nothing to do
  CHECK(in.take() == vk::TlasWork::none);

  in.set_mask(s.ball(), 1, 0x3, "test");  // while hidden: kept for later, no work
  CHECK(in.list()[k].mask == 0);
  CHECK(in.take() == vk::TlasWork::none);
  in.set_visible(s.ball(), 1, true, "test");
  CHECK(in.list()[k].mask == 0x3);
  CHECK(in.take() == vk::TlasWork::update);

  in.set_mask(s.ball(), 1, 0x5, "test");  // shown: a mask change builds the TLAS
  CHECK(in.list()[k].mask == 0x5);
  CHECK(in.take() == vk::TlasWork::build);
}

TEST_CASE("scene instances: BLAS changes and moves ask for the TLAS work they need, and bad input names the call") {
  TestContext t;
  RendererScene s(UpdatePolicy::DynamicTransform);
  const Plan plan = compile(s.table(t.ctx));
  vk::SceneInstances in(plan, instances_of(plan));
  in.set_transform(s.ball(), 0, glm::translate(glm::mat4(1.0f), {0.0f, 2.0f, 0.0f}), "test");
  CHECK(in.list()[plan.tlas_index(s.ball(), 0)].transform.rows[1][3] == 2.0f);
  CHECK(in.take() == vk::TlasWork::update);
  in.blas_refit();
  in.set_visible(s.ball(), 0, false, "test");
  const vk::AccelerationStructure rebuilt;  // empty: only its address is kept
  const PlannedBlas& ball_blas = plan.blases()[plan.geometry(s.ball()).blas];
  in.blas_rebuilt(ball_blas, rebuilt);
  CHECK(in.take() == vk::TlasWork::build);  // a build covers the update
  for (std::uint32_t i = 0; i < ball_blas.instance_count; ++i) {
    CHECK(in.list()[ball_blas.first_instance + i].blas == &rebuilt);
  }
  CHECK_THROWS_WITH_AS(in.set_visible(s.ball(), 2, false, "Renderer::set_visible"),
                       doctest::Contains("Renderer::set_visible"), SceneError);
  CHECK_THROWS_WITH_AS(in.visible(s.ball(), 7, "Renderer::visible"), doctest::Contains("no instance 7"), SceneError);
  RendererScene fixed;  // Static: moving is refused, hiding is not
  const Plan fixed_plan = compile(fixed.table(t.ctx));
  vk::SceneInstances still(fixed_plan, instances_of(fixed_plan));
  CHECK_THROWS_WITH_AS(still.set_transform(fixed.ball(), 0, glm::mat4(1.0f), "Renderer::set_transform"),
                       doctest::Contains("is Static"), UsageError);
  still.set_visible(fixed.ball(), 0, false, "Renderer::set_visible");
  CHECK(still.take() == vk::TlasWork::update);
}
