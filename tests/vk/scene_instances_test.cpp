// vk/scene_instances.hpp: what hiding, showing, masking and moving instances ask of the TLAS, without
// a trace (the pixels are renderer_features_test's).
#include "features_scene.hpp"
#include "renderer_scene.hpp"
#include "test_context.hpp"

#include <algorithm>
#include <deque>

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
  in.blas_rebuilt(plan.geometry(s.ball()).blas, rebuilt);
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
  std::vector<vk::Instance> short_list = instances_of(fixed_plan);
  short_list.pop_back();  // not the plan's list: refused, never read past the plan's instances
  CHECK_THROWS_WITH_AS(vk::SceneInstances(fixed_plan, short_list), doctest::Contains("instances given, the plan has"),
                       UsageError);
}

TEST_CASE("scene instances: adds and removes are TLAS builds that keep every other instance's records and index") {
  TestContext t;
  features_scene::FeaturesScene s;  // each ball its own geometry with geometry-wide entries
  const Plan plan = compile(s.table(t.ctx));
  vk::SceneInstances in(plan, instances_of(plan));
  const auto before = std::vector<vk::Instance>(in.list().begin(), in.list().end());
  const PlannedBlas& ball_blas = plan.blases()[plan.geometry(s.ball(0)).blas];
  REQUIRE(ball_blas.shared_sbt_offset != no_index);
  const vk::AccelerationStructure blas;  // empty: only its address is kept
  const glm::mat4 moved = glm::translate(glm::mat4(1.0f), {0.0f, 0.6f, 2.0f});

  const std::uint32_t added = in.add(s.ball(0), moved, 0x3, blas, "test");
  CHECK(added == 1);
  CHECK(in.take() == vk::TlasWork::build);
  REQUIRE(in.list().size() == before.size() + 1);
  const vk::Instance& fresh = in.list().back();
  CHECK(fresh.blas == &blas);
  CHECK(fresh.sbt_offset == ball_blas.shared_sbt_offset);  // the geometry's shared records
  CHECK(fresh.sbt_offset == before[plan.tlas_index(s.ball(0), 0)].sbt_offset);
  CHECK(fresh.custom_index == before.size());  // one past every custom index so far
  CHECK(fresh.mask == 0x3);
  CHECK(fresh.transform.rows[2][3] == 2.0f);
  for (std::size_t k = 0; k < before.size(); ++k) {  // nothing else moved or changed records
    CHECK(in.list()[k].sbt_offset == before[k].sbt_offset);
    CHECK(in.list()[k].custom_index == before[k].custom_index);
  }
  CHECK(in.instances(s.ball(0), "test") == std::vector<std::uint32_t>{0, 1});
  CHECK(in.tlas_index(s.ball(0), 1, "test") == before.size());
  in.set_visible(s.ball(0), added, false, "test");  // an added instance is like any other
  CHECK(in.list().back().mask == 0);
  CHECK(in.take() == vk::TlasWork::update);

  // Removing the declared instance: the last entry (the added one) takes its place in the list.
  const std::uint32_t k0 = plan.tlas_index(s.ball(0), 0);
  in.remove(s.ball(0), 0, "test");
  CHECK(in.take() == vk::TlasWork::build);
  CHECK(in.list().size() == before.size());
  CHECK(in.tlas_index(s.ball(0), 1, "test") == k0);
  CHECK(in.list()[k0].custom_index == before.size());
  CHECK_FALSE(in.visible(s.ball(0), 1, "test"));  // its state moved with it
  CHECK(in.instances(s.ball(0), "test") == std::vector<std::uint32_t>{1});
  CHECK_THROWS_WITH_AS(in.remove(s.ball(0), 0, "Renderer::remove_instance"),
                       doctest::Contains("Renderer::remove_instance: instance 0 of geometry \"a\" was removed"),
                       UsageError);
  CHECK_THROWS_WITH_AS(in.set_transform(s.ball(0), 0, moved, "Renderer::set_transform"), doctest::Contains("was removed"),
                       UsageError);
  // The next add takes the freed slot 0 with its next generation, and the freed custom index.
  const std::uint32_t reused = in.add(s.ball(0), moved, 0xFF, blas, "test");
  CHECK(reused == (1u << 24 | 0u));
  CHECK(in.list().back().custom_index == before[k0].custom_index);
  CHECK(in.custom_index_bound() == before.size() + 1);  // no per-instance storage grows
  CHECK(in.instances(s.ball(0), "test") == std::vector<std::uint32_t>{reused, 1});
  CHECK(in.tlas_index(s.ball(0), reused, "test") == before.size());
  const vk::AccelerationStructure rebuilt;
  in.blas_rebuilt(plan.geometry(s.ball(0)).blas, rebuilt);  // reaches the added instances too
  CHECK(in.list()[in.tlas_index(s.ball(0), 1, "test")].blas == &rebuilt);
  CHECK(in.list()[in.tlas_index(s.ball(0), reused, "test")].blas == &rebuilt);
}

TEST_CASE("bad input: a removed instance's handle, once its slot holds a new instance, is refused by name") {
  TestContext t;
  features_scene::FeaturesScene s;
  const Plan plan = compile(s.table(t.ctx));
  vk::SceneInstances in(plan, instances_of(plan));
  const vk::AccelerationStructure blas;
  const std::uint32_t first = in.add(s.ball(0), glm::mat4(1.0f), 0xFF, blas, "test");
  in.remove(s.ball(0), first, "test");
  const std::uint32_t second = in.add(s.ball(0), glm::mat4(1.0f), 0xFF, blas, "test");
  REQUIRE((second & 0xFFFFFFu) == (first & 0xFFFFFFu));  // the same slot
  REQUIRE(second != first);
  const std::string words = "Renderer::set_visible: instance " + std::to_string(first) + " of geometry \"a\" was removed "
                            "(remove_instance) and its slot 1 now holds instance " + std::to_string(second);
  CHECK_THROWS_WITH_AS(in.set_visible(s.ball(0), first, false, "Renderer::set_visible"), doctest::Contains(words.c_str()),
                       UsageError);
  CHECK_THROWS_WITH_AS(in.remove(s.ball(0), first, "Renderer::remove_instance"),
                       doctest::Contains("use a handle of a live instance"), UsageError);
  CHECK(in.visible(s.ball(0), second, "test"));  // the new one is untouched
  in.remove(s.ball(0), second, "test");
  CHECK_THROWS_WITH_AS(in.tlas_index(s.ball(0), second, "Renderer::set_transform"),
                       doctest::Contains("its slot 1 now holds nothing"), UsageError);
}

TEST_CASE("scene instances: example 05's add-one-remove-one loop runs 10 million frames in flat memory") {
  TestContext t;
  features_scene::FeaturesScene s;
  const Plan plan = compile(s.table(t.ctx));
  vk::SceneInstances in(plan, instances_of(plan));
  const std::size_t declared = in.list().size(), slots = in.slot_count();
  const vk::AccelerationStructure blas;
  const glm::mat4 at(1.0f);
  std::deque<std::uint32_t> live;  // oldest first, at most four, as example 05 keeps its beads
  std::uint32_t stale = 0;
  bool any_stale = false;
#ifdef __SANITIZE_ADDRESS__
  constexpr std::uint32_t frames = 1'000'000;  // the sanitizer step checks the memory, not the count
#else
  constexpr std::uint32_t frames = 10'000'000;
#endif
  for (std::uint32_t f = 0; f < frames; ++f) {
    live.push_back(in.add(s.ball(0), at, 0xFF, blas, "test"));
    if (live.size() > 4) {
      stale = live.front();
      any_stale = true;
      in.remove(s.ball(0), stale, "test");
      live.pop_front();
    }
    in.take();
    if (f % 1'000'003 == 0 && any_stale) {  // now and then: the handle just removed stays refused
      CHECK_THROWS_AS(in.set_visible(s.ball(0), stale, false, "test"), UsageError);
    }
  }
  CHECK(in.list().size() == declared + 4);
  CHECK(in.slot_count() <= slots + 5);             // no slot per add
  CHECK(in.custom_index_bound() <= declared + 5);  // nor a custom index
  std::vector<std::uint32_t> handles = in.instances(s.ball(0), "test");
  handles.erase(handles.begin());  // the declared instance
  CHECK(std::is_permutation(handles.begin(), handles.end(), live.begin(), live.end()));
  for (std::uint32_t h : live) CHECK(in.visible(s.ball(0), h, "test"));
}

