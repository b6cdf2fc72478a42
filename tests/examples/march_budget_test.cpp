// The error budget end to end (march/calibration.hpp with the shipped table): for three
// budgets, the knobs the table picks for two D3D12 primitives, rendered alone on the device at
// the table's size with validation on, measure within the budget against the ground truth, and
// cost fewer evaluations per ray as the budget loosens.
#include "vk/test_context.hpp"

#include <03_d3d12_scene/accuracy.hpp>
#include <proceduray/accuracy/samples.hpp>
#include <proceduray/march/calibration.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <span>
#include <vector>

using namespace proceduray;

namespace {

struct Measured {
  accuracy::Metrics metrics;
  double evals = 0.0;  ///< per ray that sees the primitive, normal included
};

/// Primitive `kind` alone (Layout::isolated, its own camera), camera rays only, with `knobs`.
Measured render_alone(const vk::Context& ctx, d3d12::PrimitiveKind kind, const MarchKnobs& knobs, std::uint32_t width,
                      std::uint32_t height) {
  const auto prims = d3d12::default_primitives();
  const d3d12::D3d12Scene scene(prims, d3d12::Layout::isolated, d3d12::accuracy_outputs);
  vk::Renderer renderer(ctx, scene, d3d12::renderer_options());
  d3d12::SceneConstants c = d3d12::default_constants(d3d12::isolated_camera(kind, width, height), 0.0f);
  c.flags = 0;
  d3d12::knobs(c, kind) = knobs;
  d3d12::set_frame(renderer, c);
  const vk::Frame f = renderer.render(width, height);
  const std::vector<accuracy::Sample> samples =
      accuracy::samples_from(std::size_t{width} * height, f.outputs.t, f.outputs.normal, f.outputs.steps, f.outputs.flags);
  const std::vector<std::uint32_t> seen = d3d12::device_objects(renderer.plan(), f.outputs.ids);
  const d3d12::ReferenceImage truth = d3d12::reference_image(c, prims, d3d12::Layout::isolated, width, height);
  const std::uint32_t id = d3d12::object_id(kind);
  return {d3d12::measure_object(truth, samples, seen, id),
          examples::mean_steps(std::span<const std::uint32_t>(truth.objects), std::span<const accuracy::Sample>(samples),
                               std::span<const std::uint32_t>(seen), id)};
}

}  // namespace

TEST_CASE("march budget - three budgets are met on the device and looser ones cost less") {
  TestContext t;
  const Calibration table = Calibration::load(shipped_calibration());
  std::uint32_t width = 0, height = 0;
  REQUIRE(std::sscanf(table.size().c_str(), "%ux%u", &width, &height) == 2);
  // Tight, medium, loose: depth median and p99 in footprints, silhouette false hits, false
  // misses, wrong-surface hits.
  const std::array<ErrorBudget, 3> budgets{ErrorBudget{0.0015, 0.005, 0.0, 0.001, 0.001},
                                           ErrorBudget{0.008, 0.025, 0.0, 0.001, 0.001},
                                           ErrorBudget{0.25, 1.0, 0.01, 0.01, 0.01}};
  for (const d3d12::PrimitiveKind kind : {d3d12::round_cube, d3d12::cog}) {
    const std::string name(d3d12::primitive_names[kind]);
    std::array<double, 3> evals{};
    for (std::size_t b = 0; b < budgets.size(); ++b) {
      const CalibrationRow& pick = table.cheapest(name, budgets[b]);
      REQUIRE_NOTHROW(validate(pick.knobs, d3d12::capabilities(kind), name));
      const Measured m = render_alone(t.ctx, kind, pick.knobs, width, height);
      const accuracy::ClassStats& all = m.metrics.all;
      CAPTURE(name);
      CAPTURE(b);
      CAPTURE(describe(pick.knobs));
      CAPTURE(all.depth.median);
      CAPTURE(all.depth.p99);
      CAPTURE(m.evals);
      REQUIRE(all.both_hit > 1000);
      CHECK(all.depth.median <= budgets[b].depth_median);
      CHECK(all.depth.p99 <= budgets[b].depth_p99);
      const double fat = m.metrics[accuracy::PixelClass::silhouette_1px].false_hit_rate();
      CHECK((std::isnan(fat) || fat <= budgets[b].silhouette_false_hits));
      CHECK(all.false_miss_rate() <= budgets[b].false_misses);
      CHECK(all.wrong_surface_rate() <= budgets[b].wrong_surface);
      CHECK(all.nonfinite == 0);
      // The table's cost is what the device measures (evaluations do not depend on the machine).
      CHECK(m.evals == doctest::Approx(pick.evals).epsilon(0.02));
      evals[b] = m.evals;
    }
    CHECK(evals[0] > evals[1]);
    CHECK(evals[1] > evals[2]);
  }
}

TEST_CASE("march budget - the D3D12 primitives' defaults meet the default budget at another size") {
  // The defaults are picked from a table measured at 1920x1080 (march_defaults_test); at a third of
  // that size a footprint is 3 times wider, so the depth errors in footprints only shrink, and the
  // rates must hold on their own.
  TestContext t;
  const ErrorBudget budget{};
  for (std::uint32_t k = d3d12::metaballs; k < d3d12::primitive_count; ++k) {
    const auto kind = static_cast<d3d12::PrimitiveKind>(k);
    const Measured m = render_alone(t.ctx, kind, d3d12::capabilities(kind).defaults, 640, 360);
    const accuracy::ClassStats& all = m.metrics.all;
    CAPTURE(d3d12::primitive_names[k]);
    CAPTURE(all.depth.median);
    CAPTURE(all.depth.p99);
    REQUIRE(all.both_hit > 1000);
    CHECK(all.depth.median <= budget.depth_median);
    CHECK(all.depth.p99 <= budget.depth_p99);
    const double fat = m.metrics[accuracy::PixelClass::silhouette_1px].false_hit_rate();
    CHECK((std::isnan(fat) || fat <= budget.silhouette_false_hits));
    CHECK(all.false_miss_rate() <= budget.false_misses);
    CHECK(all.wrong_surface_rate() <= budget.wrong_surface);
    CHECK(all.nonfinite == 0);
  }
}
