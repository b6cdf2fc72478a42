// examples/03_d3d12_scene/accuracy.hpp: the D3D12 sample's scene rendered on the device with
// per-pixel outputs and measured against its double-precision ground truth (reference.hpp),
// per object. The analytic objects (ground, box, spheres) and the metaballs' refined field
// must match to float rounding; the SDFs are held to the bounds the sphere tracer's hit rule
// gives (a hit within threshold / 32 of the crossing) and to the normal error of central
// differences at the threshold (the tetrahedral form's was 5 to 20 times larger here).
#include "test_knobs.hpp"
#include "vk/test_context.hpp"

#include <03_d3d12_scene/accuracy.hpp>
#include <proceduray/accuracy/samples.hpp>

#include <doctest/doctest.h>

#include <vector>

using namespace proceduray;

namespace {

constexpr std::uint32_t width = 96;
constexpr std::uint32_t height = 64;

struct Measured {
  std::vector<accuracy::Sample> samples;
  std::vector<std::uint32_t> seen;
  d3d12::ReferenceImage truth;
  std::vector<std::uint8_t> rgba;
};

Measured measure_d3d12(const vk::Context& ctx, const d3d12::SceneConstants& constants) {
  const d3d12::D3d12Scene scene(d3d12::accuracy_outputs);
  vk::Renderer renderer(ctx, scene, d3d12::renderer_options());
  d3d12::set_frame(renderer, constants);
  const vk::Frame f = renderer.render(width, height);
  Measured m;
  m.samples = accuracy::samples_from(std::size_t{width} * height, f.outputs.t, f.outputs.normal, f.outputs.steps, f.outputs.flags);
  m.seen = d3d12::device_objects(renderer.plan(), f.outputs.ids);
  m.truth = d3d12::reference_image(constants, width, height);
  m.rgba = f.rgba;
  return m;
}

d3d12::SceneConstants camera_rays_only() {
  d3d12::SceneConstants c = test_knobs::pinned(d3d12::default_constants(d3d12::sample_camera(width, height), 0.0f));
  c.flags = 0;
  return c;
}

accuracy::Metrics of(const Measured& m, d3d12::PrimitiveKind kind) {
  return d3d12::measure_object(m.truth, m.samples, m.seen, d3d12::object_id(kind));
}

}  // namespace

TEST_CASE("d3d12 accuracy: the ground and the analytic and metaball primitives match to float rounding") {
  TestContext t;
  const Measured m = measure_d3d12(t.ctx, camera_rays_only());
  for (const d3d12::PrimitiveKind kind : {d3d12::box, d3d12::spheres, d3d12::metaballs}) {
    const accuracy::Metrics a = of(m, kind);
    INFO("object " << d3d12::object_name(d3d12::object_id(kind)));
    CHECK(a.all.both_hit > 20);
    CHECK(a.all.false_hits == 0);
    CHECK(a.all.false_misses == 0);
    CHECK(a.all.depth.max < 1e-3);           // footprints (seen: metaballs 1e-4, the rest 2e-5)
    // Degrees. Seen: metaballs 8e-4 with fixed steps, 0.021 with segment tracing (their default
    // since 0.2.0: its crossing step, bisected 10 times, can be longer), the rest below 1e-3.
    CHECK(a.all.normal_degrees.max < (kind == d3d12::metaballs ? 0.05 : 1e-2));
  }
  const accuracy::Metrics ground = d3d12::measure_object(m.truth, m.samples, m.seen, d3d12::plane_id);
  CHECK(ground.all.both_hit > 1000);
  CHECK(ground.all.false_hits + ground.all.false_misses <= 2);  // seen: 1, behind an SDF's silhouette
  CHECK(ground.all.depth.max < 1e-3);
  const accuracy::Metrics scene = accuracy::measure(m.truth.frame(), m.samples, m.truth.pixels);
  CHECK(scene.all.nonfinite == 0);  // no NaN or Inf in any output (scenario 17)
  CHECK(scene.all.undetermined == 0);
  CHECK(scene.all.exhausted == 0);
}

TEST_CASE("d3d12 accuracy: SDF hits lie within the hit rule and their normals are central differences") {
  TestContext t;
  const Measured m = measure_d3d12(t.ctx, camera_rays_only());
  std::size_t hits = 0;
  for (std::uint32_t k = d3d12::mini_spheres; k <= d3d12::fractal_pyramid; ++k) {
    const auto kind = static_cast<d3d12::PrimitiveKind>(k);
    const accuracy::Metrics a = of(m, kind);
    INFO("object " << d3d12::object_name(d3d12::object_id(kind)));
    hits += a.all.both_hit;
    CHECK(a.all.false_hits + a.all.false_misses <= 1);
    CHECK(a[accuracy::PixelClass::interior].false_hits == 0);
    // Hits are bisected to threshold / 32 = 1/64 footprint of the crossing (seen: max 0.0155).
    CHECK(a.all.depth.median < 0.02);
    if (kind != d3d12::fractal_pyramid) CHECK(a.all.depth.max < 0.02);
    // The pyramid: one ray (seen: 7.6 footprints) steps over a ledge thinner than a threshold.
    if (kind == d3d12::fractal_pyramid) CHECK(a.all.depth.p99 < 10.0);
  }
  CHECK(hits > 300);
  // Normal error medians, degrees, central differences at the threshold (seen: mini spheres 1.1,
  // round cube 0.03, square torus 2.0, twisted torus 1.9, cylinder 0.6, cog 14); the tetrahedral
  // form at the same offset gave 6.8, 1.2, 17.7, 22.2, 7.3 and 32.5.
  for (const d3d12::PrimitiveKind kind :
       {d3d12::mini_spheres, d3d12::round_cube, d3d12::square_torus, d3d12::twisted_torus, d3d12::cylinder}) {
    INFO("object " << d3d12::object_name(d3d12::object_id(kind)));
    CHECK(of(m, kind).all.normal_degrees.median < 3.0);
  }
  CHECK(of(m, d3d12::cog).all.normal_degrees.median < 20.0);
}

TEST_CASE("d3d12 accuracy: outputs do not change the colour image") {
  TestContext t;
  const d3d12::SceneConstants c =
      test_knobs::pinned(d3d12::default_constants(d3d12::sample_camera(width, height), 0.0f));  // all rays
  const Measured with = measure_d3d12(t.ctx, c);
  const d3d12::D3d12Scene plain;
  vk::Renderer renderer(t.ctx, plain, d3d12::renderer_options());
  d3d12::set_frame(renderer, c);
  const vk::Frame without = renderer.render(width, height);
  CHECK(without.outputs.t.empty());
  CHECK(with.rgba == without.rgba);
}
