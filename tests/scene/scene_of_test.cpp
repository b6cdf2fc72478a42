// Tests for proceduray/scene/scene_of.hpp: a scene typed by the user's variant categories.
// (Types outside their category do not compile: compile_fail/scene_of_*.cpp.)
#include <proceduray/scene/compile.hpp>
#include <proceduray/scene/object.hpp>
#include <proceduray/scene/scene_of.hpp>
#include <proceduray/shader/field_list.hpp>

#include <doctest/doctest.h>

namespace scene_of_test {
struct Radiance {
  glm::vec4 colour;
};
PROCEDURAY_STRUCT(Radiance, scalar, colour);
struct Big {  // a payload alternative no ray of the scene below uses
  glm::vec4 a, b, c, d;
};
PROCEDURAY_STRUCT(Big, scalar, a, b, c, d);
struct Material {
  glm::vec4 albedo;
};
PROCEDURAY_STRUCT(Material, scalar, albedo);
struct Huge {  // root arguments no entry uses
  glm::mat4 m[4];
};
PROCEDURAY_STRUCT(Huge, scalar, m);
struct Hit {
  glm::vec3 normal;
};
PROCEDURAY_STRUCT(Hit, scalar, normal);
struct Wide {  // attributes of a hit group no record uses
  glm::vec4 a, b;
};
PROCEDURAY_STRUCT(Wide, scalar, a, b);
using Interface = proceduray::ShaderInterface<proceduray::Payload<Radiance, Big>, proceduray::RootComponent<>,
                                              proceduray::RootArguments<Material, Huge>,
                                              proceduray::Attributes<Hit, Wide>>;
}  // namespace scene_of_test

using namespace scene_of_test;

// What the interface lists: the largest alternatives, which the scene below does not use.
static_assert(Interface::max_payload_size == sizeof(Big) && Interface::max_root_arguments_size == sizeof(Huge) &&
              Interface::max_attribute_size == sizeof(Wide));
namespace pr = proceduray;

TEST_CASE("SceneOf registers each category's alternatives and compiles as a Scene") {
  pr::SceneOf<Interface> scene;
  const auto radiance = scene.add_ray<Radiance>("radiance", {.miss = "sky.rmiss"});
  const auto material = scene.add_local_signature<Material>("material");
  // The report's style: the alternative a RootArguments value holds is the record type.
  const pr::LocalSignatureId<> huge = scene.add_local_signature("huge", Interface::RootArgumentsSet(Huge{}));
  CHECK(scene.local_signature(huge).arguments_size == sizeof(Huge));
  CHECK(scene.local_signature(huge).arguments_type == typeid(Huge));
  CHECK(scene.local_signature_id<Huge>("huge") == pr::LocalSignatureId<Huge>(huge.index()));
  scene.add_hit_group<Wide>("unused", {.kind = pr::HitGroupKind::procedural, .intersection = "wide.rint"});
  scene.add_raygen("camera.rgen");
  pr::add_object<Hit>(scene, "ball", {.geometry = pr::GeometryDesc::procedural({pr::Aabb{}}), .intersection = "ball.rint",
                                      .closest_hit = {{radiance, "ball.rchit"}}},
                      material, {Material{glm::vec4(1.0f)}});
  const pr::Plan plan = pr::compile(scene);
  // The maxima come from what the records use, not from every alternative listed (static_assert above).
  CHECK(plan.pipeline().max_payload_size == sizeof(Radiance));
  CHECK(plan.pipeline().max_root_arguments_size[2] == sizeof(Material));
  CHECK(plan.pipeline().max_attribute_size == sizeof(Hit));
  // Unused entities are not planned.
  for (const pr::PlannedGroup& g : plan.pipeline().groups) CHECK(g.name != "unused");
}

TEST_CASE("SceneOf keeps the Scene's run-time checks") {
  pr::SceneOf<Interface> scene;
  scene.add_ray<Radiance>("radiance", {.miss = "sky.rmiss"});
  CHECK_THROWS_AS(scene.add_ray<Radiance>("radiance", {.miss = "sky.rmiss"}), pr::DuplicateIdError);
  CHECK_THROWS_WITH_AS(scene.add_local_signature("", Interface::RootArgumentsSet(Material{})),
                       doctest::Contains("empty local signature id"), pr::SceneError);
}
