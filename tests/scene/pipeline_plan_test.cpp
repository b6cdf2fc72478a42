// Tests for proceduray/scene/pipeline_plan.hpp: the stages, groups and sizes compile(scene) derives.
#include "proceduray/scene/pipeline_plan.hpp"

#include <doctest/doctest.h>

#include <algorithm>

#include "proceduray/scene/compile.hpp"
#include "proceduray/scene/glsl_for.hpp"
#include "scene_fixtures.hpp"

using namespace proceduray;
using namespace proceduray::test;
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<RayPayload, ShadowPayload>, proceduray::RootComponent<>, proceduray::RootArguments<>,
                                   proceduray::Attributes<FractalAttributes>>;
using TestScene = proceduray::Scene<TestSceneInterface>;

TEST_CASE("pipeline_plan report scene holds exactly the used stages and groups") {
  ReportScene r;
  build_report_scene(r);
  // A hit group no entry references is not in the plan.
  r.scene.add_hit_group<FractalAttributes>("Unused", {.kind = HitGroupKind::procedural, .closest_hit = "ClosestHit_Unused",
                                                      .intersection = "Intersection_Unused"});
  add_report_entries(r);
  const Plan sbt = compile(r.scene);
  const PipelinePlan& plan = sbt.pipeline();
  // 1 raygen + 2 miss + 8 hit groups.
  REQUIRE(plan.groups.size() == 11);
  CHECK(plan.groups[0].name == "Raygen");
  CHECK(plan.groups[0].type == GroupType::general);
  CHECK(plan.stages[plan.groups[0].general].stage == ShaderStage::raygen);
  CHECK(plan.groups[1].name == "Miss");
  CHECK(plan.groups[2].name == "Miss_Shadow");
  CHECK(plan.groups[3].name == "Triangle");
  CHECK(plan.groups[3].type == GroupType::triangles_hit);
  CHECK(plan.groups[3].intersection == unused_shader);
  CHECK(plan.groups[4].name == "Triangle_Shadow");
  CHECK(plan.groups[4].closest_hit == unused_shader);
  CHECK(std::none_of(plan.groups.begin(), plan.groups.end(), [](const PlannedGroup& g) { return g.name == "Unused"; }));
  CHECK(std::none_of(plan.stages.begin(), plan.stages.end(), [](const PlannedStage& s) { return s.shader == "ClosestHit_Unused"; }));
  // Stages appear once: 1 raygen, 2 miss, 4 closest-hit, 3 intersection shared by radiance and shadow groups.
  CHECK(plan.stages.size() == 1 + 2 + 4 + 3);
  const auto pacman = std::find_if(plan.groups.begin(), plan.groups.end(), [](const PlannedGroup& g) { return g.name == "Pacman"; });
  const auto pacman_shadow = std::find_if(plan.groups.begin(), plan.groups.end(), [](const PlannedGroup& g) { return g.name == "Pacman_Shadow"; });
  REQUIRE(pacman != plan.groups.end());
  REQUIRE(pacman_shadow != plan.groups.end());
  CHECK(pacman->type == GroupType::procedural_hit);
  CHECK(pacman->intersection == pacman_shadow->intersection);
  CHECK(plan.stages[pacman->intersection].shader == "Intersection_Pacman");
  CHECK(plan.stages[pacman->intersection].stage == ShaderStage::intersection);
  CHECK(pacman->hit_group == r.scene.hit_group_id("Pacman"));
  CHECK(pacman->attribute_size == sizeof(FractalAttributes));
  CHECK(plan.groups[3].attribute_size == triangle_attribute_size);
  CHECK(plan.groups[0].attribute_size == 0);  // general groups report none
  // Each stage carries its GLSL declarations, the text glsl_for returns.
  for (const PlannedStage& stage : plan.stages) {
    CHECK_FALSE(stage.declarations.empty());
    CHECK(glsl_for(sbt, stage.stage, stage.shader) == stage.declarations);
  }
  // Sizes are the scene's own maxima.
  CHECK(plan.max_recursion_depth == 3);
  CHECK(plan.recursion_depth_declared);
  CHECK(plan.max_payload_size == sizeof(RayPayload));
  CHECK(plan.max_attribute_size == sizeof(FractalAttributes));
  CHECK(plan.max_root_arguments_size[0] == 0);
  CHECK(plan.max_root_arguments_size[1] == 0);
  CHECK(plan.max_root_arguments_size[2] == sizeof(ProceduralRootArguments));
  CHECK(sbt.layout(lavapipe_limits).region(SbtRegionKind::hit).stride == detail::align_up(32 + sizeof(ProceduralRootArguments), 16));
  CHECK(plan.global_signature == r.scene.global_signature_id("Global"));
  CHECK(plan.local_signatures.size() == 2);
}

TEST_CASE("pipeline_plan triangles only scene reports the built-in attribute size") {
  TestScene s;
  const auto ray = s.add_ray<ShadowPayload>("r", {.miss = "m"});
  const auto group = s.add_hit_group("g", {.closest_hit = "c", .any_hit = "a"});
  s.add_hit_group<FractalAttributes>("p", {.kind = HitGroupKind::procedural, .intersection = "i"});
  const auto plane = s.add_geometry("plane", GeometryDesc::triangles({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}}));
  s.add_raygen("rgen");
  s.add_raygen("rgen");  // the same shader twice: two records, one group
  s.add_hit(ray, group, plane);
  const Plan sbt = compile(s);
  const PipelinePlan& plan = sbt.pipeline();
  CHECK(plan.max_attribute_size == triangle_attribute_size);
  CHECK(plan.max_payload_size == sizeof(ShadowPayload));
  CHECK(plan.groups.size() == 3);
  CHECK(plan.stages.size() == 4);  // rgen, m, c, a
  CHECK(sbt.records(SbtRegionKind::raygen).size() == 2);
  CHECK(sbt.records(SbtRegionKind::raygen)[0].group == sbt.records(SbtRegionKind::raygen)[1].group);
  CHECK(plan.max_recursion_depth == 1);
  CHECK_FALSE(plan.recursion_depth_declared);
  CHECK_FALSE(plan.global_signature.valid());
  CHECK(plan.local_signatures.empty());
}

TEST_CASE("pipeline_plan ray without miss shader gets a null miss record") {
  TestScene s;
  const auto ray = s.add_ray<ShadowPayload>("r", {});
  const auto group = s.add_hit_group("g", {.closest_hit = "c"});
  const auto plane = s.add_geometry("plane", GeometryDesc::triangles({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}}));
  s.add_raygen("rgen");
  s.add_hit(ray, group, plane);
  const Plan sbt = compile(s);
  REQUIRE(sbt.records(SbtRegionKind::miss).size() == 1);
  CHECK(sbt.records(SbtRegionKind::miss)[0].group == no_index);
  CHECK(sbt.pipeline().groups.size() == 2);
  // The ray's hit records use it: its payload counts though it has no miss shader.
  CHECK(sbt.pipeline().max_payload_size == sizeof(ShadowPayload));
  const SbtLayout layout = sbt.layout(lavapipe_limits);
  std::vector<std::byte> handles(2 * 32, std::byte{7});
  std::vector<std::byte> buffer(layout.size, std::byte{0xEE});
  sbt.write(layout, buffer, handles);
  const auto miss = layout.record_offset(SbtRegionKind::miss, 0);
  CHECK(std::all_of(buffer.begin() + static_cast<std::ptrdiff_t>(miss), buffer.begin() + static_cast<std::ptrdiff_t>(miss + 32),
                    [](std::byte b) { return b == std::byte{0}; }));
}

TEST_CASE("pipeline_plan gives an intersection shader one stage per any-hit it is paired with") {
  TestScene s;
  const auto ray = s.add_ray<RayPayload>("ray", {.miss = "miss"});
  const auto plain = s.add_hit_group<FractalAttributes>("plain", {.kind = HitGroupKind::procedural, .closest_hit = "hit",
                                                               .intersection = "ball.rint"});
  const auto also_plain = s.add_hit_group<FractalAttributes>("also_plain", {.kind = HitGroupKind::procedural,
                                                                         .intersection = "ball.rint"});
  const auto cut = s.add_hit_group<FractalAttributes>("cut", {.kind = HitGroupKind::procedural, .closest_hit = "hit",
                                                           .any_hit = "cut.rahit", .intersection = "ball.rint"});
  const auto g0 = s.add_geometry("g0", GeometryDesc::procedural({Aabb{}}));
  const auto g1 = s.add_geometry("g1", GeometryDesc::procedural({Aabb{}}));
  const auto g2 = s.add_geometry("g2", GeometryDesc::procedural({Aabb{}}));
  s.add_raygen("rgen");
  s.add_hit(ray, plain, g0);
  s.add_hit(ray, also_plain, g1);
  s.add_hit(ray, cut, g2);
  const Plan sbt = compile(s);
  const PipelinePlan& plan = sbt.pipeline();
  std::size_t intersections = 0;
  for (const PlannedStage& stage : plan.stages) intersections += stage.stage == ShaderStage::intersection ? 1 : 0;
  CHECK(intersections == 2);  // shared by the groups without any-hit, its own for the cut-out's
  const auto group = [&](const char* name) {
    for (const PlannedGroup& g : plan.groups)
      if (g.name == name) return g;
    FAIL("no group " << name);
    return PlannedGroup{};
  };
  CHECK(group("plain").intersection == group("also_plain").intersection);
  CHECK(group("plain").intersection != group("cut").intersection);
  CHECK(plan.stages[group("cut").intersection].shader == "ball.rint");
  CHECK(plan.stages[group("cut").any_hit].shader == "cut.rahit");
}

TEST_CASE("pipeline_plan recursion depth is declared only by set_max_recursion_depth") {
  TestScene s;
  const auto ray = s.add_ray<ShadowPayload>("r", {.miss = "m"});
  const auto group = s.add_hit_group("g", {.closest_hit = "c"});
  s.add_geometry("plane", GeometryDesc::triangles({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}}));
  s.add_raygen("rgen");
  s.set_default_hit(ray, group);
  // Undeclared: depth 1, and the plan says it was not declared (hit and miss shaders must not trace).
  const PipelinePlan undeclared = compile(s).pipeline();
  CHECK(undeclared.max_recursion_depth == 1);
  CHECK_FALSE(undeclared.recursion_depth_declared);
  // Declared as 1: the same depth, but declared.
  s.set_max_recursion_depth(1);
  const PipelinePlan one = compile(s).pipeline();
  CHECK(one.max_recursion_depth == 1);
  CHECK(one.recursion_depth_declared);
  CHECK_FALSE(one == undeclared);
  s.set_max_recursion_depth(4);
  const PipelinePlan four = compile(s).pipeline();
  CHECK(four.max_recursion_depth == 4);
  CHECK(four.recursion_depth_declared);
}

TEST_CASE("pipeline_plan max payload size ignores a ray type no record uses") {
  TestScene s;
  // "big" has no miss shader, and no geometry has instances: no record uses it.
  s.add_ray<RayPayload>("big", {});
  const auto small = s.add_ray<ShadowPayload>("small", {.miss = "small.rmiss"});
  const auto group = s.add_hit_group("g", {.closest_hit = "c"});
  const auto mesh = TriangleMesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}};
  const auto hidden = s.add_geometry("hidden", GeometryDesc::triangles(mesh, {}));
  s.add_raygen("rgen");
  s.add_hit(small, group, hidden);
  static_assert(sizeof(RayPayload) > sizeof(ShadowPayload));
  const Plan plan = compile(s);
  CHECK(plan.records(SbtRegionKind::hit).empty());
  REQUIRE(plan.records(SbtRegionKind::miss).size() == 2);
  CHECK(plan.records(SbtRegionKind::miss)[0].group == no_index);
  CHECK(plan.pipeline().max_payload_size == sizeof(ShadowPayload));
  // An instance gives "big" hit records: its payload counts then.
  s.add_geometry("seen", GeometryDesc::triangles(mesh));
  s.set_default_hit(s.ray_id<RayPayload>("big"), s.add_hit_group("big", {.closest_hit = "big.rchit"}));
  s.set_default_hit(small, group);
  const Plan seen = compile(s);
  CHECK(seen.records(SbtRegionKind::hit).size() == 2);
  CHECK(seen.pipeline().max_payload_size == sizeof(RayPayload));
}
