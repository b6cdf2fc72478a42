// Tests for proceduray/scene/scene_tables.hpp: the scene, its table and its build live together.
#include "proceduray/scene/scene_tables.hpp"

#include "proceduray/scene/default_global_signature.hpp"
#include "scene_fixtures.hpp"

#include <doctest/doctest.h>

#include <type_traits>

using namespace proceduray;

namespace scene_tables_test {

struct Payload { glm::vec4 colour; };
struct Hit { glm::vec3 normal; float t; };
struct Tint { glm::vec3 rgb; float alpha; };
PROCEDURAY_STRUCT(Payload, scalar, colour);
PROCEDURAY_STRUCT(Hit, scalar, normal, t);
PROCEDURAY_STRUCT(Tint, scalar, rgb, alpha);

/// A one-ray, one-object scene written as the examples write theirs.
struct Spheres : SceneTables {
  Spheres() {
    const auto radiance = scene.add_ray<Payload>("radiance", {.miss = "miss.rmiss"});
    const auto tint = scene.add_local_signature<Tint>("tint");
    set_global_signature(default_global_signature());
    table.add_raygen("raygen.rgen");
    add_object<Hit>("sphere", {.geometry = GeometryDesc::procedural({Aabb{}}), .intersection = "sphere.rint",
                               .closest_hit = {{radiance, "sphere.rchit"}}}, tint, {Tint{{1, 0, 0}, 1}});
  }
};

}  // namespace scene_tables_test

using namespace scene_tables_test;

TEST_CASE("scene tables can be neither copied nor moved") {
  // The table points at the scene and the build at both: they must stay where they are.
  static_assert(!std::is_copy_constructible_v<SceneTables> && !std::is_move_constructible_v<SceneTables>);
  static_assert(!std::is_copy_assignable_v<SceneTables> && !std::is_move_assignable_v<SceneTables>);
  static_assert(!std::is_move_constructible_v<Spheres>);
  Spheres s;
  CHECK(&s.table.scene() == &s.scene);
}

TEST_CASE("scene tables build their table and keep it") {
  Spheres s;
  CHECK_FALSE(s.built());
  CHECK_THROWS_WITH_AS(s.sbt(), doctest::Contains("call build(limits) first"), SceneError);
  const ShaderBindingTable& sbt = s.build(test::lavapipe_limits);
  CHECK(s.built());
  CHECK(&s.sbt() == &sbt);
  CHECK(sbt.records(SbtRegionKind::hit).size() == 1);
  CHECK(sbt.plan().global_signature == s.scene.global_signature_id("global"));
  CHECK(sbt.plan().max_record_data_size[2] == sizeof(Tint));
}

TEST_CASE("scene tables keep the previous build when a rebuild throws") {
  Spheres s;
  const ShaderBindingTable& first = s.build(test::lavapipe_limits);
  const auto records = first.records(SbtRegionKind::hit).size();
  s.table.set_max_recursion_depth(5);
  DeviceLimits shallow = test::lavapipe_limits;
  shallow.max_ray_recursion_depth = 2;
  CHECK_THROWS_AS(s.build(shallow), DeviceLimitError);
  REQUIRE(s.built());
  CHECK(s.sbt().records(SbtRegionKind::hit).size() == records);
  CHECK(s.sbt().plan().max_recursion_depth == 1);
}

TEST_CASE("scene tables set the global signature once") {
  Spheres s;
  CHECK_THROWS_AS(s.set_global_signature(default_global_signature()), DuplicateIdError);
  const GlobalSignatureId other = s.set_global_signature(default_global_signature(), "other");
  CHECK(other == s.scene.global_signature_id("other"));
  CHECK(s.build(test::lavapipe_limits).plan().global_signature == s.scene.global_signature_id("other"));
}
