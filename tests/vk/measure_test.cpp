// Tests for proceduray/vk/measure.hpp: a field measured on the device against its own GLSL in
// double. The truth equals the closed form (ball); a good setting measures near-exact, a coarse
// one worse; the truth is reused from memory and disk and redone when the GLSL changes; bad
// views, knobs and bounds are refused.
#include "test_context.hpp"
#include "test_fields.hpp"
#include "test_paths.hpp"

#include <proceduray/accuracy/closed_form.hpp>
#include <proceduray/vk/measure.hpp>

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>


namespace {

namespace pr = proceduray;
namespace acc = proceduray::accuracy;

using test_fields::ball_cpu;
using test_fields::gyroid_cpu;

const pr::DistanceField ball_field{.id = "ball", .glsl = "ball.glsl", .aabb = {glm::vec3(-1.0f), glm::vec3(1.0f)},
                                   .exact = true};
const pr::DistanceField gyroid_field{.id = "gyroid", .glsl = "gyroid.glsl",
                                     .aabb = {glm::vec3(-1.0f), glm::vec3(1.0f)}, .lipschitz = 1.75f};

pr::vk::MeasureOptions options(std::filesystem::path cache = {}) {
  return {.shader_dirs = {test_source_dir() / "vk" / "shaders" / "fields", test_source_dir() / ".." / "examples" / "06_your_field" / "shaders"},
          .cache_dir = std::move(cache), .repeats = 2};
}

pr::vk::MeasureView view(std::uint32_t w = 96, std::uint32_t h = 72) {
  return {pr::look_at({0.3f, 0.8f, 3.0f}, {0.0f, 0.0f, 0.0f}, 50.0f, w, h), w, h};
}

std::size_t errors(const pr::vk::Measurement& m) {
  return m.metrics.all.false_hits + m.metrics.all.false_misses + m.wrong_surface;
}

}  // namespace

TEST_CASE("measure: the truth of a ball field is the closed form's, and its default setting measures near-exact") {
  TestContext t;
  pr::vk::FieldMeter meter(t.ctx, ball_field, options());
  const pr::vk::MeasureView v = view();
  bool cached = true;
  const pr::vk::ViewTruth& truth = meter.truth_of(ball_cpu, v, cached);
  CHECK_FALSE(cached);
  std::size_t hits = 0;
  for (std::uint32_t y = 0; y < v.height; ++y) {
    for (std::uint32_t x = 0; x < v.width; ++x) {
      const glm::dvec3 d = pr::vk::detail::measure_direction(v.camera, x, y, v.width, v.height);
      const acc::Result c = acc::intersect_sphere(glm::dvec3(v.camera.eye), d, glm::dvec3(0.0), 1.0, 0.0, 1e30);
      const acc::Reference& r = truth.sample.pixels[std::size_t{y} * v.width + x];
      REQUIRE(r.outcome == c.outcome);
      if (c.outcome != acc::Outcome::hit) continue;
      ++hits;
      CHECK(std::abs(r.t - c.t) < 1e-9);
      CHECK(glm::length(r.normal - c.normal) < 1e-6);
    }
  }
  CHECK(hits > v.width * v.height / 8);
  const pr::vk::Measurement m = meter.measure(ball_cpu, pr::march_base_knobs, v);
  CHECK(m.truth_cached);  // truth_of above computed it
  CHECK(m.metrics.all.both_hit > hits * 98 / 100);
  CHECK(errors(m) <= hits / 100);
  CHECK(m.metrics.all.depth.median < 0.1);   // footprints: refined hits
  CHECK(m.metrics.all.depth.p99 < 2.0);
  CHECK(m.metrics[acc::PixelClass::interior].normal_degrees.p95 < 1.0);
  CHECK(m.evaluations_per_ray > 1.0);
  CHECK(m.gpu_ms > 0.0);
  // Every ray in one class of the split, its evaluations the frame's; a ray grazing the ball
  // marches longer than one that misses it by far, or than one that hits it head on.
  const acc::EvaluationSplit& e = m.evaluation_split;
  CHECK(e.hit.rays + e.near_miss.rays + e.far_miss.rays == double(v.width) * v.height);
  CHECK(e.hit.rays == double(hits));
  CHECK(e.evaluations() == doctest::Approx(m.evaluations_per_ray * v.width * v.height));
  CHECK(e.near_miss.per_ray() > e.far_miss.per_ray());
  CHECK(e.near_miss.per_ray() > e.hit.per_ray() - 6.0);  // the hits' include the normal's 6
}

TEST_CASE("measure: a coarse setting of a field with L > 1 measures worse than the default") {
  TestContext t;
  pr::vk::FieldMeter meter(t.ctx, gyroid_field, options());
  const pr::vk::Measurement good = meter.measure(gyroid_cpu, meter.capabilities().defaults, view());
  CHECK_FALSE(good.truth_cached);
  CHECK(good.truth_ms > 0.0);
  const std::size_t hits = good.metrics.all.both_hit + good.metrics.all.false_misses;
  CHECK(hits > 500);
  CHECK(errors(good) <= hits / 100);
  pr::MarchKnobs coarse = meter.capabilities().defaults;
  coarse.method = pr::MarchMethod::fixed;  // equal steps: thin sheets between two steps are missed
  coarse.fixed_steps = 6;
  const pr::vk::Measurement bad = meter.measure(gyroid_cpu, coarse, view());
  CHECK(bad.truth_cached);
  CHECK(errors(bad) > 3 * errors(good) + 20);
  CHECK(bad.evaluations_per_ray < good.evaluations_per_ray);  // cheaper, and that is what it costs
  pr::MarchKnobs sphere = meter.capabilities().defaults;
  sphere.method = pr::MarchMethod::sphere;  // assumes L = 1
  CHECK_THROWS_WITH_AS(meter.measure(gyroid_cpu, sphere, view()), doctest::Contains("method sphere does not apply"),
                       pr::UsageError);
}

TEST_CASE("measure: a stratified truth traces a fraction of the pixels and bounds the rates it estimates") {
  TestContext t;
  pr::MarchKnobs coarse = pr::field_capabilities(gyroid_field).defaults;
  coarse.method = pr::MarchMethod::fixed;  // misses thin sheets: rates to estimate
  coarse.fixed_steps = 6;
  const pr::vk::MeasureView v = view(192, 144);
  pr::vk::FieldMeter full(t.ctx, gyroid_field, options());
  pr::vk::MeasureOptions o = options();
  o.interior_stride = 8;
  pr::vk::FieldMeter sampled(t.ctx, gyroid_field, o);
  const pr::vk::Measurement exact = full.measure(gyroid_cpu, coarse, v), est = sampled.measure(gyroid_cpu, coarse, v);
  CHECK(exact.truth_traced == std::size_t{v.width} * v.height);
  CHECK(exact.confidence.false_miss_rate_95 == exact.confidence.false_miss_rate);
  CAPTURE(est.truth_traced);
  CHECK(est.truth_traced < std::size_t{v.width} * v.height);
  const double misses = exact.metrics.all.false_miss_rate();
  CAPTURE(misses);
  CAPTURE(est.confidence.false_miss_rate);
  CAPTURE(est.confidence.false_miss_rate_95);
  REQUIRE(misses > 0.0);
  CHECK(est.confidence.false_miss_rate_95 >= exact.confidence.false_miss_rate);
  CHECK(est.confidence.false_miss_rate == doctest::Approx(exact.confidence.false_miss_rate).epsilon(0.5));
  // The silhouettes are traced in full: their false hits are counted, not estimated.
  CHECK(est.metrics[acc::PixelClass::silhouette_1px].false_hits == exact.metrics[acc::PixelClass::silhouette_1px].false_hits);
  pr::vk::MeasureOptions zero = options();
  zero.interior_stride = 0;
  CHECK_THROWS_WITH_AS(pr::vk::FieldMeter(t.ctx, gyroid_field, zero),
                       doctest::Contains("interior_stride is 0; give 1 (the truth of every pixel) to 1024"),
                       pr::UsageError);
}

TEST_CASE("measure: the truth is kept on disk, reused by another meter, and redone when the GLSL changes") {
  TestContext t;
  const std::filesystem::path dir = test_output_dir("measure_cache");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "shaders");
  std::filesystem::copy_file(test_source_dir() / "vk" / "shaders" / "fields" / "ball.glsl", dir / "shaders" / "ball.glsl");
  pr::vk::MeasureOptions o{.shader_dirs = {dir / "shaders"}, .cache_dir = dir / "cache", .repeats = 1};
  double first_median = 0.0;
  {
    pr::vk::FieldMeter meter(t.ctx, ball_field, o);
    const pr::vk::Measurement m = meter.measure(ball_cpu, pr::march_base_knobs, view(48, 36));
    CHECK_FALSE(m.truth_cached);
    first_median = m.metrics.all.depth.median;
  }
  {
    pr::vk::FieldMeter meter(t.ctx, ball_field, o);
    const pr::vk::Measurement m = meter.measure(ball_cpu, pr::march_base_knobs, view(48, 36));
    CHECK(m.truth_cached);
    CHECK(m.metrics.all.depth.median == first_median);
    CHECK_FALSE(meter.measure(ball_cpu, pr::march_base_knobs, view(50, 36)).truth_cached);  // another view
  }
  std::ofstream(dir / "shaders" / "ball.glsl", std::ios::app) << "// changed\n";
  pr::vk::FieldMeter meter(t.ctx, ball_field, o);
  CHECK_FALSE(meter.measure(ball_cpu, pr::march_base_knobs, view(48, 36)).truth_cached);
}

TEST_CASE("measure: bad views, a bound the field exceeds and a missing file are refused") {
  TestContext t;
  pr::vk::FieldMeter meter(t.ctx, ball_field, options());
  pr::vk::MeasureView v = view();
  v.width = 0;
  CHECK_THROWS_WITH_AS(meter.measure(ball_cpu, pr::march_base_knobs, v), doctest::Contains("view size 0x72"),
                       pr::UsageError);
  v = view();
  v.camera.pixel_angle = 0.0f;
  CHECK_THROWS_WITH_AS(meter.measure(ball_cpu, pr::march_base_knobs, v), doctest::Contains("look_at"), pr::UsageError);
  pr::DistanceField low = gyroid_field;
  low.lipschitz = 1.0f;  // the gyroid's slope reaches 1.73
  pr::vk::FieldMeter wrong(t.ctx, low, options());
  CHECK_THROWS_WITH_AS(wrong.measure(gyroid_cpu, pr::march_base_knobs, view()),
                       doctest::Contains("above its declared Lipschitz bound 1"), pr::UsageError);
  pr::DistanceField missing = ball_field;
  missing.glsl = "nowhere.glsl";
  CHECK_THROWS_WITH_AS(pr::vk::FieldMeter(t.ctx, missing, options()), doctest::Contains("nowhere.glsl"),
                       pr::UsageError);
}

namespace {
/// The uniform an animated field reads its radius from (sized_ball.glsl), as a user's scene declares it.
struct Animation {
  float radius = 1.0f;
  float time = 0.0f;
};
PROCEDURAY_STRUCT(Animation, scalar, radius, time);
constexpr pr::UniformSlot<Animation> animation_slot{.binding = 2, .name = "constants"};
struct Other {
  float radius = 1.0f;
};
PROCEDURAY_STRUCT(Other, scalar, radius);

pr::DistanceField sized_field() {
  return {.id = "sized", .glsl = "sized_ball.glsl", .function = "sized_ball_distance",
          .aabb = {glm::vec3(-1.0f), glm::vec3(1.0f)}, .exact = true,
          .parameters = {pr::field_parameter(animation_slot, &Animation::radius)}};
}
}  // namespace

TEST_CASE("measure: a field reading a uniform is measured at the values set, and its truth kept per value") {
  TestContext t;
  pr::vk::FieldMeter meter(t.ctx, sized_field(), options());
  const pr::vk::MeasureView v = view();
  const auto at = [](double radius) {
    return [radius](glm::dvec3 p) { return test_fields::sized_ball<double>::sized_ball_distance(p, radius); };
  };
  // No value yet: the render would read garbage, so measure refuses and names set().
  CHECK_THROWS_WITH_AS(meter.measure(at(0.6), pr::march_base_knobs, v),
                       doctest::Contains("reads the uniform \"constants\" (its parameters), which has no value; call "
                                         "FieldMeter::set(slot, value)"),
                       pr::UsageError);
  meter.set(animation_slot, Animation{0.6f, 0.0f});
  const pr::vk::Measurement same = meter.measure(at(0.6), pr::march_base_knobs, v);
  CHECK_FALSE(same.truth_cached);
  CHECK(same.metrics.all.both_hit > 200);
  CHECK(errors(same) <= 4);
  CHECK(same.metrics.all.depth.median < 0.05);
  // The device reads the value set: at 0.5 against a truth at 0.6 (the key is the value set, not
  // the callable, so this truth is new), every rim pixel disagrees.
  meter.set(animation_slot, Animation{0.5f, 0.0f});
  const pr::vk::Measurement wrong = meter.measure(at(0.6), pr::march_base_knobs, v);
  CHECK_FALSE(wrong.truth_cached);
  CHECK(errors(wrong) > 40);
  // Back at 0.6, the truth comes from memory and agrees again.
  meter.set(animation_slot, Animation{0.6f, 0.0f});
  const pr::vk::Measurement again = meter.measure(at(0.6), pr::march_base_knobs, v);
  CHECK(again.truth_cached);
  CHECK(errors(again) == errors(same));
  // Another uniform, or another type under the field's uniform name, is refused.
  CHECK_THROWS_WITH_AS(meter.set(pr::UniformSlot<Animation>{.binding = 2, .name = "scene"}, Animation{}),
                       "FieldMeter::set: distance field \"sized\" reads no uniform \"scene\"; it reads \"constants\": set those",
                       pr::UsageError);
  CHECK_THROWS_WITH_AS(meter.set(pr::UniformSlot<Other>{.binding = 2, .name = "constants"}, Other{}),
                       doctest::Contains("uniform \"constants\" holds Animation"), pr::UsageError);
  CHECK(t.ctx.validation_messages().empty());
}
