// scene/outputs.hpp: which per-pixel outputs a scene asks for, and where compile() binds them.
#include <proceduray/scene/compile.hpp>
#include <proceduray/scene/default_global_signature.hpp>
#include <proceduray/scene/object.hpp>
#include <proceduray/scene/outputs.hpp>
#include <proceduray/scene/uniform_slot.hpp>
#include <proceduray/shader/field_list.hpp>

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <vector>

namespace outputs_test {
struct Light {
  glm::vec3 colour;
};
PROCEDURAY_STRUCT(Light, scalar, colour);
struct Hit {
  glm::vec3 normal;
};
PROCEDURAY_STRUCT(Hit, scalar, normal);
struct Globals {
  glm::vec4 sky;
};
PROCEDURAY_STRUCT(Globals, std430, sky);
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<Light>, proceduray::RootComponent<Globals>, proceduray::RootArguments<>,
                                   proceduray::Attributes<Hit>>;
using TestScene = proceduray::Scene<TestSceneInterface>;
}  // namespace outputs_test

using namespace proceduray;
using namespace outputs_test;

namespace {
/// One ray, one procedural object; `extra` global bindings beside the TLAS (0) and image (1).
TestScene scene_with(OutputSet outputs, std::vector<Binding> extra = {}) {
  TestScene s;
  const auto ray = s.add_ray<Light>("light", {.miss = "sky.rmiss"});
  s.set_global_signature(default_global_signature(std::move(extra)));
  s.add_raygen("cam.rgen");
  add_object<Hit>(s, "ball", {.geometry = GeometryDesc::procedural({Aabb{}}), .intersection = "ball.rint",
                              .closest_hit = {{ray, "ball.rchit"}}});
  s.set_outputs(outputs);
  return s;
}
}  // namespace

TEST_CASE("outputs set holds what was asked for, in Output order") {
  constexpr OutputSet set{Output::flags, Output::t};
  static_assert(set.has(Output::t) && set.has(Output::flags) && !set.has(Output::normal));
  std::vector<Output> order;
  set.each([&](Output o) { order.push_back(o); });
  CHECK(order == std::vector<Output>{Output::t, Output::flags});
  CHECK(OutputSet{}.empty());
  CHECK(OutputSet{Output::t} != OutputSet{Output::steps});
  CHECK(name(Output::normal) == "normal");
  CHECK(format_of(Output::ids).channels == 4);
  CHECK(format_of(Output::steps).unsigned_int);
}

TEST_CASE("outputs get set 0 bindings after the highest one the global signature uses") {
  constexpr UniformSlot<Globals> globals{.binding = 5, .name = "globals"};
  const Plan plan = compile(scene_with({Output::t, Output::steps}, {globals}));
  REQUIRE(plan.outputs().size() == 2);
  CHECK(plan.outputs()[0] == PlannedOutput{Output::t, 6});
  CHECK(plan.outputs()[1] == PlannedOutput{Output::steps, 7});
  // The pipeline's global signature carries them, so the descriptor set layout has them.
  const auto& bindings = plan.global_signature()->bindings;
  std::size_t outputs = 0;
  for (const Binding& b : bindings) {
    if (b.kind != BindingKind::output_image) continue;
    ++outputs;
    CHECK(b.set == 0);
    CHECK(b.name.empty());  // declared with its format by glsl_outputs, not by binding_glsl
  }
  CHECK(outputs == 2);
}

TEST_CASE("outputs without a global signature get one of their own") {
  TestScene s = scene_with({Output::normal});
  TestScene bare;
  const auto ray = bare.add_ray<Light>("light", {.miss = "sky.rmiss"});
  bare.add_raygen("cam.rgen");
  add_object<Hit>(bare, "ball", {.geometry = GeometryDesc::procedural({Aabb{}}), .intersection = "ball.rint",
                                 .closest_hit = {{ray, "ball.rchit"}}});
  bare.set_outputs({Output::normal});
  const Plan plan = compile(bare);
  REQUIRE(plan.global_signature() != nullptr);
  CHECK(plan.outputs()[0].binding == 0);
  CHECK(compile(scene_with({})).outputs().empty());
}

TEST_CASE("outputs change the plan but not its payloads, records or groups") {
  const Plan none = compile(scene_with({}));
  const Plan all = compile(scene_with({Output::t, Output::normal, Output::ids, Output::steps, Output::flags}));
  CHECK_FALSE(none == all);
  CHECK(none.pipeline().max_payload_size == all.pipeline().max_payload_size);
  CHECK(none.pipeline().groups.size() == all.pipeline().groups.size());
  CHECK(none.records(SbtRegionKind::hit).size() == all.records(SbtRegionKind::hit).size());
}

TEST_CASE("outputs binding declared by the user is refused, naming Scene::set_outputs") {
  TestScene s;
  CHECK_THROWS_WITH_AS(s.set_global_signature({.bindings = {{BindingKind::output_image, 3, 0, 1, "", nullptr}}}),
                       doctest::Contains("Scene::set_outputs"), SceneError);
}

TEST_CASE("outputs helpers reach every stage, output_hit only closest-hit and any-hit") {
  const Plan plan = compile(scene_with({Output::t, Output::flags}));
  const std::string& rgen = glsl_for(plan, ShaderStage::raygen, "cam.rgen");
  const std::string& rint = glsl_for(plan, ShaderStage::intersection, "ball.rint");
  const std::string& rchit = glsl_for(plan, ShaderStage::closest_hit, "ball.rchit");
  for (const std::string* text : {&rgen, &rint, &rchit}) {
    CHECK(text->find("#define PROCEDURAY_OUTPUTS 1") != std::string::npos);
    CHECK(text->find("void output_t(float v)") != std::string::npos);
    CHECK(text->find("#define output_normal(v)") != std::string::npos);
  }
  CHECK(rchit.find("void output_hit(vec3 n)") != std::string::npos);
  CHECK(rint.find("output_hit") == std::string::npos);
  CHECK(rgen.find("output_hit") == std::string::npos);
  const Plan none = compile(scene_with({}));
  const std::string& plain = glsl_for(none, ShaderStage::closest_hit, "ball.rchit");
  CHECK(plain.find("PROCEDURAY_OUTPUTS") == std::string::npos);
  CHECK(plain.find("#define output_hit(n)\n") != std::string::npos);
  CHECK(plain.find("image2D output_") == std::string::npos);
}
