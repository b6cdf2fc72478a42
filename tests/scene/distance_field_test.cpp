// Tests for proceduray/scene/distance_field.hpp: a field registers the object add_object would,
// with the generated intersection stage; compile() plans its settings binding and source; a
// bad field changes nothing.
#include "proceduray/scene/distance_field.hpp"

#include "proceduray/scene/compile.hpp"
#include "proceduray/scene/default_global_signature.hpp"
#include "proceduray/scene/uniform_slot.hpp"

#include <doctest/doctest.h>

#include <string>

using namespace proceduray;

namespace distance_field_test {

struct Payload { glm::vec4 colour; };
struct Occlusion { std::uint32_t occluded; };
struct Material { glm::vec3 albedo; std::uint32_t id; };
struct Frame { glm::vec4 sky; float time; };
PROCEDURAY_STRUCT(Payload, scalar, colour);
PROCEDURAY_STRUCT(Occlusion, scalar, occluded);
PROCEDURAY_STRUCT(Material, scalar, albedo, id);
PROCEDURAY_STRUCT(Frame, scalar, sky, time);
using Interface = ShaderInterface<proceduray::Payload<Payload, Occlusion>, RootComponent<Frame>,
                                  RootArguments<Material>, Attributes<FieldHit>>;
constexpr UniformSlot<Frame> frame_slot{.binding = 2, .name = "frame"};

struct Rays {
  Scene<Interface> scene;
  RayId<Payload> radiance = scene.add_ray<Payload>("radiance", {.miss = "radiance.rmiss"});
  RayId<Occlusion> shadow = scene.add_ray<Occlusion>("shadow", {.miss = "shadow.rmiss"});
  LocalSignatureId<Material> material = scene.add_local_signature<Material>("material");
  Rays() {
    scene.add_raygen("raygen.rgen");
    scene.set_global_signature(default_global_signature({frame_slot}));
  }
};

DistanceFieldDesc gyroid(RayId<Payload> radiance) {
  return {.glsl = "gyroid.glsl", .aabb = {glm::vec3(-1.0f), glm::vec3(1.0f)}, .lipschitz = 1.75f,
          .closest_hit = {{radiance, "shade.rchit"}}};
}

}  // namespace distance_field_test

using namespace distance_field_test;

TEST_CASE("distance field: registers the object, and compile() plans its settings and its generated stage") {
  Rays r;
  const GeometryId g = add_distance_field(r.scene, "gyroid", gyroid(r.radiance), r.material, {{{1, 0, 0}, 7}});
  const GeometryId b = add_distance_field(r.scene, "ball", {.glsl = "ball.glsl", .exact = true,
                                                            .closest_hit = {{r.radiance, "shade.rchit"}}},
                                          r.material, {{{0, 1, 0}, 8}});
  CHECK(r.scene.geometry_id("gyroid") == g);
  CHECK(r.scene.hit_group_id("gyroid").valid());
  CHECK(r.scene.hit_group_id("gyroid_shadow").valid());
  REQUIRE(r.scene.fields().size() == 2);
  CHECK(r.scene.fields()[0].lipschitz == 1.75f);
  const Plan plan = compile(r.scene);
  REQUIRE(plan.fields().size() == 2);
  CHECK(plan.fields()[0].geometry == g);
  CHECK(plan.fields()[1].geometry == b);
  CHECK(plan.fields()[1].field.id == "ball");
  // The settings buffer: after the signature's bindings (0 TLAS, 1 image, 2 frame).
  CHECK(plan.field_binding() == 3);
  bool declared = false;
  for (const Binding& binding : plan.global_signature()->bindings) {
    declared = declared || (binding.binding == 3 && binding.kind == BindingKind::storage_buffer &&
                            binding.name == std::string(field_settings_name) && binding.type == &type_ops<FieldSettings>);
  }
  CHECK(declared);
  // Each field's intersection compiles its generated source (field i reads data[i]); files keep none.
  int generated = 0;
  for (const PlannedStage& s : plan.pipeline().stages) {
    CAPTURE(s.shader);
    if (s.stage != ShaderStage::intersection) {
      CHECK(s.source.empty());
      continue;
    }
    ++generated;
    const bool is_gyroid = s.shader == "gyroid.field.rint";
    CHECK((is_gyroid || s.shader == "ball.field.rint"));
    CHECK(s.source.find(is_gyroid ? "proceduray_fields.data[0]" : "proceduray_fields.data[1]") != std::string::npos);
    CHECK(s.declarations.find("FieldSettings") != std::string::npos);  // declared for the stage
    CHECK(s.declarations.find("hitAttributeEXT FieldHit hit") != std::string::npos);
  }
  CHECK(generated == 2);  // one per field: the shadow groups share the radiance groups' stage
}

TEST_CASE("distance field: parameters are uniform members passed per frame; compile() wants the uniform declared") {
  Rays r;
  DistanceFieldDesc d = gyroid(r.radiance);
  d.parameters = {field_parameter(frame_slot, &Frame::time), field_parameter(frame_slot, &Frame::sky)};
  d.iterations = 4;
  add_distance_field(r.scene, "gyroid", d, r.material, {{{1, 0, 0}, 7}});
  const Plan plan = compile(r.scene);
  REQUIRE(plan.fields().size() == 1);
  CHECK(plan.fields()[0].field.parameters.size() == 2);
  bool called = false;
  for (const PlannedStage& s : plan.pipeline().stages) {
    called = called || s.source.find("return gyroid_distance(p, iterations, frame.time, frame.sky);") != std::string::npos;
  }
  CHECK(called);
  // The same uniform under another name (or not declared at all) is no uniform the shader can read.
  Rays other;
  constexpr UniformSlot<Frame> elsewhere{.binding = 5, .name = "other"};
  DistanceFieldDesc e = gyroid(other.radiance);
  e.parameters = {field_parameter(elsewhere, &Frame::time)};
  add_distance_field(other.scene, "gyroid", e, other.material, {{{1, 0, 0}, 7}});
  try {
    (void)compile(other.scene);
    FAIL("a parameter of an undeclared uniform compiled");
  } catch (const SceneError& err) {
    const std::string m = err.what();
    CHECK(m.find("distance field \"gyroid\"") != std::string::npos);
    CHECK(m.find("other.time") != std::string::npos);
    CHECK(m.find("set_global_signature") != std::string::npos);
  }
  // A slot without a GLSL name cannot be read by a generated shader.
  constexpr UniformSlot<Frame> unnamed{.binding = 2};
  CHECK_THROWS_WITH_AS(field_parameter(unnamed, &Frame::time), doctest::Contains("has no GLSL name"), UsageError);
}

TEST_CASE("distance field: record parameters read the field's own hit record, of the records' type") {
  Rays r;
  DistanceFieldDesc d = gyroid(r.radiance);
  d.parameters = {field_parameter(r.material, &Material::albedo), field_parameter(frame_slot, &Frame::time)};
  add_distance_field(r.scene, "gyroid", d, r.material, {{{1, 0, 0}, 7}});
  const Plan plan = compile(r.scene);
  bool called = false;
  for (const PlannedStage& s : plan.pipeline().stages) {
    called = called || s.source.find("return gyroid_distance(p, arguments.albedo, frame.time);") != std::string::npos;
  }
  CHECK(called);
  // No records at all: the parameter would read what is not there.
  Rays none;
  DistanceFieldDesc e = gyroid(none.radiance);
  e.parameters = {field_parameter(none.material, &Material::id)};
  try {
    add_distance_field(none.scene, "gyroid", e);
    FAIL("a record parameter without records was accepted");
  } catch (const UsageError& err) {
    const std::string m = err.what();
    CHECK(m.find("arguments.id of Material records, but its records are none") != std::string::npos);
  }
  CHECK(none.scene.fields().empty());
}

TEST_CASE("distance field: starting knobs are the field's defaults, checked when declared") {
  Rays r;
  DistanceFieldDesc d = gyroid(r.radiance);
  MarchKnobs k = march_base_knobs;
  k.threshold = 2.0f;
  d.knobs = k;
  add_distance_field(r.scene, "gyroid", d, r.material, {{{1, 0, 0}, 7}});
  CHECK(compile(r.scene).fields()[0].caps.defaults.threshold == 2.0f);
  Rays bad;
  DistanceFieldDesc b = gyroid(bad.radiance);
  k.method = MarchMethod::sphere;  // L = 1.75: sphere steps overshoot
  b.knobs = k;
  CHECK_THROWS_WITH_AS(add_distance_field(bad.scene, "gyroid", b, bad.material, {{{1, 0, 0}, 7}}),
                       doctest::Contains("starting knobs"), UsageError);
  CHECK(bad.scene.fields().empty());  // nothing registered
}

TEST_CASE("distance field: a scene without fields plans no settings binding") {
  Rays r;
  const Plan plan = compile(r.scene);
  CHECK(plan.fields().empty());
  CHECK(plan.field_binding() == no_index);
  CHECK(plan.global_signature()->bindings.size() == 3);
}

TEST_CASE("distance field: a bad field or object changes nothing") {
  Rays r;
  DistanceFieldDesc bad = gyroid(r.radiance);
  bad.lipschitz = -2.0f;
  CHECK_THROWS_WITH_AS(add_distance_field(r.scene, "gyroid", bad, r.material, {{{1, 0, 0}, 7}}),
                       doctest::Contains("add_distance_field: distance field \"gyroid\": Lipschitz bound -2"),
                       UsageError);
  CHECK(r.scene.find_geometry("gyroid") == nullptr);
  CHECK(r.scene.fields().empty());
  add_distance_field(r.scene, "gyroid", gyroid(r.radiance), r.material, {{{1, 0, 0}, 7}});
  // The same id again: the object's check (a geometry of that id exists), the field not recorded twice.
  CHECK_THROWS_AS(add_distance_field(r.scene, "gyroid", gyroid(r.radiance), r.material, {{{1, 0, 0}, 7}}),
                  DuplicateIdError);
  CHECK(r.scene.fields().size() == 1);
  // Two records for one instance: add_object's check, before the field is recorded.
  CHECK_THROWS_AS(add_distance_field(r.scene, "second", gyroid(r.radiance), r.material,
                                     {{{1, 0, 0}, 7}, {{0, 1, 0}, 8}}),
                  SceneError);
  CHECK(r.scene.fields().size() == 1);
}

namespace distance_field_test {

CalibrationRow calibrated(const char* geometry, MarchMethod method, double evals, double median,
                          std::uint32_t iterations = 0) {
  MarchKnobs k = march_base_knobs;
  k.method = method;
  k.iterations = iterations;
  return {geometry, "distance field", k, evals, median, 0.5, 0.0, 0.0, 1.0, 0.0};
}

}  // namespace distance_field_test

TEST_CASE("distance field: an error budget picks per field at compile time, never a method the field refuses") {
  Rays r;
  add_distance_field(r.scene, "gyroid", gyroid(r.radiance), r.material, {{{1, 0, 0}, 7}});
  // Plain sphere steps are cheapest and meet the budget on paper, but the gyroid's bound is 1.75.
  const Calibration table("test device", "320x240",
                          {calibrated("gyroid", MarchMethod::sphere, 9.0, 0.01),
                           calibrated("gyroid", MarchMethod::lipschitz, 14.0, 0.02),
                           calibrated("gyroid", MarchMethod::lipschitz, 20.0, 0.005)});
  r.scene.set_error_budget({}, table, 320, 240);
  const Plan plan = compile(r.scene);
  REQUIRE(plan.fields()[0].pick.has_value());
  CHECK(plan.fields()[0].pick->evals == 14.0);
  CHECK(plan.fields()[0].pick->knobs.method == MarchMethod::lipschitz);
  CHECK(plan.fields()[0].caps.defaults.method == MarchMethod::lipschitz);  // the renderer starts from the pick
  r.scene.set_error_budget({.depth_median = 0.01}, table, 320, 240);
  CHECK(compile(r.scene).fields()[0].pick->evals == 20.0);
  // Unmeetable: the best reachable setting is named.
  r.scene.set_error_budget({.depth_median = 0.001}, table, 320, 240);
  CHECK_THROWS_WITH_AS(compile(r.scene), doctest::Contains("no calibrated setting of 'gyroid' meets the budget"),
                       UsageError);
  CHECK_THROWS_WITH_AS(compile(r.scene), doctest::Contains("the best reachable: depth median 0.005"), UsageError);
  // A table with no rows for the field, or only rows it refuses.
  r.scene.set_error_budget({}, Calibration("d", "320x240", {calibrated("cog", MarchMethod::lipschitz, 9.0, 0.01)}),
                           320, 240);
  CHECK_THROWS_WITH_AS(compile(r.scene), doctest::Contains("has no rows for it; calibrate it"), UsageError);
  r.scene.set_error_budget({}, Calibration("d", "320x240", {calibrated("gyroid", MarchMethod::sphere, 9.0, 0.01)}),
                           320, 240);
  CHECK_THROWS_WITH_AS(compile(r.scene), doctest::Contains("1 rows for it, none a setting it accepts"), UsageError);
}

TEST_CASE("distance field: a budget does not carry across sizes; at 1080p a 4-iteration fractal is not picked") {
  Rays r;
  add_distance_field(r.scene, "bulb", {.glsl = "bulb.glsl", .exact = true, .iterations = 8,
                                       .closest_hit = {{r.radiance, "shade.rchit"}}},
                     r.material, {{{1, 0, 0}, 7}});
  // At 256x256, 4 iterations meet a 0.25-footprint median; measured at 1080p they give 0.39.
  const Calibration small("d", "256x256", {calibrated("bulb", MarchMethod::lipschitz, 20.0, 0.2, 4),
                                           calibrated("bulb", MarchMethod::lipschitz, 28.0, 0.05, 6)});
  r.scene.set_error_budget({.depth_median = 0.25}, small, 1920, 1080);
  CHECK_THROWS_WITH_AS(compile(r.scene), doctest::Contains("measured at 256x256, the frames are 1920x1080"),
                       UsageError);
  CHECK_THROWS_WITH_AS(compile(r.scene), doctest::Contains("calibrate at 1920x1080"), UsageError);
  const Calibration full("d", "1920x1080", {calibrated("bulb", MarchMethod::lipschitz, 20.0, 0.39, 4),
                                            calibrated("bulb", MarchMethod::lipschitz, 28.0, 0.12, 6)});
  r.scene.set_error_budget({.depth_median = 0.25}, full, 1920, 1080);
  const Plan plan = compile(r.scene);
  CHECK(plan.fields()[0].pick->knobs.iterations == 6);
  CHECK(plan.fields()[0].caps.defaults.iterations == 6);
}

TEST_CASE("bad input: Scene::set_error_budget with a negative bound") {
  Rays r;
  CHECK_THROWS_WITH_AS(r.scene.set_error_budget({.false_misses = -1.0}, Calibration("d", "320x240", {}), 320, 240),
                       doctest::Contains("Scene::set_error_budget: the error budget's false_misses is -1"), UsageError);
  CHECK_FALSE(r.scene.error_budget().has_value());  // refused, not stored
}
