// scene/callable.hpp: callables registered by id, their records in the callable region, and
// the callableDataEXT declarations glsl_for derives for them.
#include <proceduray/scene/compile.hpp>
#include <proceduray/scene/glsl_for.hpp>
#include <proceduray/shader/field_list.hpp>

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <cstring>
#include <optional>
#include <string>

using namespace proceduray;

namespace callable_test {
struct Light {
  glm::vec3 colour;
};
PROCEDURAY_STRUCT(Light, scalar, colour);
struct TintCall {
  glm::vec3 colour;
};
PROCEDURAY_STRUCT(TintCall, scalar, colour);
struct NoiseCall {
  glm::vec3 position;
  float value;
};
PROCEDURAY_STRUCT(NoiseCall, scalar, position, value);
struct TintArgs {
  glm::vec4 factor;
};
PROCEDURAY_STRUCT(TintArgs, scalar, factor);
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<Light, TintCall, NoiseCall>, proceduray::RootComponent<>, proceduray::RootArguments<TintArgs>,
                                   proceduray::Attributes<>>;
using TestScene = proceduray::Scene<TestSceneInterface>;
}  // namespace callable_test

using namespace callable_test;

namespace {
/// One ray, one triangle, two callables ("tint" with root arguments, "noise" without).
struct Fixture {
  TestScene scene;
  std::optional<Plan> sbt;
  CallableId<TintCall> tint;
  CallableId<NoiseCall> noise;
  Fixture() {
    auto light = scene.add_ray<Light>("light", {.miss = "sky.rmiss"});
    auto group = scene.add_hit_group("tri", {.closest_hit = "tri.rchit"});
    scene.add_geometry("tri", GeometryDesc::triangles({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}}));
    tint = scene.add_callable<TintCall>("tint", {.shader = "tint.rcall"});
    noise = scene.add_callable<NoiseCall>("noise", {.shader = "noise.rcall"});
    auto args = scene.add_local_signature<TintArgs>("tint_args");
    scene.add_raygen("main.rgen");
    scene.set_default_hit(light, group);
    scene.add_callable_record(tint, args, TintArgs{glm::vec4(0.5f, 1.0f, 2.0f, 0.0f)});
    sbt.emplace(compile(scene));
  }
};
bool has(const std::string& text, const char* piece) { return text.find(piece) != std::string::npos; }
}  // namespace

TEST_CASE("callables register by id with their data type") {
  Fixture f;
  CHECK(f.tint.index() == 0);
  CHECK(f.noise.index() == 1);
  CHECK(f.scene.callable_id<TintCall>("tint") == f.tint);
  CHECK(f.scene.callable(f.noise).data_size == sizeof(NoiseCall));
  CHECK_THROWS_WITH_AS(f.scene.callable_id<NoiseCall>("tint"), doctest::Contains("callable \"tint\" has data type"),
                       TypeMismatchError);
  CHECK_THROWS_WITH_AS(f.scene.callable_id("tnt"), doctest::Contains("tint"), UnknownIdError);
  CHECK_THROWS_WITH_AS(f.scene.add_callable<TintCall>("tint", {.shader = "x.rcall"}), doctest::Contains("tint"),
                       DuplicateIdError);
  CHECK_THROWS_WITH_AS(f.scene.add_callable<TintCall>("blank", {}),
                       doctest::Contains("Scene::add_callable: callable \"blank\" has no shader; set .shader"), SceneError);
}

TEST_CASE("callable records fill the callable region in callable order with their data") {
  Fixture f;
  const Plan& sbt = *f.sbt;
  const auto records = sbt.records(SbtRegionKind::callable);
  REQUIRE(records.size() == 2);
  const PipelinePlan& plan = sbt.pipeline();
  CHECK(plan.groups[records[0].group].name == "tint.rcall");
  CHECK(plan.groups[records[1].group].name == "noise.rcall");
  CHECK(plan.stages[plan.groups[records[1].group].general].stage == ShaderStage::callable);
  CHECK(plan.max_root_arguments_size[3] == sizeof(TintArgs));
  const SbtLayout layout = sbt.layout(DeviceLimits{});
  const SbtRegion& region = layout.regions[3];
  CHECK(region.count == 2);
  CHECK(region.stride >= layout.properties.handle_size + sizeof(TintArgs));
  CHECK(region.offset >= layout.regions[2].offset + layout.regions[2].size);
  const auto data = sbt.root_arguments(records[0]);
  REQUIRE(data.size() == sizeof(TintArgs));
  TintArgs back{};
  std::memcpy(&back, data.data(), sizeof back);
  CHECK(back.factor.z == 2.0f);
  CHECK(sbt.root_arguments(records[1]).empty());
  // The callable groups come after every hit group, so hit group handles keep their order.
  CHECK(records[0].group > sbt.records(SbtRegionKind::hit)[0].group);
}

TEST_CASE("a callable takes one entry") {
  Fixture f;
  const auto entries = f.scene.entries().all().size();
  CHECK_THROWS_WITH_AS(f.scene.add_callable_record(f.tint, f.scene.local_signature_id<TintArgs>("tint_args"), TintArgs{}),
                       doctest::Contains("Scene::add_callable_record: callable \"tint\" already has an entry"),
                       DuplicateIdError);
  CHECK(f.scene.entries().all().size() == entries);
  CHECK_THROWS_AS(f.scene.add_callable_record(CallableId<TintCall>(7), f.scene.local_signature_id<TintArgs>("tint_args"),
                                              TintArgs{}),
                  UnknownIdError);
}

TEST_CASE("glsl_for declares callable data for callers and the callee") {
  Fixture f;
  const std::string raygen = glsl_for(*f.sbt, ShaderStage::raygen, "main.rgen");
  CHECK(has(raygen, "struct TintCall {"));
  CHECK(has(raygen, "const uint tint_callable = 0u;"));
  CHECK(has(raygen, "const uint noise_callable = 1u;"));
  CHECK(has(raygen, "layout(location = 0) callableDataEXT TintCall tint_data;"));
  CHECK(has(raygen, "layout(location = 1) callableDataEXT NoiseCall noise_data;"));
  // The call function fills the callable index and data location from the declaration.
  CHECK(has(raygen, "TintCall tint_call(TintCall d) { tint_data = d; executeCallableEXT(tint_callable, 0); return tint_data; }"));
  CHECK(has(raygen, "NoiseCall noise_call(NoiseCall d) { noise_data = d; executeCallableEXT(noise_callable, 1);"));
  CHECK(has(glsl_for(*f.sbt, ShaderStage::closest_hit, "tri.rchit"), "callableDataEXT NoiseCall noise_data;"));
  CHECK(has(glsl_for(*f.sbt, ShaderStage::miss, "sky.rmiss"), "callableDataEXT TintCall tint_data;"));
  const std::string tint = glsl_for(*f.sbt, ShaderStage::callable, "tint.rcall");
  CHECK(has(tint, "layout(location = 2) callableDataInEXT TintCall call;"));  // past the outgoing ones
  CHECK(has(tint, "layout(shaderRecordEXT, scalar) buffer TintArgsRootArguments {"));
  CHECK_FALSE(has(tint, "callableDataEXT TintCall"));  // its own location is the incoming data
  CHECK(has(tint, "layout(location = 1) callableDataEXT NoiseCall noise_data;"));
  CHECK_FALSE(has(tint, "tint_call("));
  CHECK_FALSE(has(tint, "rayPayload"));  // callables do not trace rays
  const std::string noise = glsl_for(*f.sbt, ShaderStage::callable, "noise.rcall");
  CHECK(has(noise, "layout(location = 2) callableDataInEXT NoiseCall call;"));
  CHECK_FALSE(has(noise, "shaderRecordEXT"));
}
