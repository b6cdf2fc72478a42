// Tests for proceduray/scene/scene.hpp (and entities.hpp): entities by id, and the entries that bind them.
#include "proceduray/scene/scene.hpp"

#include <doctest/doctest.h>

#include "proceduray/scene/compile.hpp"
#include "proceduray/scene/default_global_signature.hpp"
#include "proceduray/scene/object.hpp"
#include "proceduray/shader/field_list.hpp"
#include "scene_fixtures.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>
#include <string>

using namespace proceduray;

namespace {
struct TestPayload { float value; };
struct OtherPayload { std::uint32_t hit; };
struct Arguments { std::uint32_t index; };
struct TestAttributes { float normal[3]; };
PROCEDURAY_STRUCT(TestPayload, scalar, value);
PROCEDURAY_STRUCT(OtherPayload, scalar, hit);
PROCEDURAY_STRUCT(Arguments, scalar, index);
PROCEDURAY_STRUCT(TestAttributes, scalar, normal);
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<TestPayload, OtherPayload>, proceduray::RootComponent<>, proceduray::RootArguments<Arguments>,
                                   proceduray::Attributes<TestAttributes>>;
using TestScene = proceduray::Scene<TestSceneInterface>;
TriangleMesh triangle() { return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}}; }
}  // namespace

TEST_CASE("scene entities register by id and return typed ids") {
  TestScene s;
  const RayId<TestPayload> radiance = s.add_ray<TestPayload>("Radiance", {.miss = "miss"});
  const RayId<OtherPayload> shadow = s.add_ray<OtherPayload>("Shadow", {.miss = "miss_shadow"});
  const HitGroupId tri = s.add_hit_group("Triangle", {.closest_hit = "chit"});
  const HitGroupId proc = s.add_hit_group<TestAttributes>("Proc", {.kind = HitGroupKind::procedural, .intersection = "isect"});
  const GeometryId plane = s.add_geometry("Plane", GeometryDesc::triangles(triangle()));
  const GlobalSignatureId global = s.add_global_signature("Global", {.bindings = {{.kind = BindingKind::acceleration_structure}}});
  const LocalSignatureId<Arguments> local = s.add_local_signature<Arguments>("Local");
  CHECK(radiance.index() == 0);
  CHECK(shadow.index() == 1);
  CHECK(s.ray_id<TestPayload>("Radiance") == radiance);
  CHECK(s.ray_id("Shadow") == RayId<>(shadow));
  CHECK(s.hit_group_id("Proc") == proc);
  CHECK(s.geometry_id("Plane") == plane);
  CHECK(s.global_signature_id("Global") == global);
  CHECK(s.local_signature_id<Arguments>("Local") == local);
  CHECK(s.ray(radiance).payload_size == sizeof(TestPayload));
  CHECK(s.ray("Shadow").desc.miss == "miss_shadow");
  CHECK(s.hit_group(tri).attribute_size == triangle_attribute_size);
  CHECK(s.hit_group(proc).attribute_size == sizeof(TestAttributes));
  CHECK(s.local_signature(local).arguments_size == sizeof(Arguments));
  CHECK(s.global_signature(global).desc.bindings.size() == 1);
  CHECK(s.geometry(plane).desc.kind == GeometryKind::triangles);
}

TEST_CASE("scene find returns a pointer or nullptr") {
  TestScene s;
  s.add_ray<TestPayload>("Radiance", {.miss = "miss"});
  s.add_hit_group("Triangle", {});
  s.add_geometry("Plane", GeometryDesc::triangles(triangle()));
  s.add_local_signature<Arguments>("Local");
  s.add_global_signature("Global", {});
  REQUIRE(s.find_ray("Radiance") != nullptr);
  CHECK(s.find_ray("Radiance")->desc.miss == "miss");
  CHECK(s.find_ray("radiance") == nullptr);
  CHECK(s.find_hit_group("Triangle") != nullptr);
  CHECK(s.find_hit_group("Nope") == nullptr);
  CHECK(s.find_geometry("Plane") != nullptr);
  CHECK(s.find_geometry("plane") == nullptr);
  CHECK(s.find_local_signature("Local") != nullptr);
  CHECK(s.find_global_signature("Global") != nullptr);
  CHECK(s.find_global_signature("Local") == nullptr);
}

TEST_CASE("scene duplicate ids throw naming the id") {
  TestScene s;
  s.add_ray<TestPayload>("Radiance", {.miss = "miss"});
  CHECK_THROWS_WITH_AS(s.add_ray<TestPayload>("Radiance", {.miss = "other"}),
                       doctest::Contains("Scene::add_ray: duplicate ray id \"Radiance\""), DuplicateIdError);
  s.add_geometry("Plane", GeometryDesc::triangles(triangle()));
  CHECK_THROWS_WITH_AS(s.add_geometry("Plane", GeometryDesc::triangles(triangle())),
                       doctest::Contains("duplicate geometry id \"Plane\""), DuplicateIdError);
  CHECK(s.blases().size() == 1);  // the failed add left no BLAS behind
  s.add_local_signature<Arguments>("Local");
  CHECK_THROWS_AS(s.add_local_signature<Arguments>("Local"), DuplicateIdError);
  s.add_hit_group("G", {});
  CHECK_THROWS_WITH_AS(s.add_hit_group("G", {}), doctest::Contains("choose a unique id"), DuplicateIdError);
}

TEST_CASE("scene unknown ids name the nearest known ids") {
  TestScene s;
  for (const char* name : {"Pacman", "Pacman_Shadow", "Mandelbulb", "Julia"}) {
    s.add_hit_group<TestAttributes>(name, {.kind = HitGroupKind::procedural, .intersection = "isect"});
  }
  CHECK_THROWS_WITH_AS(s.hit_group_id("Pacmn"),
                       doctest::Contains("Scene::hit_group_id: unknown hit group id \"Pacmn\"; nearest known ids: \"Pacman\", \"Julia\""),
                       UnknownIdError);
  CHECK_THROWS_WITH_AS(s.hit_group("Mandelbrot"), doctest::Contains("nearest known ids: \"Mandelbulb\""), UnknownIdError);
  CHECK_THROWS_WITH_AS(s.ray_id("Radiance"), doctest::Contains("unknown ray id \"Radiance\"; nearest known ids: (none)"),
                       UnknownIdError);
  CHECK_THROWS_WITH_AS(s.geometry(GeometryId(7)), doctest::Contains("geometry #7 is not registered"), UnknownIdError);
  CHECK_THROWS_WITH_AS(s.geometry(GeometryId()), doctest::Contains("a default-constructed geometry id names no geometry"), UnknownIdError);
}

TEST_CASE("scene typed lookups check the registered type") {
  TestScene s;
  s.add_ray<TestPayload>("Radiance", {.miss = "miss"});
  s.add_local_signature<Arguments>("Local");
  CHECK_NOTHROW(s.ray_id<TestPayload>("Radiance"));
  CHECK_THROWS_WITH_AS(s.ray_id<OtherPayload>("Radiance"), doctest::Contains("ray \"Radiance\" has payload type"),
                       TypeMismatchError);
  CHECK_THROWS_WITH_AS(s.local_signature_id<TestPayload>("Local"), doctest::Contains("ask for the type it was registered with"),
                       TypeMismatchError);
}

TEST_CASE("scene hit group kinds are checked when registered") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_hit_group("Tri", {.closest_hit = "c", .intersection = "isect"}),
                       doctest::Contains("triangle hit group \"Tri\" has intersection shader \"isect\""), HitGroupKindError);
  CHECK_THROWS_WITH_AS(s.add_hit_group("Proc", {.kind = HitGroupKind::procedural, .closest_hit = "c"}),
                       doctest::Contains("procedural hit group \"Proc\" has no intersection shader"), HitGroupKindError);
  CHECK_THROWS_WITH_AS(s.add_hit_group<TestAttributes>("Tri2", {.closest_hit = "c"}),
                       doctest::Contains("triangles report the built-in barycentrics"), HitGroupKindError);
  CHECK(s.hit_groups().size() == 0);
}

TEST_CASE("scene geometries sharing a BLAS get consecutive geometry indices") {
  TestScene s;
  GeometryDesc a = GeometryDesc::procedural({Aabb{}}, {identity_transform(), identity_transform()});
  a.blas = "Shared";
  GeometryDesc b = GeometryDesc::procedural({Aabb{}}, {});
  b.blas = "Shared";
  const GeometryId own = s.add_geometry("Own", GeometryDesc::procedural({Aabb{}}));
  const GeometryId ga = s.add_geometry("A", a);
  const GeometryId gb = s.add_geometry("B", b);
  CHECK(s.blases().size() == 2);
  CHECK(s.geometry(own).geometry_index == 0);
  CHECK(s.geometry(ga).geometry_index == 0);
  CHECK(s.geometry(gb).geometry_index == 1);
  CHECK(s.geometry(ga).blas == s.geometry(gb).blas);
  CHECK(s.blas_of(gb).instances.size() == 2);
  CHECK(s.blas_of(own).name == "Own");
  CHECK(s.instance_count() == 3);
  GeometryDesc tri = GeometryDesc::triangles(triangle(), {});
  tri.blas = "Shared";
  CHECK_THROWS_WITH_AS(s.add_geometry("T", tri), doctest::Contains("a BLAS holds one kind"), InvalidGeometryError);
  GeometryDesc other = GeometryDesc::procedural({Aabb{}}, {identity_transform()});
  other.blas = "Shared";
  CHECK_THROWS_WITH_AS(s.add_geometry("C", other), doctest::Contains("instances belong to the BLAS"), InvalidGeometryError);
}

TEST_CASE("scene add_geometry refuses a tiny scale, a NaN transform and an inverted AABB naming call, id, index, fix") {
  TestScene s;
  const InstanceTransform ok = identity_transform();
  const InstanceTransform tiny = instance_transform(glm::scale(glm::mat4(1.0f), glm::vec3(1e-11f)));
  InstanceTransform nan = identity_transform();
  nan[2][3] = std::numeric_limits<float>::quiet_NaN();
  auto message = [&](const GeometryDesc& desc) -> std::string {
    try {
      s.add_geometry("Pacman", desc);
    } catch (const InvalidGeometryError& e) {
      return e.what();
    }
    return "(no exception)";
  };
  const std::string small = message(GeometryDesc::procedural({Aabb{}}, {ok, ok, tiny}));
  CHECK_MESSAGE(small.find("Scene::add_geometry: geometry \"Pacman\" instance 2 transform is singular") !=
                    std::string::npos, small);
  CHECK_MESSAGE(small.find("check for a zero or tiny (< 1e-10) scale") != std::string::npos, small);
  const std::string not_finite = message(GeometryDesc::procedural({Aabb{}}, {ok, nan}));
  CHECK_MESSAGE(not_finite.find("Scene::add_geometry: geometry \"Pacman\" instance 1 transform has a non-finite "
                                "element at row 2 column 3") != std::string::npos, not_finite);
  CHECK_MESSAGE(not_finite.find("give a finite affine transform") != std::string::npos, not_finite);
  const std::string inverted = message(GeometryDesc::procedural({Aabb{}, Aabb{glm::vec3(1.0f), glm::vec3(-1.0f)}}));
  CHECK_MESSAGE(inverted.find("Scene::add_geometry: geometry \"Pacman\" AABB 1 has min") != std::string::npos, inverted);
  CHECK_MESSAGE(inverted.find("swap the corners so min <= max on every axis") != std::string::npos, inverted);
  CHECK(s.geometries().size() == 0);  // nothing was added
}

TEST_CASE("scene add_geometry that throws leaves the scene unchanged") {
  TestScene s;
  GeometryDesc a = GeometryDesc::procedural({Aabb{}}, {identity_transform(), identity_transform()});
  a.blas = "Shared";
  s.add_geometry("A", a);
  s.add_geometry("Own", GeometryDesc::procedural({Aabb{}}));
  // A duplicate id, into a new BLAS and into the shared one: no BLAS, geometry or instance appears.
  CHECK_THROWS_AS(s.add_geometry("Own", GeometryDesc::procedural({Aabb{}})), DuplicateIdError);
  GeometryDesc again = GeometryDesc::procedural({Aabb{}}, {});
  again.blas = "Shared";
  CHECK_THROWS_AS(s.add_geometry("A", again), DuplicateIdError);
  GeometryDesc fresh = GeometryDesc::procedural({Aabb{}}, {identity_transform()});
  fresh.blas = "Fresh";
  CHECK_THROWS_AS(s.add_geometry("Own", fresh), DuplicateIdError);
  CHECK(s.geometries().size() == 2);
  CHECK(s.blases().size() == 2);
  CHECK(s.blases()[0].geometries.size() == 1);
  CHECK(s.instance_count() == 3);
  // The BLAS name of the failed call is still free.
  fresh.blas = "Fresh";
  const GeometryId f = s.add_geometry("F", fresh);
  CHECK(s.blas_of(f).name == "Fresh");
  CHECK(s.blas_of(f).shared);
  CHECK(s.blases().size() == 3);
}

TEST_CASE("scene geometries sharing a BLAS shares its update policy") {
  TestScene scene;
  const TriangleMesh mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}};
  GeometryDesc moving = GeometryDesc::triangles(mesh);
  moving.blas = "shared";
  moving.update = UpdatePolicy::DynamicTransform;
  scene.add_geometry("moving", moving);
  GeometryDesc still = GeometryDesc::triangles(mesh, {});
  still.blas = "shared";
  CHECK_THROWS_WITH_AS(scene.add_geometry("still", still),
                       doctest::Contains("geometry \"still\" is Static but BLAS \"shared\" is DynamicTransform; "
                                         "geometries sharing a BLAS share its instances and its builds"),
                       InvalidGeometryError);
  still.update = UpdatePolicy::DynamicTransform;
  scene.add_geometry("still", still);
  CHECK(scene.blases()[0].update == UpdatePolicy::DynamicTransform);
  GeometryDesc bogus = GeometryDesc::triangles(mesh);
  bogus.update = static_cast<UpdatePolicy>(7);
  CHECK_THROWS_WITH_AS(scene.add_geometry("bogus", bogus), doctest::Contains("has update policy 7; use UpdatePolicy::Static"),
                       InvalidGeometryError);
}

// ---- Entries: Scene::add_raygen, add_miss, add_hit, set_default_hit, add_callable_record and the pipeline settings.

TEST_CASE("scene add_hit: hit group kind must match the geometry") {
  test::ReportScene r;
  test::build_report_scene(r);
  auto& t = r.scene;
  CHECK_THROWS_WITH_AS(t.add_hit(r.radiance, r.scene.hit_group_id("Triangle"), r.pacman),
                       doctest::Contains("Scene::add_hit: procedural geometry \"Pacman\" bound to triangles hit group "
                                         "\"Triangle\", which has no intersection shader"),
                       HitGroupKindError);
  CHECK_THROWS_WITH_AS(t.add_hit(r.radiance, r.scene.hit_group_id("Pacman"), r.plane),
                       doctest::Contains("bind a triangles hit group"), HitGroupKindError);
  CHECK(t.entries().all().empty());
}

TEST_CASE("scene add_hit: string ids are checked at run time") {
  test::ReportScene r;
  test::build_report_scene(r);
  auto& t = r.scene;
  CHECK_THROWS_WITH_AS(t.add_hit("Radiance", "Pacman", "Procedural", test::TriangleRootArguments{}, "Pacman"),
                       doctest::Contains("local signature \"Procedural\" has root arguments type"), TypeMismatchError);
  CHECK_THROWS_WITH_AS(t.add_hit("Radiance", "Pacmam", "Procedural", test::ProceduralRootArguments{}, "Pacman"),
                       doctest::Contains("unknown hit group id \"Pacmam\"; nearest known ids: \"Pacman\""), UnknownIdError);
  CHECK_THROWS_WITH_AS(t.add_hit("Radiance", "Pacman", "Procedural", test::ProceduralRootArguments{}, "Pacman", 3),
                       doctest::Contains("Scene::add_hit: instance 3 of geometry \"Pacman\" does not exist (it has 3 instances)"),
                       SceneError);
  CHECK_THROWS_AS(t.add_hit(r.radiance, HitGroupId(), r.pacman), UnknownIdError);
  CHECK(t.entries().all().empty());
}

TEST_CASE("scene entries keep the order they were added in and copies of their root arguments") {
  TestScene s;
  const auto ray = s.add_ray<TestPayload>("Radiance", {.miss = "miss"});
  const auto group = s.add_hit_group("Triangle", {.closest_hit = "chit"});
  const auto plane = s.add_geometry("Plane", GeometryDesc::triangles(triangle(), {identity_transform(), identity_transform()}));
  const auto sig = s.add_local_signature<Arguments>("Local");
  s.reserve_entries(4, 3 * sizeof(Arguments));
  Arguments args{7};
  const EntryId hit = s.add_hit(ray, group, sig, args, plane, 1);
  args.index = 8;  // the entry copied the bytes when it was added
  const EntryId raygen = s.add_raygen("rgen", sig, Arguments{9});
  const EntryId miss = s.add_miss(ray, sig, Arguments{10});
  const EntryId wide = s.add_hit(ray, group, plane);
  CHECK(hit.index() == 0);
  CHECK(raygen.index() == 1);
  CHECK(miss.index() == 2);
  CHECK(wide.index() == 3);
  const EntryList& list = s.entries();
  REQUIRE(list.all().size() == 4);
  CHECK(list.all()[0].region == SbtRegionKind::hit);
  CHECK(list.all()[0].instance == 1);
  CHECK(list.all()[0].geometry == plane.index());
  CHECK(list.all()[1].region == SbtRegionKind::raygen);
  CHECK(list.raygen_shaders()[list.all()[1].shader] == "rgen");
  CHECK(list.all()[2].region == SbtRegionKind::miss);
  CHECK(list.all()[3].instance == all_instances);
  CHECK(list.all()[3].local_signature == no_index);
  CHECK(list.data().size() == 3 * sizeof(Arguments));
  Arguments back{};
  REQUIRE(list.data(list.all()[0]).size() == sizeof(Arguments));
  std::memcpy(&back, list.data(list.all()[0]).data(), sizeof back);
  CHECK(back.index == 7);
  std::memcpy(&back, list.data(list.all()[2]).data(), sizeof back);
  CHECK(back.index == 10);
  CHECK(list.data(list.all()[3]).empty());
  CHECK_THROWS_WITH_AS(s.add_raygen(""), doctest::Contains("Scene::add_raygen: empty raygen shader name"), SceneError);
  CHECK_THROWS_WITH_AS(s.add_raygen("rgen", LocalSignatureId<Arguments>(3), Arguments{}),
                       doctest::Contains("Scene::add_raygen: local signature #3 is not registered"), UnknownIdError);
  CHECK_THROWS_WITH_AS(s.add_hit(ray, group, LocalSignatureId<Arguments>(3), Arguments{}, plane),
                       doctest::Contains("Scene::add_hit: local signature #3"), UnknownIdError);
  CHECK(list.all().size() == 4);
}

TEST_CASE("scene set_max_recursion_depth refuses 0 and keeps what was declared") {
  TestScene s;
  CHECK_FALSE(s.max_recursion_depth().has_value());
  CHECK_THROWS_WITH_AS(s.set_max_recursion_depth(0), doctest::Contains("Scene::set_max_recursion_depth: depth 0"), SceneError);
  CHECK_FALSE(s.max_recursion_depth().has_value());
  s.set_max_recursion_depth(2);
  CHECK(s.max_recursion_depth() == 2u);
}

TEST_CASE("scene set_global_signature with a desc registers it and selects it") {
  test::ReportScene r;
  test::build_report_scene(r);
  test::add_report_entries(r);  // selects "Global"
  auto& s = r.scene;
  const auto signatures = s.global_signatures().size();
  const GlobalSignatureId g = s.set_global_signature(default_global_signature());
  CHECK(s.global_signatures().size() == signatures + 1);
  CHECK(g == s.global_signature_id("global"));  // the default id
  CHECK(s.pipeline_global_signature() == g);
  CHECK(s.global_signature(g).desc == default_global_signature());
  Plan plan = compile(s);
  CHECK(plan.pipeline().global_signature == g);
  REQUIRE(plan.global_signature() != nullptr);
  // The scene declares a recursion depth: compile() adds the depth counter's image after the bindings.
  REQUIRE(s.max_recursion_depth().has_value());
  GlobalSignatureDesc expected = default_global_signature();
  expected.bindings.push_back({BindingKind::output_image, plan.depth_binding(), 0, 1, "", nullptr});
  CHECK(*plan.global_signature() == expected);
  // Registered once: the same id again is a duplicate, and the selection stays.
  CHECK_THROWS_AS(s.set_global_signature(default_global_signature()), DuplicateIdError);
  CHECK(s.pipeline_global_signature() == g);
  const GlobalSignatureId other = s.set_global_signature(default_global_signature(), "other");
  CHECK(other == s.global_signature_id("other"));
  CHECK(s.pipeline_global_signature() == other);
  CHECK(compile(s).pipeline().global_signature == s.global_signature_id("other"));
  // By id: selects a registered one, refuses an id the scene did not issue.
  s.set_global_signature(s.global_signature_id("Global"));
  CHECK(compile(s).pipeline().global_signature == s.global_signature_id("Global"));
  CHECK_THROWS_WITH_AS(s.set_global_signature(GlobalSignatureId(9)), doctest::Contains("Scene::set_global_signature"),
                       UnknownIdError);
  CHECK(s.pipeline_global_signature() == s.global_signature_id("Global"));
}

TEST_CASE("scene without a global signature compiles to a plan without one") {
  test::ReportScene r;
  test::build_report_scene(r);
  r.scene.add_raygen("Raygen");
  r.scene.set_default_hit(r.radiance, r.scene.hit_group_id("Triangle"));
  r.scene.set_default_hit(r.shadow, r.scene.hit_group_id("Triangle_Shadow"));
  r.scene.set_default_hit(r.radiance, r.scene.hit_group_id("Pacman"));
  r.scene.set_default_hit(r.shadow, r.scene.hit_group_id("Pacman_Shadow"));
  CHECK_FALSE(r.scene.pipeline_global_signature().valid());
  const Plan plan = compile(r.scene);
  CHECK_FALSE(plan.pipeline().global_signature.valid());
  CHECK(plan.global_signature() == nullptr);
}

// ---- The interface: each registration's type is an alternative of its category (the rest do not
// compile: compile_fail/scene_*.cpp); the maxima come from what the records use.
namespace scene_interface_test {
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
}  // namespace scene_interface_test

using namespace scene_interface_test;
namespace pr = proceduray;



// What the interface lists: the largest alternatives, which the scene below does not use.
static_assert(Interface::max_payload_size == sizeof(Big) && Interface::max_root_arguments_size == sizeof(Huge) &&
              Interface::max_attribute_size == sizeof(Wide));

TEST_CASE("Scene<Interface> registers each category's alternatives and compile() sizes from those records use") {
  pr::Scene<Interface> scene;
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

TEST_CASE("Scene<Interface> keeps the run-time checks") {
  pr::Scene<Interface> scene;
  scene.add_ray<Radiance>("radiance", {.miss = "sky.rmiss"});
  CHECK_THROWS_AS(scene.add_ray<Radiance>("radiance", {.miss = "sky.rmiss"}), pr::DuplicateIdError);
  CHECK_THROWS_WITH_AS(scene.add_local_signature("", Interface::RootArgumentsSet(Material{})),
                       doctest::Contains("empty local signature id"), pr::SceneError);
}
