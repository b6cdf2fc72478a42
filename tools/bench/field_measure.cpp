// How long measuring and calibrating one distance field takes, truth included: examples/06's
// gyroid, one setting measured from a cold truth, then the methods preset calibrated (a progress
// line per setting), at the size given; and the same setting from a stratified truth (one pixel
// in --stride outside the silhouettes), its truth time and its rates against the full truth's.
// Prints wall times; nothing is cached on disk.
//
//   bench_field_measure [--size 1920x1080] [--device cpu|gpu|auto] [--stride 8]
#include <proceduray/proceduray.hpp>
#include <proceduray/shader/glsl_cpp.hpp>

#include <CLI/CLI.hpp>

#include <chrono>
#include <filesystem>
#include <cstdio>

namespace bench_field {
using namespace proceduray::glsl_cpp;
template <class T>
struct gyroid {
  PROCEDURAY_GLSL_CPP_SCALAR(T)
#include "06_your_field/shaders/gyroid.glsl"
};
}  // namespace bench_field

int main(int argc, char** argv) {
  namespace pr = proceduray;
  CLI::App app{"Wall time of measuring and calibrating one distance field"};
  std::string size = "320x240", device = "auto";
  std::uint32_t stride = 8;
  app.add_option("--size", size, "WxH")->capture_default_str();
  app.add_option("--device", device, "cpu, gpu or auto")->check(CLI::IsMember({"cpu", "gpu", "auto"}));
  app.add_option("--stride", stride, "the stratified truth's interior stride")->check(CLI::Range(2u, 1024u))
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  std::uint32_t w = 0, h = 0;
  if (std::sscanf(size.c_str(), "%ux%u", &w, &h) != 2) return 2;
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const auto start = Clock::now();
  pr::vk::Context ctx({.device = device == "cpu" ? pr::vk::DevicePreference::cpu
                                 : device == "gpu" ? pr::vk::DevicePreference::gpu : pr::vk::DevicePreference::automatic});
  const pr::DistanceField field{.id = "gyroid", .glsl = "gyroid.glsl", .aabb = {glm::vec3(-1.0f), glm::vec3(1.0f)},
                                .lipschitz = 1.75f};
  // From the repository root (a GPU machine's copy) or where the build saw it.
  const std::filesystem::path here = "examples/06_your_field/shaders";
  pr::vk::FieldMeter meter(ctx, field, {.shader_dirs = {std::filesystem::exists(here) ? here
                                                                                      : PROCEDURAY_BENCH_FIELD_DIR}});
  const auto truth = [](glm::dvec3 p) { return bench_field::gyroid<double>::gyroid_distance(p); };
  const pr::vk::MeasureView view{pr::look_at({1.6f, 1.2f, 2.4f}, {0.0f, 0.0f, 0.0f}, 45.0f, w, h), w, h};
  std::printf("device %s, %ux%u, %u truth threads; setup %.2f s\n", ctx.name().c_str(), w, h,
              pr::accuracy::worker_count(), seconds(start));
  const auto t1 = Clock::now();
  const pr::vk::Measurement m = meter.measure(truth, meter.capabilities().defaults, view);
  std::printf("measure, one setting, cold truth: %.2f s (truth %.2f s, gpu %.3f ms, %.2f evals/ray in the box, "
              "depth median %.3g fp)\n", seconds(t1), m.truth_ms / 1000.0, m.gpu_ms, m.evaluations_per_box_ray,
              m.metrics.all.depth.median);
  pr::MarchKnobs coarse = meter.capabilities().defaults;  // a setting with misses, so the rates have something to estimate
  coarse.threshold = 2.0f;
  coarse.method = pr::MarchMethod::fixed;
  coarse.fixed_steps = 24;
  const pr::vk::Measurement exact = meter.measure(truth, coarse, view);
  pr::vk::FieldMeter strat(ctx, field, {.shader_dirs = {std::filesystem::exists(here) ? here : PROCEDURAY_BENCH_FIELD_DIR},
                                        .interior_stride = stride});
  const auto t3 = Clock::now();
  const pr::vk::Measurement est = strat.measure(truth, coarse, view);
  std::printf("stratified truth, stride %u: %.2f s (truth %.2f s for %zu of %u pixels); fixed 24 steps: false misses "
              "%.4g%% (95%% bound %.4g%%) against %.4g%%, wrong surface %.4g%% (bound %.4g%%) against %.4g%%, depth "
              "median %.3g against %.3g fp\n",
              stride, seconds(t3), est.truth_ms / 1000.0, est.truth_traced, w * h, 100.0 * est.confidence.false_miss_rate,
              100.0 * est.confidence.false_miss_rate_95, 100.0 * exact.confidence.false_miss_rate,
              100.0 * est.confidence.wrong_surface_rate, 100.0 * est.confidence.wrong_surface_rate_95,
              100.0 * exact.confidence.wrong_surface_rate, est.metrics.all.depth.median, exact.metrics.all.depth.median);
  const auto t2 = Clock::now();
  const pr::vk::Calibrated c = pr::vk::calibrate(meter, truth, {.view = view, .progress = [&](const std::string& line) {
    std::printf("  [%6.2f s] %s\n", seconds(t2), line.substr(0, 100).c_str());
  }});
  std::printf("calibrate, the preset (%zu settings, truth warm): %.2f s\n", c.table.rows().size(), seconds(t2));
  std::printf("total: %.2f s\n", seconds(start));
  return ctx.validation_messages().empty() ? 0 : 1;
}
