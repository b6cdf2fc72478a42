// scene/glsl_for.hpp: declarations derived from the scene, per shader and stage.
#include <proceduray/scene/compile.hpp>
#include <proceduray/scene/glsl_for.hpp>
#include <proceduray/scene/uniform_slot.hpp>
#include <proceduray/shader/field_list.hpp>

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <optional>

namespace glsl_for_test {
struct Light {
  glm::vec3 colour;
  float pad;
};
PROCEDURAY_STRUCT(Light, scalar, colour, pad);
struct Shadow {
  std::uint32_t occluded;
};
PROCEDURAY_STRUCT(Shadow, scalar, occluded);
struct Hit {
  glm::vec3 normal;
};
PROCEDURAY_STRUCT(Hit, scalar, normal);
struct Material {
  glm::vec4 albedo;
};
PROCEDURAY_STRUCT(Material, scalar, albedo);
struct Other {
  float x;
};
PROCEDURAY_STRUCT(Other, scalar, x);
struct Globals {
  glm::vec4 sky;
};
PROCEDURAY_STRUCT(Globals, std430, sky);
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<Light, Shadow>, proceduray::RootComponent<Globals, Other>, proceduray::RootArguments<Material, Other>,
                                   proceduray::Attributes<Hit>>;
using TestScene = proceduray::Scene<TestSceneInterface>;
}  // namespace glsl_for_test

using namespace proceduray;
using namespace glsl_for_test;

namespace {

constexpr UniformSlot<Globals> globals{.binding = 2, .name = "globals"};
constexpr StorageSlot<Other> others{.binding = 3, .set = 1, .name = "others"};

/// How a fixture misuses its shaders, if at all.
enum class Misuse { none, two_payloads, two_records };

/// Two rays (light, shadow), a procedural ball, a triangle floor. two_payloads binds the ball's
/// closest hit to the shadow ray too; two_records gives the ball's shadow entry another record type:
/// compile() refuses both.
struct Scenes {
  TestScene scene;

  explicit Scenes(Misuse misuse = Misuse::none) {
    const bool second_payload = misuse == Misuse::two_payloads;
    auto light = scene.add_ray<Light>("light", {.miss = "sky.rmiss"});
    auto shadow = scene.add_ray<Shadow>("shadow ray", {.miss = "shadow.rmiss"});
    scene.add_hit_group<Hit>("ball", {.kind = HitGroupKind::procedural, .closest_hit = "ball.rchit",
                                      .intersection = "ball.rint"});
    scene.add_hit_group<Hit>("ball_shadow", {.kind = HitGroupKind::procedural,
                                             .closest_hit = second_payload ? "ball.rchit" : "",
                                             .intersection = "ball.rint"});
    scene.add_hit_group("floor", {.kind = HitGroupKind::triangles, .closest_hit = "floor.rchit"});
    scene.add_hit_group("floor_shadow", {.kind = HitGroupKind::triangles});
    auto ball = scene.add_geometry("ball", GeometryDesc::procedural({Aabb{}}));
    auto floor = scene.add_geometry("floor", GeometryDesc::triangles({{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, {0, 1, 2}}));
    auto material = scene.add_local_signature<Material>("material");
    auto other = scene.add_local_signature<Other>("other");
    auto global = scene.add_global_signature("global", {.bindings = {{BindingKind::acceleration_structure, 0, 0, 1, "tlas"},
                                                                     {BindingKind::storage_image, 1, 0, 1, "image"},
                                                                     globals, others}});
    scene.add_raygen("main.rgen");
    scene.set_global_signature(global);
    scene.add_hit(light, scene.hit_group_id("ball"), material, Material{}, ball);
    if (misuse == Misuse::two_records) {
      scene.add_hit(shadow, scene.hit_group_id("ball_shadow"), other, Other{}, ball);
    } else {
      scene.add_hit(shadow, scene.hit_group_id("ball_shadow"), material, Material{}, ball);
    }
    scene.add_hit(light, scene.hit_group_id("floor"), other, Other{}, floor);
    scene.add_hit(shadow, scene.hit_group_id("floor_shadow"), floor);
  }
};

/// The well-formed scene, compiled.
struct Fixture : Scenes {
  Plan plan = compile(scene);
  std::string operator()(ShaderStage stage, const char* shader) const { return glsl_for(plan, stage, shader); }
};

bool has(const std::string& text, const char* piece) { return text.find(piece) != std::string::npos; }

}  // namespace

TEST_CASE("glsl_for gives every stage the structs ray indices and named bindings") {
  const Fixture f;
  const std::string any = f(ShaderStage::intersection, "ball.rint");
  CHECK(has(any, "struct Light {"));
  CHECK(has(any, "struct Material {"));
  CHECK(has(any, "const uint light_ray = 0u;"));
  CHECK(has(any, "const uint shadow_ray_ray = 1u;"));  // "shadow ray" made an identifier
  CHECK(has(any, "const uint ray_count = 2u;"));
  CHECK(has(any, "layout(set = 0, binding = 0) uniform accelerationStructureEXT tlas;"));
  CHECK(has(any, "layout(set = 0, binding = 1, rgba8) uniform image2D image;"));
  CHECK(has(any, "layout(set = 0, binding = 2, std430) uniform GlobalsUniform {"));
  CHECK(has(any, "} globals;"));
  CHECK(has(any, "layout(set = 1, binding = 3, scalar) readonly buffer OtherBuffer {\n    Other data[];\n} others;"));
}

TEST_CASE("glsl_for declares payloads by stage") {
  const Fixture f;
  const std::string raygen = f(ShaderStage::raygen, "main.rgen");
  CHECK(has(raygen, "layout(location = 0) rayPayloadEXT Light light;"));
  CHECK(has(raygen, "layout(location = 1) rayPayloadEXT Shadow shadow_ray;"));
  CHECK_FALSE(has(raygen, "rayPayloadInEXT"));
  // Incoming payloads sit at location ray_count, past every outgoing one.
  CHECK(has(f(ShaderStage::miss, "shadow.rmiss"), "layout(location = 2) rayPayloadInEXT Shadow payload;"));
  CHECK(has(f(ShaderStage::miss, "sky.rmiss"), "layout(location = 2) rayPayloadInEXT Light payload;"));
  CHECK(has(f(ShaderStage::miss, "sky.rmiss"), "layout(location = 1) rayPayloadEXT Shadow shadow_ray;"));  // misses may trace
  const std::string hit = f(ShaderStage::closest_hit, "ball.rchit");
  CHECK(has(hit, "layout(location = 2) rayPayloadInEXT Light payload;"));
  CHECK(has(hit, "layout(location = 1) rayPayloadEXT Shadow shadow_ray;"));  // to trace shadow rays
  CHECK(has(hit, "layout(location = 0) rayPayloadEXT Light light;"));  // its own ray type too: reflections
  CHECK(has(hit, "hitAttributeEXT Hit hit;"));
  CHECK(has(hit, "layout(shaderRecordEXT, scalar) buffer MaterialRootArguments {"));
  const std::string isect = f(ShaderStage::intersection, "ball.rint");
  CHECK(has(isect, "hitAttributeEXT Hit hit;"));
  CHECK_FALSE(has(isect, "rayPayload"));
  CHECK_FALSE(has(isect, "trace_"));  // intersection and any-hit shaders cannot trace
  const std::string floor = f(ShaderStage::closest_hit, "floor.rchit");
  CHECK(has(floor, "OtherRootArguments"));
  CHECK_FALSE(has(floor, "hitAttributeEXT"));  // triangles use the built-in barycentrics
}

TEST_CASE("glsl_for gives tracing stages a trace function per ray type") {
  const Fixture f;
  for (const auto& use : {std::pair{ShaderStage::raygen, "main.rgen"}, std::pair{ShaderStage::miss, "sky.rmiss"},
                          std::pair{ShaderStage::closest_hit, "ball.rchit"}}) {
    const char* shader = use.second;  // no structured binding: clang 14 cannot capture one (CAPTURE)
    CAPTURE(shader);
    const std::string glsl = f(use.first, shader);
    // flags, mask, SBT offset = ray index, stride = ray count, miss index = ray index, location = ray index
    CHECK(has(glsl, "void trace_light(vec3 origin, float tmin, vec3 direction, float tmax) { traceRayEXT(tlas, "
                    "light_flags, light_mask, light_ray, ray_count, light_ray, origin, tmin, direction, tmax, 0); }"));
    CHECK(has(glsl, "void trace_shadow_ray(vec3 origin, float tmin, vec3 direction, float tmax) { traceRayEXT(tlas, "
                    "shadow_ray_flags, shadow_ray_mask, shadow_ray_ray, ray_count, shadow_ray_ray, origin, tmin, "
                    "direction, tmax, 1); }"));
    // The explicit-payload form copies p in and returns what the shaders left.
    CHECK(has(glsl, "Shadow trace_shadow_ray(vec3 origin, float tmin, vec3 direction, float tmax, Shadow p) { "
                    "shadow_ray = p; traceRayEXT(tlas, shadow_ray_flags, shadow_ray_mask, shadow_ray_ray, ray_count, "
                    "shadow_ray_ray, origin, tmin, direction, tmax, 1); return shadow_ray; }"));
  }
  CHECK_FALSE(has(f(ShaderStage::intersection, "ball.rint"), "traceRayEXT"));  // the fixture has no any-hit shader
}

TEST_CASE("glsl_for declares no trace functions without a named acceleration structure") {
  TestScene scene;
  auto light = scene.add_ray<Light>("light", {.miss = "sky.rmiss"});
  auto group = scene.add_hit_group("floor", {.kind = HitGroupKind::triangles, .closest_hit = "floor.rchit"});
  scene.add_geometry("floor", GeometryDesc::triangles({{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, {0, 1, 2}}));
  auto global = scene.add_global_signature("global", {.bindings = {{BindingKind::acceleration_structure, 0, 0, 1, ""}}});
  scene.add_raygen("main.rgen");
  scene.set_global_signature(global);
  scene.set_default_hit(light, group);
  const Plan plan = compile(scene);
  const std::string raygen = glsl_for(plan, ShaderStage::raygen, "main.rgen");
  CHECK(has(raygen, "rayPayloadEXT Light light;"));
  CHECK_FALSE(has(raygen, "trace_light"));
}

TEST_CASE("glsl_for puts the scene's procedural boxes in every stage, once however often appended") {
  const Fixture f;
  for (const auto& [stage, shader] : {std::pair{ShaderStage::raygen, "main.rgen"}, std::pair{ShaderStage::intersection, "ball.rint"},
                                      std::pair{ShaderStage::closest_hit, "floor.rchit"}}) {
    const std::string glsl = f(stage, shader);
    CHECK(has(glsl, "const vec3 ball_aabb_min = vec3("));
    CHECK(has(glsl, "#ifndef PROCEDURAY_AABB_CONSTS"));  // a hand-appended copy is skipped
    CHECK_FALSE(has(glsl, "floor_aabb"));  // triangles have no boxes
  }
}

TEST_CASE("glsl_summary lists a shader's generated names without struct bodies or function bodies") {
  const Fixture f;
  const std::string names = glsl_summary(f(ShaderStage::closest_hit, "ball.rchit"));
  CHECK(has(names, "struct Light\n"));
  CHECK_FALSE(has(names, "vec3 colour;"));  // members stay in the declarations
  CHECK(has(names, "const uint light_ray = 0u;\n"));
  CHECK(has(names, "void trace_light(vec3 origin, float tmin, vec3 direction, float tmax)\n"));
  CHECK(has(names, "Shadow trace_shadow_ray(vec3 origin, float tmin, vec3 direction, float tmax, Shadow p)\n"));
  CHECK(has(names, "layout(location = 2) rayPayloadInEXT Light payload;\n"));
  CHECK(has(names, "hitAttributeEXT Hit hit;\n"));
  CHECK(has(names, "buffer MaterialRootArguments arguments\n"));
  CHECK(has(names, "uniform GlobalsUniform globals\n"));
  CHECK_FALSE(has(names, "traceRayEXT"));
}

TEST_CASE("glsl_for names a shader used with two payload types") {
  const Scenes f(Misuse::two_payloads);
  CHECK_THROWS_WITH_AS(compile(f.scene),
                       doctest::Contains("compile: shader \"ball.rchit\" is used with two payload types, Light and Shadow"),
                       SceneError);
}

TEST_CASE("glsl_for names a shader used with two record types") {
  CHECK_NOTHROW(Fixture()(ShaderStage::intersection, "ball.rint"));
  const Scenes f(Misuse::two_records);
  CHECK_THROWS_WITH_AS(compile(f.scene),
                       doctest::Contains("compile: shader \"ball.rint\" is used with two root arguments types, Material and Other"),
                       SceneError);
}

TEST_CASE("glsl_for refuses a shader the plan does not use as that stage") {
  const Fixture f;
  CHECK_THROWS_WITH_AS(f(ShaderStage::closest_hit, "nope.rchit"),
                       doctest::Contains("glsl_for: the plan has no closest_hit stage \"nope.rchit\" (its stages: \"main.rgen\""),
                       UnknownIdError);
  CHECK_THROWS_WITH_AS(f(ShaderStage::miss, "ball.rchit"), doctest::Contains("the plan has no miss stage \"ball.rchit\""),
                       UnknownIdError);
  // The declarations are the plan's: the same text from a copy, after the scene is gone.
  std::optional<Fixture> scoped(std::in_place);
  const Plan copy = scoped->plan;
  const std::string text = (*scoped)(ShaderStage::closest_hit, "ball.rchit");
  scoped.reset();
  CHECK(glsl_for(copy, ShaderStage::closest_hit, "ball.rchit") == text);
}

namespace glsl_for_test {
struct Knobs {
  glm::vec4 tint;
  float exposure;
};
PROCEDURAY_STRUCT(Knobs, scalar, tint, exposure);
using KnobsScene = proceduray::Scene<proceduray::ShaderInterface<proceduray::Payload<Light>, proceduray::RootComponent<Knobs>,
                                                                 proceduray::RootArguments<>, proceduray::Attributes<>>>;
}  // namespace glsl_for_test

TEST_CASE("glsl_for declares a named push constant block in every stage") {
  KnobsScene scene;
  constexpr PushConstantSlot<Knobs> knobs{.name = "knobs"};
  auto light = scene.add_ray<Light>("light", {.miss = "sky.rmiss"});
  auto group = scene.add_hit_group("floor", {.kind = HitGroupKind::triangles, .closest_hit = "floor.rchit"});
  scene.add_geometry("floor", GeometryDesc::triangles({{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, {0, 1, 2}}));
  auto global = scene.add_global_signature("global", {.bindings = {{BindingKind::acceleration_structure, 0, 0, 1, "tlas"}},
                                                      .push_constants = knobs});
  scene.add_raygen("main.rgen");
  scene.set_global_signature(global);
  scene.set_default_hit(light, group);
  const Plan sbt = compile(scene);
  for (const auto& [stage, shader] : {std::pair{ShaderStage::raygen, "main.rgen"}, std::pair{ShaderStage::miss, "sky.rmiss"},
                                      std::pair{ShaderStage::closest_hit, "floor.rchit"}}) {
    const std::string glsl = glsl_for(sbt, stage, shader);
    CHECK(has(glsl, "struct Knobs {"));
    CHECK(has(glsl, "layout(push_constant, scalar) uniform KnobsPushConstants {"));
    CHECK(has(glsl, "} knobs;"));
  }
}
