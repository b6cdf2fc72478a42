// The bad-input table of the pure layers: each case is one call a user could make with a wrong
// value, and the error it must get (type and the words that name the operation, value and fix).
// Each would fail if the check went away: the call would then return normally. tests/vk/
// bad_input_test.cpp holds the cases that need a device.
#include <doctest/doctest.h>

#include "proceduray/march/knobs.hpp"
#include "proceduray/scene/compile.hpp"
#include "proceduray/scene/object.hpp"
#include "proceduray/scene/scene.hpp"
#include "proceduray/shader/camera.hpp"
#include "proceduray/shader/field_list.hpp"

#include <cmath>
#include <limits>
#include <string>

using namespace proceduray;

namespace bad_input {
struct Colour {
  glm::vec4 colour;
};
struct Big {  // 4800 bytes: over max_payload_size
  glm::vec4 values[300];
};
struct Hit {
  glm::vec3 normal;
};
struct Tint {
  glm::vec4 colour;
};
PROCEDURAY_STRUCT(Colour, scalar, colour);
PROCEDURAY_STRUCT(Big, scalar, values);
PROCEDURAY_STRUCT(Hit, scalar, normal);
PROCEDURAY_STRUCT(Tint, scalar, colour);
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<Colour, Tint, Big>, proceduray::RootComponent<>, proceduray::RootArguments<>,
                                   proceduray::Attributes<Hit>>;
using TestScene = proceduray::Scene<TestSceneInterface>;
}  // namespace bad_input

namespace {
using bad_input::Colour;
using bad_input::TestScene;
using Contains = doctest::Contains;

constexpr float not_a_number = std::numeric_limits<float>::quiet_NaN();

/// A scene that compiles: one ray, one procedural object, a raygen.
struct Small {
  TestScene scene;
  RayId<Colour> ray = scene.add_ray<Colour>("primary", {.miss = "sky.rmiss"});
  HitGroupId group = scene.add_hit_group<bad_input::Hit>(
      "ball", {.kind = HitGroupKind::procedural, .closest_hit = "ball.rchit", .intersection = "ball.rint"});
  GeometryId ball = scene.add_geometry("ball", GeometryDesc::procedural({Aabb{}}));
  Small() {
    scene.add_raygen("camera.rgen");
    scene.add_hit(ray, group, ball);
  }
};

}  // namespace

// ---- ids that would not survive the trip to GLSL

TEST_CASE("bad input: two ray ids that mangle to one GLSL name") {
  TestScene s;
  s.add_ray<Colour>("primary-2", {});
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("primary_2", {}),
                       Contains("Scene::add_ray: ray \"primary_2\" and ray \"primary-2\" would both be declared in GLSL as \"primary_2\""),
                       DuplicateIdError);
  CHECK(s.rays().size() == 1);  // the refused ray is not registered
}

TEST_CASE("bad input: a ray named like the incoming payload") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("payload", {}),
                       Contains("ray \"payload\" would be declared in GLSL as \"payload\", a name the generated declarations use"),
                       SceneError);
}

TEST_CASE("bad input: a ray named like the hit attributes") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("hit", {}), Contains("\"hit\", a name the generated declarations use"), SceneError);
}

TEST_CASE("bad input: a ray named with a GLSL keyword") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("sample", {}),
                       Contains("Scene::add_ray: ray \"sample\" would be declared in GLSL as \"sample\", a GLSL reserved word"),
                       SceneError);
}

TEST_CASE("bad input: a ray named texture2DRect, a type glslang reserves") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("texture2DRect", {}), Contains("a GLSL reserved word"), SceneError);
}

TEST_CASE("bad input: a ray named itexture2D") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("itexture2D", {}), Contains("a GLSL reserved word"), SceneError);
}

TEST_CASE("bad input: a ray named devicecoherent") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("devicecoherent", {}), Contains("a GLSL reserved word"), SceneError);
}

TEST_CASE("bad input: a ray named pervertexEXT") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("pervertexEXT", {}), Contains("a GLSL reserved word"), SceneError);
}

TEST_CASE("bad input: a ray id with the gl_ prefix") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("gl_ray", {}), Contains("gl_ prefix or double underscore"), SceneError);
}

TEST_CASE("bad input: a ray id that mangles to a double underscore") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("a -b", {}), Contains("as \"a__b\", a GLSL reserved word (or a gl_ prefix or double underscore)"),
                       SceneError);
}

TEST_CASE("bad input: two layers that mangle to one GLSL name") {
  TestScene s;
  s.add_layer("casts_shadow");
  CHECK_THROWS_WITH_AS(s.add_layer("casts shadow"),
                       Contains("Scene::add_layer: layer \"casts shadow\" and layer \"casts_shadow\" would both be declared "
                                "in GLSL as \"layer_casts_shadow\""),
                       DuplicateIdError);
  CHECK(s.layers().size() == 1);
}

TEST_CASE("bad input: two callables that mangle to one GLSL name") {
  TestScene s;
  s.add_callable<bad_input::Tint>("tint-1", {.shader = "tint.rcall"});
  CHECK_THROWS_WITH_AS(s.add_callable<bad_input::Tint>("tint_1", {.shader = "tint.rcall"}),
                       Contains("callable \"tint_1\" and callable \"tint-1\" would both be declared in GLSL as \"tint_1_callable\""),
                       DuplicateIdError);
}

TEST_CASE("bad input: a ray whose name is a callable's generated name") {
  TestScene s;
  s.add_callable<bad_input::Tint>("x", {.shader = "tint.rcall"});
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("x_call", {}),
                       Contains("ray \"x_call\" and callable \"x\" would both be declared in GLSL as \"x_call\""),
                       DuplicateIdError);
}

TEST_CASE("bad input: a binding named like a ray") {
  TestScene s;
  s.add_ray<Colour>("radiance", {});
  CHECK_THROWS_WITH_AS(
      s.add_global_signature("global", {.bindings = {{BindingKind::acceleration_structure, 0, 0, 1, "radiance"}}}),
      Contains("Scene::add_global_signature: binding \"radiance\" and ray \"radiance\" would both be declared in GLSL"),
      DuplicateIdError);
}

TEST_CASE("bad input: a binding named with a GLSL keyword") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_global_signature("global", {.bindings = {{BindingKind::storage_image, 0, 0, 1, "image2D"}}}),
                       Contains("binding \"image2D\" would be declared in GLSL as \"image2D\", a GLSL reserved word"),
                       SceneError);
}

TEST_CASE("bad input: a ray named like its payload's struct") {
  TestScene s;
  s.add_ray<bad_input::Tint>("Tint", {});  // the ray declares `Tint Tint`: only compile sees the struct names
  s.add_raygen("camera.rgen");
  CHECK_THROWS_WITH_AS(compile(s), Contains("compile: struct Tint and ray \"Tint\" would both be declared in GLSL as \"Tint\""),
                       DuplicateIdError);
}

// ---- ray declarations

TEST_CASE("bad input: ray flags opaque and no_opaque together") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("r", {.flags = RayFlags::opaque | RayFlags::no_opaque}),
                       Contains("Scene::add_ray: ray \"r\" combines more than one of opaque, no_opaque, cull_opaque and "
                                "cull_no_opaque (flags 0x3)"),
                       SceneError);
}

TEST_CASE("bad input: ray flags opaque and cull_opaque together") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("r", {.flags = RayFlags::opaque | RayFlags::cull_opaque}), Contains("(flags 0x41)"),
                       SceneError);
}

TEST_CASE("bad input: ray culls back and front faces") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("r", {.flags = RayFlags::cull_back_facing | RayFlags::cull_front_facing}),
                       Contains("culls both back- and front-facing triangles (flags 0x30)"), SceneError);
}

TEST_CASE("bad input: ray flags outside RayFlags") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("r", {.flags = static_cast<RayFlags>(0x104)}),
                       Contains("ray \"r\" has unknown ray flag bits 0x100"), SceneError);
}

TEST_CASE("bad input: ray cull mask 0") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("r", {.cull_mask = 0}), Contains("ray \"r\" has cull mask 0, which no instance passes"),
                       SceneError);
}

TEST_CASE("bad input: a payload over the size limit") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_ray<bad_input::Big>("r", {}),
                       Contains("ray \"r\" has a payload of 4800 bytes, over the 4096 the library allows"), SceneError);
}

TEST_CASE("bad input: a duplicate ray id") {
  TestScene s;
  s.add_ray<Colour>("r", {});
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("r", {}), Contains("Scene::add_ray: duplicate ray id \"r\""), DuplicateIdError);
}

TEST_CASE("bad input: an empty ray id") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_ray<Colour>("", {}), Contains("Scene::add_ray: empty ray id"), SceneError);
}

// ---- ids from another scene, or unknown

TEST_CASE("bad input: a GeometryId from another scene") {
  Small a, b;
  CHECK_THROWS_WITH_AS(a.scene.add_hit(a.ray, a.group, b.ball, 0),
                       Contains("Scene::add_hit: the id (index 0) was issued by scene #"), UnknownIdError);
}

TEST_CASE("bad input: a RayId from another scene") {
  Small a, b;
  CHECK_THROWS_WITH_AS(a.scene.set_default_hit(b.ray, a.group), Contains("Scene::set_default_hit: the id (index 0) was issued"),
                       UnknownIdError);
}

TEST_CASE("bad input: looking up a geometry with another scene's id") {
  Small a, b;
  CHECK_THROWS_WITH_AS(a.scene.geometry(b.ball), Contains("Scene::geometry: the id (index 0) was issued by scene #"),
                       UnknownIdError);
}

TEST_CASE("bad input: a plan asked about another scene's geometry") {
  Small a, b;
  const Plan plan = compile(a.scene);
  CHECK_THROWS_WITH_AS(plan.geometry(b.ball), Contains("but this plan (and a renderer built from it) was compiled from scene #"),
                       UnknownIdError);
  CHECK(plan.geometry(a.ball).name == "ball");
}

TEST_CASE("bad input: a geometry added after compile, asked of the plan") {
  Small a;
  const Plan plan = compile(a.scene);
  const GeometryId later = a.scene.add_geometry("later", GeometryDesc::procedural({Aabb{}}));
  CHECK_THROWS_WITH_AS(plan.geometry(later, "Renderer::set_transform"),
                       Contains("Renderer::set_transform: geometry #1 is not in the compiled scene"), UnknownIdError);
}

TEST_CASE("bad input: an unknown ray id by name") {
  Small a;
  CHECK_THROWS_WITH_AS(a.scene.ray_id("primry"), Contains("unknown ray id \"primry\"; nearest known ids: \"primary\""),
                       UnknownIdError);
}

TEST_CASE("bad input: a default-constructed GeometryId") {
  Small a;
  CHECK_THROWS_WITH_AS(a.scene.add_hit(a.ray, a.group, GeometryId{}), Contains("a default-constructed geometry id names no geometry; use the id this scene returned"),
                       UnknownIdError);
}

TEST_CASE("bad input: a default-constructed GeometryId asked of a plan") {
  Small a;
  const Plan plan = compile(a.scene);
  CHECK_THROWS_WITH_AS(plan.geometry(GeometryId{}, "Renderer::set_transform"),
                       Contains("Renderer::set_transform: a default-constructed GeometryId names no geometry; use the id "
                                "Scene::add_geometry"),
                       UnknownIdError);
}

TEST_CASE("bad input: a geometry mask of 0x100 (wider than Vulkan's 8 bits)") {
  TestScene s;
  GeometryDesc d = GeometryDesc::procedural({Aabb{}});
  d.instances = {identity_transform()};
  d.mask = 0x100;  // an uint8_t field would have truncated this to 0: the instance would vanish
  CHECK_THROWS_WITH_AS(s.add_geometry("ball", d),
                       Contains("mask is 0x100, more than Vulkan's 8 instance-mask bits; use layer bits"),
                       InvalidGeometryError);
  d.mask = 0xFF;
  d.instance_masks = {0x1FF};
  CHECK_THROWS_WITH_AS(s.add_geometry("ball", d), Contains("instance mask 0 is 0x1ff"), InvalidGeometryError);
}

// ---- entries and compile

TEST_CASE("bad input: an instance past the geometry's count") {
  Small a;
  CHECK_THROWS_WITH_AS(a.scene.add_hit(a.ray, a.group, a.ball, 3), Contains("instance 3 of geometry \"ball\" does not exist"),
                       SceneError);
}

TEST_CASE("bad input: a triangle geometry bound to a procedural hit group") {
  Small a;
  const GeometryId plane = a.scene.add_geometry("plane", GeometryDesc::triangles({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}}));
  CHECK_THROWS_WITH_AS(a.scene.add_hit(a.ray, a.group, plane), Contains("bind a triangles hit group"), HitGroupKindError);
}

TEST_CASE("bad input: a scene without raygen") {
  TestScene s;
  s.add_ray<Colour>("r", {});
  CHECK_THROWS_WITH_AS(compile(s), Contains("compile: no raygen entry; add one with Scene::add_raygen"), SceneError);
}

TEST_CASE("bad input: a geometry no entry covers") {
  Small a;
  a.scene.add_geometry("orphan", GeometryDesc::procedural({Aabb{}}));
  CHECK_THROWS_WITH_AS(compile(a.scene), Contains("(\"primary\", \"orphan\", instances without own entries)"),
                       MissingEntryError);
}

TEST_CASE("bad input: recursion depth 0") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.set_max_recursion_depth(0), Contains("depth 0 allows no traceRayEXT at all; use >= 1"), SceneError);
}

TEST_CASE("bad input: a ninth layer") {
  TestScene s;
  for (int i = 0; i < 8; ++i) s.add_layer("l" + std::to_string(i));
  CHECK_THROWS_WITH_AS(s.add_layer("l8"), Contains("would be the ninth; an instance mask has 8 bits"), SceneError);
}

TEST_CASE("bad input: a callable without a shader") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_callable<bad_input::Tint>("tint", {}), Contains("has no shader; set .shader"), SceneError);
}

TEST_CASE("bad input: a procedural object without an intersection shader") {
  Small a;
  CHECK_THROWS_WITH_AS(add_object<bad_input::Hit>(a.scene, "box", {.geometry = GeometryDesc::procedural({Aabb{}})}),
                       Contains("add_object: procedural hit group \"box\" has no intersection shader; AABB geometry needs "
                                "one: set .intersection"),
                       SceneError);
}

TEST_CASE("bad input: an inverted AABB") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_geometry("box", GeometryDesc::procedural({Aabb{{1, 1, 1}, {0, 0, 0}}})), Contains("box"),
                       InvalidGeometryError);
}

TEST_CASE("bad input: a triangle index past the vertices") {
  TestScene s;
  CHECK_THROWS_AS(s.add_geometry("tri", GeometryDesc::triangles({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 7}})),
                  InvalidGeometryError);
}

// ---- camera

TEST_CASE("bad input: a camera with a NaN eye") {
  CHECK_THROWS_WITH_AS(look_at({not_a_number, 0, 0}, {0, 0, 1}, 45.0f, 64, 64), Contains("look_at: eye (nan"), UsageError);
}

TEST_CASE("bad input: a camera with an infinite target") {
  const float inf = std::numeric_limits<float>::infinity();
  CHECK_THROWS_WITH_AS(look_at({0, 0, 0}, {0, 0, inf}, 45.0f, 64, 64), Contains("is not finite (NaN or infinity)"), UsageError);
}

TEST_CASE("bad input: a camera with a NaN field of view") {
  CHECK_THROWS_WITH_AS(look_at({0, 0, 0}, {0, 0, 1}, not_a_number, 64, 64), Contains("is not finite"), UsageError);
}

TEST_CASE("bad input: a camera whose eye is its target") {
  CHECK_THROWS_WITH_AS(look_at({1, 1, 1}, {1, 1, 1}, 45.0f, 64, 64), Contains("eye and target must differ"), UsageError);
}

// ---- march knobs

TEST_CASE("bad input: an unknown march knob") {
  MarchKnobs k;
  CHECK_THROWS_WITH_AS(set_knob(k, "treshold", "0.5"), Contains("march knobs: unknown knob 'treshold'; valid: "), UsageError);
}

TEST_CASE("bad input: two bindings of one global signature with one name") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.add_global_signature("global", {.bindings = {{BindingKind::acceleration_structure, 0, 0, 1, "tlas"},
                                                                      {BindingKind::storage_image, 1, 0, 1, "tlas"}}}),
                       Contains("binding \"tlas\" and binding \"tlas\" would both be declared in GLSL as \"tlas\""),
                       DuplicateIdError);
}

TEST_CASE("bad input: a ray registered after a global signature with a binding of its name") {
  TestScene s;
  s.set_global_signature({.bindings = {{BindingKind::acceleration_structure, 0, 0, 1, "tlas"}}});
  s.add_ray<Colour>("tlas", {});  // registration does not see signatures: only one of them is declared
  s.add_raygen("camera.rgen");
  CHECK_THROWS_WITH_AS(compile(s), Contains("compile: binding \"tlas\" and ray \"tlas\" would both be declared"),
                       DuplicateIdError);
}

TEST_CASE("glsl names: two global signatures may reuse binding names") {
  TestScene s;  // not an error: only the pipeline's signature is declared
  s.add_global_signature("a", {.bindings = {{BindingKind::acceleration_structure, 0, 0, 1, "tlas"}}});
  CHECK_NOTHROW(s.add_global_signature("b", {.bindings = {{BindingKind::acceleration_structure, 0, 0, 1, "tlas"}}}));
}
