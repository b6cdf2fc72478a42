// scene/recursion.hpp: the nesting depth derived from what each stage traces, and cycles found.
#include "proceduray/scene/recursion.hpp"

#include <doctest/doctest.h>

#include "proceduray/scene/compile.hpp"
#include "proceduray/shader/field_list.hpp"

#include <string>

using namespace proceduray;

namespace recursion_test {
struct Colour {
  glm::vec4 rgba;
};
struct Hit {
  glm::vec3 normal;
};
PROCEDURAY_STRUCT(Colour, scalar, rgba);
PROCEDURAY_STRUCT(Hit, scalar, normal);
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<Colour>, proceduray::RootComponent<>, proceduray::RootArguments<>,
                                   proceduray::Attributes<Hit>>;
using TestScene = proceduray::Scene<TestSceneInterface>;
}  // namespace recursion_test

namespace {
using recursion_test::Colour;
using recursion_test::TestScene;

/// Rays radiance (0) and shadow (1), a mirror ball whose closest hit may trace, a callable.
struct Mirror {
  TestScene scene;
  Plan plan;
  std::vector<StageTraces> traces;
  Mirror() {
    const auto radiance = scene.add_ray<Colour>("radiance", {.miss = "sky.rmiss"});
    const auto shadow = scene.add_ray<Colour>("shadow", {.miss = "shadow.rmiss"});
    const auto mirror = scene.add_hit_group<recursion_test::Hit>(
        "mirror", {.kind = HitGroupKind::procedural, .closest_hit = "mirror.rchit", .intersection = "ball.rint"});
    const auto occluder = scene.add_hit_group<recursion_test::Hit>(
        "occluder", {.kind = HitGroupKind::procedural, .closest_hit = "occluder.rchit", .intersection = "ball.rint"});
    const auto ball = scene.add_geometry("ball", GeometryDesc::procedural({Aabb{}}));
    scene.add_callable<Colour>("tint", {.shader = "tint.rcall"});
    scene.add_raygen("camera.rgen");
    scene.add_hit(radiance, mirror, ball);
    scene.add_hit(shadow, occluder, ball);
    plan = compile(scene);
    traces.resize(plan.pipeline().stages.size());
    at("camera.rgen").rays = {0};
  }
  StageTraces& at(std::string_view shader) {
    for (std::size_t i = 0; i < traces.size(); ++i) {
      if (plan.pipeline().stages[i].shader == shader) return traces[i];
    }
    FAIL("no stage " << std::string(shader));
    return traces[0];
  }
  RecursionNeed need() const { return recursion_need(plan, traces); }
};

}  // namespace

TEST_CASE("recursion raygen tracing only needs depth 1") {
  Mirror m;
  const RecursionNeed n = m.need();
  CHECK(n.bounded);
  CHECK(n.depth == 1);
  CHECK(n.path == "raygen 'camera.rgen' > ray \"radiance\"");
}

TEST_CASE("recursion a closest hit that traces shadow rays needs depth 2, with the chain named") {
  Mirror m;
  m.at("mirror.rchit").rays = {1};
  const RecursionNeed n = m.need();
  CHECK(n.bounded);
  CHECK(n.depth == 2);
  CHECK(n.path == "raygen 'camera.rgen' > ray \"radiance\" > closest_hit 'mirror.rchit' > ray \"shadow\"");
}

TEST_CASE("recursion a shadow ray whose closest hit traces shadow rays again is a cycle") {
  Mirror m;
  m.at("mirror.rchit").rays = {1};
  m.at("occluder.rchit").rays = {1};  // shadow > shadow: a cycle
  CHECK_FALSE(m.need().bounded);
  m.at("occluder.rchit").rays = {};
  m.at("shadow.rmiss").rays = {};
  CHECK(m.need().depth == 2);
}

TEST_CASE("recursion a closest hit that traces its own ray type is a cycle, named") {
  Mirror m;
  m.at("mirror.rchit").rays = {0, 1};
  const RecursionNeed n = m.need();
  CHECK_FALSE(n.bounded);
  CHECK(n.path == "raygen 'camera.rgen' > ray \"radiance\" > closest_hit 'mirror.rchit' > ray \"radiance\"");
}

TEST_CASE("recursion a miss shader that traces counts like a closest hit") {
  Mirror m;
  m.at("sky.rmiss").rays = {1};
  CHECK(m.need().depth == 2);
}

TEST_CASE("recursion a stage that calls callables traces what the callables trace") {
  Mirror m;
  m.at("tint.rcall").rays = {1};
  CHECK(m.need().depth == 1);  // nobody calls it
  m.at("mirror.rchit").calls = true;
  CHECK(m.need().depth == 2);
}

TEST_CASE("recursion an unknown payload location counts as any ray") {
  Mirror m;
  m.at("mirror.rchit").rays = {7};  // not a ray index
  CHECK_FALSE(m.need().bounded);   // may trace radiance again
  m.at("mirror.rchit").rays = {};
  m.at("mirror.rchit").any_ray = true;
  CHECK_FALSE(m.need().bounded);
}

TEST_CASE("settle_recursion puts the derived depth in the plan, and layout checks it against the device") {
  Mirror m;
  m.at("mirror.rchit").rays = {1};
  CHECK_FALSE(m.plan.pipeline().recursion_settled);
  m.plan.settle_recursion(m.traces, DeviceLimits{}, "Renderer");
  CHECK(m.plan.pipeline().recursion_settled);
  CHECK(m.plan.pipeline().max_recursion_depth == 2);
  CHECK(m.plan.pipeline().recursion_path ==
        "raygen 'camera.rgen' > ray \"radiance\" > closest_hit 'mirror.rchit' > ray \"shadow\"");
  DeviceLimits shallow{.max_ray_recursion_depth = 1, .device = "a shallow device"};
  CHECK_THROWS_WITH_AS(m.plan.layout(shallow),
                       doctest::Contains("Plan::layout: the scene's max recursion depth (raygen 'camera.rgen' > ray "
                                         "\"radiance\" > closest_hit 'mirror.rchit' > ray \"shadow\") is 2, a shallow "
                                         "device allows 1 (maxRayRecursionDepth)"),
                       DeviceLimitError);
  DeviceLimits deep = shallow;
  deep.max_ray_recursion_depth = 2;
  CHECK_NOTHROW((void)m.plan.layout(deep));
  // Settling checks the depth it derives against the device itself (layout() ran before it).
  Mirror again;
  again.at("mirror.rchit").rays = {1};
  CHECK_THROWS_WITH_AS(again.plan.settle_recursion(again.traces, shallow, "Renderer"),
                       doctest::Contains("Renderer: the shaders nest rays 2 deep (raygen 'camera.rgen' > ray \"radiance\" "
                                         "> closest_hit 'mirror.rchit' > ray \"shadow\"), a shallow device allows 1 "
                                         "(maxRayRecursionDepth)"),
                       DeviceLimitError);
  CHECK_FALSE(again.plan.pipeline().recursion_settled);
}

TEST_CASE("settle_recursion refuses a declared depth below the shaders' nesting, and a cycle with none declared") {
  {
    Mirror m;
    m.at("mirror.rchit").rays = {0, 1};  // reflections: radiance traces radiance
    CHECK_THROWS_WITH_AS(m.plan.settle_recursion(m.traces, DeviceLimits{}, "Renderer"),
                         doctest::Contains("Renderer: the shaders trace in a cycle (raygen 'camera.rgen' > ray "
                                           "\"radiance\" > closest_hit 'mirror.rchit' > ray \"radiance\")"),
                         UsageError);
    CHECK_FALSE(m.plan.pipeline().recursion_settled);
  }
  {
    Mirror m;  // the same cycle with a declared bound: the declared depth is final
    m.scene.set_max_recursion_depth(4);
    m.plan = compile(m.scene);
    m.at("mirror.rchit").rays = {0, 1};
    m.plan.settle_recursion(m.traces, DeviceLimits{});
    CHECK(m.plan.pipeline().max_recursion_depth == 4);
  }
  {
    Mirror m;
    m.scene.set_max_recursion_depth(1);
    m.plan = compile(m.scene);
    m.at("mirror.rchit").rays = {1};
    CHECK_THROWS_WITH_AS(m.plan.settle_recursion(m.traces, DeviceLimits{}, "Renderer"),
                         doctest::Contains("Renderer: the shaders nest rays 2 deep (raygen 'camera.rgen' > ray "
                                           "\"radiance\" > closest_hit 'mirror.rchit' > ray \"shadow\") but the "
                                           "scene declares max recursion depth 1"),
                         UsageError);
  }
  Mirror m;
  m.traces.pop_back();
  CHECK_THROWS_WITH_AS(m.plan.settle_recursion(m.traces, DeviceLimits{}), doctest::Contains("give one per pipeline().stages entry"),
                       UsageError);
}
