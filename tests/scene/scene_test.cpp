#include "proceduray/scene/scene.hpp"

#include <doctest/doctest.h>

#include "proceduray/shader/field_list.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>
#include <string>

using namespace proceduray;

namespace {
struct TestPayload { float value; };
struct OtherPayload { std::uint32_t hit; };
struct Args { std::uint32_t index; };
struct TestAttributes { float normal[3]; };
PROCEDURAY_STRUCT(TestPayload, scalar, value);
PROCEDURAY_STRUCT(OtherPayload, scalar, hit);
PROCEDURAY_STRUCT(Args, scalar, index);
PROCEDURAY_STRUCT(TestAttributes, scalar, normal);
TriangleMesh triangle() { return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}}; }
}  // namespace

TEST_CASE("scene entities register by id and return typed ids") {
  Scene s;
  const RayId<TestPayload> radiance = s.add_ray<TestPayload>("Radiance", {.miss = "miss"});
  const RayId<OtherPayload> shadow = s.add_ray<OtherPayload>("Shadow", {.miss = "miss_shadow"});
  const HitGroupId tri = s.add_hit_group("Triangle", {.closest_hit = "chit"});
  const HitGroupId proc = s.add_hit_group<TestAttributes>("Proc", {.kind = HitGroupKind::procedural, .intersection = "isect"});
  const GeometryId plane = s.add_geometry("Plane", GeometryDesc::triangles(triangle()));
  const GlobalSignatureId global = s.add_global_signature("Global", {.bindings = {{.kind = BindingKind::acceleration_structure}}});
  const LocalSignatureId<Args> local = s.add_local_signature<Args>("Local");
  CHECK(radiance.index() == 0);
  CHECK(shadow.index() == 1);
  CHECK(s.ray_id<TestPayload>("Radiance") == radiance);
  CHECK(s.ray_id("Shadow") == RayId<>(shadow));
  CHECK(s.hit_group_id("Proc") == proc);
  CHECK(s.geometry_id("Plane") == plane);
  CHECK(s.global_signature_id("Global") == global);
  CHECK(s.local_signature_id<Args>("Local") == local);
  CHECK(s.ray(radiance).payload_size == sizeof(TestPayload));
  CHECK(s.ray("Shadow").desc.miss == "miss_shadow");
  CHECK(s.hit_group(tri).attribute_size == triangle_attribute_size);
  CHECK(s.hit_group(proc).attribute_size == sizeof(TestAttributes));
  CHECK(s.local_signature(local).data_size == sizeof(Args));
  CHECK(s.global_signature(global).desc.bindings.size() == 1);
  CHECK(s.geometry(plane).desc.kind == GeometryKind::triangles);
}

TEST_CASE("scene find returns a pointer or nullptr") {
  Scene s;
  s.add_ray<TestPayload>("Radiance", {.miss = "miss"});
  s.add_hit_group("Triangle", {});
  s.add_geometry("Plane", GeometryDesc::triangles(triangle()));
  s.add_local_signature<Args>("Local");
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
  Scene s;
  s.add_ray<TestPayload>("Radiance", {.miss = "miss"});
  CHECK_THROWS_WITH_AS(s.add_ray<TestPayload>("Radiance", {.miss = "other"}),
                       doctest::Contains("Scene::add_ray: duplicate ray id \"Radiance\""), DuplicateIdError);
  s.add_geometry("Plane", GeometryDesc::triangles(triangle()));
  CHECK_THROWS_WITH_AS(s.add_geometry("Plane", GeometryDesc::triangles(triangle())),
                       doctest::Contains("duplicate geometry id \"Plane\""), DuplicateIdError);
  CHECK(s.blases().size() == 1);  // the failed add left no BLAS behind
  s.add_local_signature<Args>("Local");
  CHECK_THROWS_AS(s.add_local_signature<Args>("Local"), DuplicateIdError);
  s.add_hit_group("G", {});
  CHECK_THROWS_WITH_AS(s.add_hit_group("G", {}), doctest::Contains("choose a unique id"), DuplicateIdError);
}

TEST_CASE("scene unknown ids name the nearest known ids") {
  Scene s;
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
  CHECK_THROWS_WITH_AS(s.geometry(GeometryId()), doctest::Contains("(invalid id)"), UnknownIdError);
}

TEST_CASE("scene typed lookups check the registered type") {
  Scene s;
  s.add_ray<TestPayload>("Radiance", {.miss = "miss"});
  s.add_local_signature<Args>("Local");
  CHECK_NOTHROW(s.ray_id<TestPayload>("Radiance"));
  CHECK_THROWS_WITH_AS(s.ray_id<OtherPayload>("Radiance"), doctest::Contains("ray \"Radiance\" has payload type"),
                       TypeMismatchError);
  CHECK_THROWS_WITH_AS(s.local_signature_id<TestPayload>("Local"), doctest::Contains("ask for the type it was registered with"),
                       TypeMismatchError);
}

TEST_CASE("scene hit group kinds are checked when registered") {
  Scene s;
  CHECK_THROWS_WITH_AS(s.add_hit_group("Tri", {.closest_hit = "c", .intersection = "isect"}),
                       doctest::Contains("triangle hit group \"Tri\" has intersection shader \"isect\""), HitGroupKindError);
  CHECK_THROWS_WITH_AS(s.add_hit_group("Proc", {.kind = HitGroupKind::procedural, .closest_hit = "c"}),
                       doctest::Contains("procedural hit group \"Proc\" has no intersection shader"), HitGroupKindError);
  CHECK_THROWS_WITH_AS(s.add_hit_group<TestAttributes>("Tri2", {.closest_hit = "c"}),
                       doctest::Contains("triangles report the built-in barycentrics"), HitGroupKindError);
  CHECK(s.hit_groups().size() == 0);
}

TEST_CASE("scene geometries sharing a BLAS get consecutive geometry indices") {
  Scene s;
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
  Scene s;
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
  Scene s;
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
  Scene scene;
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
