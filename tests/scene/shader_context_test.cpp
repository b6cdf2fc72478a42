// scene/shader_context.hpp: who uses a failing stage, and why a generated name a shader calls is missing.
#include <proceduray/scene/compile.hpp>
#include <proceduray/scene/glsl_for.hpp>
#include <proceduray/scene/shader_context.hpp>
#include <proceduray/shader/field_list.hpp>

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <string>

namespace shader_context_test {
struct Light {
  glm::vec3 colour;
};
PROCEDURAY_STRUCT(Light, scalar, colour);
struct Hit {
  glm::vec3 normal;
};
PROCEDURAY_STRUCT(Hit, scalar, normal);
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<Light>, proceduray::RootComponent<>, proceduray::RootArguments<>,
                                   proceduray::Attributes<Hit>>;
using TestScene = proceduray::Scene<TestSceneInterface>;
}  // namespace shader_context_test

using namespace proceduray;
using namespace shader_context_test;

namespace {

/// Rays light and shadow; a procedural ball whose two groups share "ball.rint"; `tlas` names the
/// acceleration structure binding or leaves it unnamed.
Plan plan_of(bool tlas = true) {
  TestScene scene;
  auto light = scene.add_ray<Light>("light", {.miss = "sky.rmiss"});
  auto shadow = scene.add_ray<Light>("shadow", {.miss = "sky.rmiss"});  // one miss shader: one payload type
  scene.add_hit_group<Hit>("ball", {.kind = HitGroupKind::procedural, .closest_hit = "ball.rchit", .intersection = "ball.rint"});
  scene.add_hit_group<Hit>("ball_shadow", {.kind = HitGroupKind::procedural, .intersection = "ball.rint"});
  auto ball = scene.add_geometry("ball", GeometryDesc::procedural({Aabb{}}));
  auto global = scene.add_global_signature("global", {.bindings = {{BindingKind::acceleration_structure, 0, 0, 1,
                                                                    tlas ? "tlas" : ""}}});
  scene.add_raygen("main.rgen");
  scene.set_global_signature(global);
  scene.add_hit(light, scene.hit_group_id("ball"), ball);
  scene.add_hit(shadow, scene.hit_group_id("ball_shadow"), ball);
  return compile(scene);
}

std::uint32_t stage_index(const Plan& plan, ShaderStage stage, const char* shader) {
  const auto& stages = plan.pipeline().stages;
  for (std::uint32_t i = 0; i < stages.size(); ++i) {
    if (stages[i].stage == stage && stages[i].shader == shader) return i;
  }
  FAIL("no such stage");
  return 0;
}

bool has(const std::string& text, const char* piece) { return text.find(piece) != std::string::npos; }

}  // namespace

TEST_CASE("stage_users names the entities whose groups run a stage") {
  const Plan plan = plan_of();
  CHECK(stage_users(plan, stage_index(plan, ShaderStage::raygen, "main.rgen")) == "raygen \"main.rgen\"");
  CHECK(stage_users(plan, stage_index(plan, ShaderStage::miss, "sky.rmiss")) ==
        "the miss shader of rays \"light\", \"shadow\"");
  CHECK(stage_users(plan, stage_index(plan, ShaderStage::closest_hit, "ball.rchit")) ==
        "hit groups \"ball\" (ray \"light\")");
  CHECK(stage_users(plan, stage_index(plan, ShaderStage::intersection, "ball.rint")) ==
        "hit groups \"ball\" (ray \"light\"), \"ball_shadow\" (ray \"shadow\")");
  CHECK(stage_users(plan, 99).empty());
}

TEST_CASE("generated_name_hint names the ray a trace function lacks, and the declared ones") {
  const Plan plan = plan_of();
  const std::string undeclared = generated_name_hint(
      plan, ShaderStage::closest_hit, "ERROR: x.rchit:3: 'trace_glow' : no matching overloaded function found \n");
  CHECK(has(undeclared, "trace_glow is not generated: the scene declares no ray \"glow\" (its rays: \"light\", \"shadow\")"));
  // A declared ray in a stage Vulkan does not let trace.
  const std::string isect = generated_name_hint(plan, ShaderStage::intersection,
                                                "ERROR: x.rint:2: 'trace_light' : no matching overloaded function found");
  CHECK(has(isect, "trace_light is not generated for intersection shaders"));
  // A declared ray in a tracing stage: the error is something else.
  CHECK(generated_name_hint(plan, ShaderStage::raygen, "ERROR: x:2: 'trace_light' : no matching overloaded function found")
            .empty());
  CHECK(generated_name_hint(plan, ShaderStage::raygen, "ERROR: x:2: 'y' : undeclared identifier").empty());
  // No named acceleration structure: no trace functions at all.
  const std::string unnamed = generated_name_hint(plan_of(false), ShaderStage::raygen,
                                                  "ERROR: x:2: 'trace_light' : undeclared identifier");
  CHECK(has(unnamed, "names no acceleration structure binding"));
}

TEST_CASE("bad input: a ray with no miss shader traced without a payload is refused, naming the fix") {
  TestScene scene;
  auto light = scene.add_ray<Light>("light", {});  // no miss shader
  scene.add_hit_group<Hit>("ball", {.kind = HitGroupKind::procedural, .closest_hit = "ball.rchit", .intersection = "ball.rint"});
  auto ball = scene.add_geometry("ball", GeometryDesc::procedural({Aabb{}}));
  auto global = scene.add_global_signature("global", {.bindings = {{BindingKind::acceleration_structure, 0, 0, 1, "tlas"}}});
  scene.add_raygen("main.rgen");
  scene.set_global_signature(global);
  scene.add_hit(light, scene.hit_group_id("ball"), ball);
  const Plan plan = compile(scene);
  // Only the form whose payload a miss returns: a miss can never hand back uninitialised memory.
  const std::string glsl = glsl_for(plan, ShaderStage::raygen, "main.rgen");
  CHECK(has(glsl, "Light trace_light(vec3 origin, float tmin, vec3 direction, float tmax, Light p) { light = p; "));
  CHECK_FALSE(has(glsl, "void trace_light("));
  const std::string hint = generated_name_hint(plan, ShaderStage::raygen,
                                               "ERROR: x.rgen:4: 'trace_light' : no matching overloaded function found");
  CHECK(has(hint, "trace_light(origin, tmin, direction, tmax) is not generated: ray \"light\" has no miss shader, so a "
                  "miss would leave its payload uninitialised; pass the payload a miss returns, "
                  "trace_light(origin, tmin, direction, tmax, p), or give the ray a miss shader (RayDesc::miss)"));
}
