// Tests for proceduray/scene/object.hpp: one call registers what the hand-written scene registers
// (hit groups per ray, the geometry, the entries), and a bad object changes nothing.
#include "proceduray/scene/object.hpp"

#include "proceduray/scene/compile.hpp"

#include "scene_fixtures.hpp"

#include <doctest/doctest.h>

#include <cstring>
#include <string>
#include <vector>

using namespace proceduray;

namespace object_test {

struct Payload { glm::vec4 colour; };
struct Occlusion { std::uint32_t occluded; };
struct Hit { glm::vec3 normal; float steps; };
struct Material { glm::vec3 albedo; std::uint32_t id; };
PROCEDURAY_STRUCT(Payload, scalar, colour);
PROCEDURAY_STRUCT(Occlusion, scalar, occluded);
PROCEDURAY_STRUCT(Hit, scalar, normal, steps);
PROCEDURAY_STRUCT(Material, scalar, albedo, id);
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<Payload, Occlusion>, proceduray::RootComponent<>, proceduray::RootArguments<Material>,
                                   proceduray::Attributes<Hit>>;
using TestScene = proceduray::Scene<TestSceneInterface>;

/// Two rays and a material signature, as every test here starts.
struct Rays {
  TestScene scene;
  RayId<Payload> radiance = scene.add_ray<Payload>("radiance", {.miss = "radiance.rmiss"});
  RayId<Occlusion> shadow = scene.add_ray<Occlusion>("shadow", {.miss = "shadow.rmiss"});
  LocalSignatureId<Material> material = scene.add_local_signature<Material>("material");
  Rays() { scene.add_raygen("raygen.rgen"); }
};

/// A one-triangle floor.
TriangleMesh triangle() { return {{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, {0, 2, 1}}; }

std::vector<InstanceTransform> at_x(std::initializer_list<float> xs) {
  std::vector<InstanceTransform> out;
  for (float x : xs) out.push_back(instance_transform(glm::translate(glm::mat4(1.0f), {x, 0.0f, 0.0f})));
  return out;
}

ObjectDesc spheres_desc(const Rays& r) {
  return {.geometry = GeometryDesc::procedural({Aabb{}}, at_x({-2.0f, 2.0f})), .intersection = "sphere.rint",
          .closest_hit = {{r.radiance, "shade.rchit"}}};
}

/// What a hit record holds, by name: group, ray, geometry, instance and material id.
std::vector<std::string> describe(const TestScene& s, const Plan& sbt) {
  std::vector<std::string> out;
  for (const SbtRecord& rec : sbt.records(SbtRegionKind::hit)) {
    Material m{};
    const auto data = sbt.root_arguments(rec);
    if (data.size() == sizeof(Material)) std::memcpy(&m, data.data(), sizeof m);
    out.push_back(sbt.pipeline().groups[rec.group].name + " " + s.rays().name(rec.ray) + " " +
                  s.geometries().name(rec.geometry) + " " +
                  (rec.instance == no_index ? std::string("*") : std::to_string(rec.instance)) + " " +
                  (data.empty() ? std::string("-") : std::to_string(m.id)));
  }
  return out;
}

}  // namespace object_test

using namespace object_test;

TEST_CASE("add_object registers what the hand-written hit groups geometry and entries register") {
  const Material red{{1, 0, 0}, 1}, blue{{0, 0, 1}, 2}, grey{{0.5f, 0.5f, 0.5f}, 3};
  Rays by_hand;
  by_hand.scene.add_hit_group<Hit>("spheres", {.kind = HitGroupKind::procedural, .closest_hit = "shade.rchit",
                                               .intersection = "sphere.rint"});
  by_hand.scene.add_hit_group<Hit>("spheres_shadow", {.kind = HitGroupKind::procedural, .intersection = "sphere.rint"});
  const GeometryId hs = by_hand.scene.add_geometry("spheres", spheres_desc(by_hand).geometry);
  by_hand.scene.add_hit_group("floor", {.kind = HitGroupKind::triangles, .closest_hit = "floor.rchit"});
  by_hand.scene.add_hit_group("floor_shadow", {.kind = HitGroupKind::triangles});
  const GeometryId hf = by_hand.scene.add_geometry("floor", GeometryDesc::triangles(triangle()));
  const HitGroupId spheres = by_hand.scene.hit_group_id("spheres");
  const HitGroupId spheres_shadow = by_hand.scene.hit_group_id("spheres_shadow");
  for (std::uint32_t i = 0; i < 2; ++i) {
    by_hand.scene.add_hit(by_hand.radiance, spheres, by_hand.material, i ? blue : red, hs, i);
    by_hand.scene.add_hit(by_hand.shadow, spheres_shadow, by_hand.material, i ? blue : red, hs, i);
  }
  by_hand.scene.add_hit(by_hand.radiance, by_hand.scene.hit_group_id("floor"), by_hand.material, grey, hf);
  by_hand.scene.add_hit(by_hand.shadow, by_hand.scene.hit_group_id("floor_shadow"), by_hand.material, grey, hf);

  Rays objects;
  const GeometryId os = add_object<Hit>(objects.scene, "spheres", spheres_desc(objects), objects.material,
                                        {red, blue});
  const GeometryId of = add_object(objects.scene, "floor",
                                   {.geometry = GeometryDesc::triangles(triangle()),
                                    .closest_hit = {{objects.radiance, "floor.rchit"}}},
                                   objects.material, {grey});
  CHECK(os == hs);
  CHECK(of == hf);
  REQUIRE(objects.scene.hit_groups().size() == 4);
  CHECK(objects.scene.hit_group("spheres_shadow").desc.closest_hit.empty());
  CHECK(objects.scene.hit_group("spheres_shadow").desc.intersection == "sphere.rint");
  CHECK(objects.scene.hit_group("spheres").attribute_size == sizeof(Hit));
  CHECK(objects.scene.hit_group("floor").desc.kind == HitGroupKind::triangles);
  const Plan a = compile(by_hand.scene);
  const Plan b = compile(objects.scene);
  const std::vector<std::string> records = describe(objects.scene, b);
  CHECK(records == describe(by_hand.scene, a));
  CHECK(records == std::vector<std::string>{"spheres radiance spheres 0 1", "spheres_shadow shadow spheres 0 1",
                                            "spheres radiance spheres 1 2", "spheres_shadow shadow spheres 1 2",
                                            "floor radiance floor * 3", "floor_shadow shadow floor * 3"});
}

TEST_CASE("add_object with one record binds it to every instance and without one binds no data") {
  Rays r;
  add_object<Hit>(r.scene, "spheres", spheres_desc(r), r.material, {Material{{}, 7}});
  add_object<Hit>(r.scene, "bare",
                  {.geometry = GeometryDesc::procedural({Aabb{}}), .intersection = "bare.rint"});
  const Plan sbt = compile(r.scene);
  CHECK(describe(r.scene, sbt) == std::vector<std::string>{"spheres radiance spheres * 7",
                                                           "spheres_shadow shadow spheres * 7", "bare radiance bare * -",
                                                           "bare_shadow shadow bare * -"});
  CHECK(r.scene.hit_group("bare").desc.closest_hit.empty());
}

TEST_CASE("add_object any-hit shaders go to the listed ray only") {
  Rays r;
  add_object(r.scene, "leaves", {.geometry = GeometryDesc::triangles(triangle()),
                                          .any_hit = {{r.shadow, "alpha.rahit"}}});
  CHECK(r.scene.hit_group("leaves").desc.any_hit.empty());
  CHECK(r.scene.hit_group("leaves_shadow").desc.any_hit == "alpha.rahit");
}

TEST_CASE("add_object rejects a bad object before changing the scene or its entries") {
  Rays r;
  add_object<Hit>(r.scene, "spheres", spheres_desc(r), r.material, {Material{}});
  const auto groups = r.scene.hit_groups().size();
  const auto geometries = r.scene.geometries().size();
  const auto entries = r.scene.entries().all().size();
  auto unchanged = [&] {
    CHECK(r.scene.hit_groups().size() == groups);
    CHECK(r.scene.geometries().size() == geometries);
    CHECK(r.scene.entries().all().size() == entries);
  };
  const Material m{};
  // Three records for two instances.
  CHECK_THROWS_WITH_AS(add_object<Hit>(r.scene, "other", spheres_desc(r), r.material, {m, m, m}),
                       doctest::Contains("object \"other\" has 3 records for 2 instances"), SceneError);
  unchanged();
  // The id is taken.
  CHECK_THROWS_WITH_AS(add_object<Hit>(r.scene, "spheres", spheres_desc(r), r.material, {m}),
                       doctest::Contains("geometry \"spheres\" already exists"), DuplicateIdError);
  unchanged();
  // Attributes on triangles.
  const ObjectDesc floor{.geometry = GeometryDesc::triangles(triangle())};
  CHECK_THROWS_WITH_AS(add_object<Hit>(r.scene, "floor", floor, r.material, {m}),
                       doctest::Contains("call add_object<void>"), HitGroupKindError);
  unchanged();
  // Boxes without an attribute type: the shaders would read an undeclared `hit`.
  CHECK_THROWS_WITH_AS(add_object(r.scene, "bare", spheres_desc(r), r.material, {m}),
                       doctest::Contains("object \"bare\" is procedural (AABBs) but declares no attribute type"),
                       HitGroupKindError);
  CHECK_THROWS_WITH_AS(add_object(r.scene, "bare", spheres_desc(r), r.material, {m}),
                       doctest::Contains("call add_object<YourAttributes>(...)"), HitGroupKindError);
  unchanged();
  // An intersection shader on triangles.
  ObjectDesc clipped = floor;
  clipped.intersection = "clip.rint";
  CHECK_THROWS_AS(add_object(r.scene, "floor", clipped, r.material, {m}), HitGroupKindError);
  unchanged();
  // A ray listed twice.
  ObjectDesc twice = spheres_desc(r);
  twice.closest_hit.push_back({r.radiance, "other.rchit"});
  CHECK_THROWS_WITH_AS(add_object<Hit>(r.scene, "twice", twice, r.material, {m}),
                       doctest::Contains("lists ray \"radiance\" twice in closest_hit"), DuplicateIdError);
  unchanged();
  // A ray of no scene.
  ObjectDesc stray = spheres_desc(r);
  stray.closest_hit = {{RayId<>(5), "x.rchit"}};
  CHECK_THROWS_AS(add_object<Hit>(r.scene, "stray", stray, r.material, {m}), UnknownIdError);
  unchanged();
  // A signature and no record.
  CHECK_THROWS_WITH_AS(add_object<Hit>(r.scene, "empty", spheres_desc(r), r.material, {}),
                       doctest::Contains("has a local signature but no record"), SceneError);
  unchanged();
  // Bad geometry: named by the object's id.
  ObjectDesc nothing = spheres_desc(r);
  nothing.geometry.aabbs.clear();
  CHECK_THROWS_WITH_AS(add_object<Hit>(r.scene, "nothing", nothing, r.material, {m}),
                       doctest::Contains("geometry \"nothing\" is procedural with no AABB"), InvalidGeometryError);
  unchanged();
  // A signature of no scene.
  CHECK_THROWS_WITH_AS(add_object<Hit>(r.scene, "lost", spheres_desc(r), LocalSignatureId<Material>(9), {m}),
                       doctest::Contains("add_object: object \"lost\" signature"), UnknownIdError);
  unchanged();
}

TEST_CASE("add_object needs the rays first") {
  TestScene scene;
  const ObjectDesc early{.geometry = GeometryDesc::procedural({Aabb{}}), .intersection = "x.rint"};
  CHECK_THROWS_WITH_AS(add_object(scene, "early", early), doctest::Contains("register the rays first"), SceneError);
  CHECK(scene.geometries().size() == 0);
}
