// Tests for proceduray/vk/calibrate.hpp: a field's preset measured on the device (no sphere
// steps past L = 1, a progress line per setting, every error recorded), the table reused from
// the cache folder and redone after the GLSL changes, and the pick of a budget reaching the
// renderer through compile().
#include "test_context.hpp"
#include "test_fields.hpp"
#include "test_paths.hpp"

#include <proceduray/proceduray.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>


namespace {

namespace pr = proceduray;

using test_fields::gyroid_cpu;
const pr::DistanceField gyroid_field{.id = "gyroid", .glsl = "gyroid.glsl",
                                     .aabb = {glm::vec3(-1.0f), glm::vec3(1.0f)}, .lipschitz = 1.75f};

pr::vk::MeasureView view() { return {pr::look_at({0.3f, 0.8f, 3.0f}, {0.0f, 0.0f, 0.0f}, 50.0f, 64, 48), 64, 48}; }

}  // namespace

TEST_CASE("calibrate: the preset of a field with L > 1 has no sphere steps and records every error") {
  const pr::MarchCapabilities caps = pr::field_capabilities(gyroid_field);
  const std::vector<pr::MarchKnobs> preset = pr::vk::field_preset(caps);
  CHECK(preset.size() >= 10);
  for (const pr::MarchKnobs& k : preset) {
    CHECK(k.method != pr::MarchMethod::sphere);
    CHECK_NOTHROW(pr::validate(k, caps, "gyroid"));
  }
  const pr::DistanceField bulb{.id = "bulb", .glsl = "bulb.glsl", .exact = true, .iterations = 8};
  bool fewer = false;
  for (const pr::MarchKnobs& k : pr::vk::field_preset(pr::field_capabilities(bulb))) fewer = fewer || k.iterations == 6;
  CHECK(fewer);  // a fractal's iterations are calibrated too
}

TEST_CASE("calibrate: measured once, reused from the cache, redone after the GLSL changes, picked by compile") {
  TestContext t;
  const std::filesystem::path dir = test_output_dir("calibrate_cache");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "shaders");
  std::filesystem::copy_file(test_source_dir() / ".." / "examples" / "06_your_field" / "shaders" / "gyroid.glsl", dir / "shaders" / "gyroid.glsl");
  const pr::vk::MeasureOptions measure{.shader_dirs = {dir / "shaders"}, .repeats = 1};
  std::vector<std::string> lines;
  pr::vk::CalibrateOptions o{.view = view(), .cache_dir = dir / "cache",
                             .progress = [&](const std::string& l) { lines.push_back(l); }};
  pr::Calibration table;
  {
    pr::vk::FieldMeter meter(t.ctx, gyroid_field, measure);
    const pr::vk::Calibrated c = pr::vk::calibrate(meter, gyroid_cpu, o);
    CHECK_FALSE(c.cached);
    CHECK(std::filesystem::exists(c.file));
    CHECK(lines.size() == pr::vk::field_preset(meter.capabilities()).size());
    CHECK(lines[0].find("calibrate gyroid: 1/") == 0);
    CHECK(c.table.size() == "64x48");
    REQUIRE(c.table.rows().size() >= 8);
    for (const pr::CalibrationRow& r : c.table.rows()) {
      CHECK(r.geometry == "gyroid");
      CHECK(r.evals > 1.0);
      CHECK(std::isfinite(r.wrong_surface));
    }
    table = c.table;
  }
  lines.clear();
  {
    pr::vk::FieldMeter meter(t.ctx, gyroid_field, measure);
    const pr::vk::Calibrated c = pr::vk::calibrate(meter, gyroid_cpu, o);
    CHECK(c.cached);
    CHECK(lines.empty());  // nothing measured
    CHECK(c.table.rows().size() == table.rows().size());
  }
  CHECK(table.device() == t.ctx.name());
  CHECK(table.source().find("gyroid glsl ") == 0);  // what was measured: the file's text
  const pr::Calibration before = table;
  std::ofstream(dir / "shaders" / "gyroid.glsl", std::ios::app) << "// changed\n";
  {
    pr::vk::FieldMeter meter(t.ctx, gyroid_field, measure);
    const pr::vk::Calibrated c = pr::vk::calibrate(meter, gyroid_cpu, o);
    CHECK_FALSE(c.cached);
    CHECK(c.table.source() != before.source());
    table = c.table;
  }
  // The default budget's pick reaches the renderer as the field's knobs.
  using Interface = pr::ShaderInterface<pr::Payload<pr::vk::detail::MeasurePayload>,
                                        pr::RootComponent<pr::vk::detail::MeasureConstants>, pr::RootArguments<>,
                                        pr::Attributes<pr::FieldHit>>;
  pr::Scene<Interface> scene;
  const auto ray = scene.add_ray<pr::vk::detail::MeasurePayload>("measure", {.miss = "measure/measure.rmiss"});
  scene.set_global_signature(pr::default_global_signature({pr::vk::detail::measure_constants}));
  scene.add_raygen("measure/measure.rgen");
  const pr::GeometryId g = pr::add_distance_field(scene, "gyroid", {.glsl = "gyroid.glsl", .lipschitz = 1.75f,
                                                                    .closest_hit = {{ray, "measure/measure.rchit"}}});
  const pr::vk::RendererOptions ro{.shader_dirs = {dir / "shaders", pr::vk::library_shader_dir()}};
  // A table measured for the file's old text, or on another device, is refused.
  scene.set_error_budget({}, before, 64, 48);
  CHECK_THROWS_WITH_AS(pr::vk::Renderer(t.ctx, scene, ro), doctest::Contains("calibrate it again"), pr::UsageError);
  scene.set_error_budget({}, pr::Calibration("Some GPU", "64x48", table.rows(), table.source()), 64, 48);
  CHECK_THROWS_WITH_AS(pr::vk::Renderer(t.ctx, scene, ro), doctest::Contains("was measured on Some GPU"),
                       pr::UsageError);
  scene.set_error_budget({}, table, 64, 48);
  const pr::CalibrationRow expected = table.cheapest("gyroid", {});
  pr::vk::Renderer r(t.ctx, scene, ro);
  CHECK(pr::describe(r.field_knobs(g)) == pr::describe(expected.knobs));
  CHECK(r.plan().fields()[0].pick->evals == expected.evals);
}

namespace {
struct Animation {
  float radius = 1.0f;
};
PROCEDURAY_STRUCT(Animation, scalar, radius);
constexpr pr::UniformSlot<Animation> animation_slot{.binding = 2, .name = "constants"};
}  // namespace

TEST_CASE("calibrate: a field reading a uniform is calibrated at the values set, and its table kept per value") {
  TestContext t;
  const std::filesystem::path dir = test_output_dir("calibrate_parameters");
  std::filesystem::remove_all(dir);
  const pr::DistanceField sized{.id = "sized", .glsl = "sized_ball.glsl", .function = "sized_ball_distance",
                                .aabb = {glm::vec3(-1.0f), glm::vec3(1.0f)}, .exact = true,
                                .parameters = {pr::field_parameter(animation_slot, &Animation::radius)}};
  pr::vk::FieldMeter meter(t.ctx, sized, {.shader_dirs = {test_source_dir() / "vk" / "shaders" / "fields"}, .repeats = 1});
  float radius = 0.6f;
  const auto cpu = [&](glm::dvec3 p) { return test_fields::sized_ball<double>::sized_ball_distance(p, radius); };
  const pr::vk::CalibrateOptions o{.view = view(), .settings = {pr::march_base_knobs}, .cache_dir = dir};
  CHECK_THROWS_WITH_AS(pr::vk::calibrate(meter, cpu, o), doctest::Contains("call FieldMeter::set(slot, value)"),
                       pr::UsageError);
  meter.set(animation_slot, {radius});
  const pr::vk::Calibrated first = pr::vk::calibrate(meter, cpu, o);
  CHECK_FALSE(first.cached);
  REQUIRE(first.table.rows().size() == 1);
  CHECK(first.table.rows()[0].false_misses <= 0.01);
  CHECK(pr::vk::calibrate(meter, cpu, o).cached);
  radius = 0.4f;  // the next frame of the animation: another table
  meter.set(animation_slot, {radius});
  const pr::vk::Calibrated second = pr::vk::calibrate(meter, cpu, o);
  CHECK_FALSE(second.cached);
  CHECK(second.file != first.file);
  CHECK(t.ctx.validation_messages().empty());
}
