// Benchmark (not a test): frame time against the number of marched instances, the library's
// ray-tracing pipeline (its acceleration structure hands each ray only the boxes it enters)
// against a compute peer of the same scene (shaders/instances.comp: every ray tests every
// instance's box, then marches the ones it enters with the library's own marcher and knobs).
// The scene: n power-8 Mandelbulbs on a square grid filling the view, camera rays only, each
// pixel shaded by its hit's normal. Per count the two are interleaved frame by frame, timed with
// GPU timestamps, and their last images compared pixel by pixel.
//
//   bench_instances [--device cpu|gpu|auto] [--size 512x512] [--counts 1,10,100,1000,10000]
//                   [--frames 5] [--csv instances.csv] [--validation] [--flops-per-eval F --peak-gflops P]
//   tools/bench/instances_chart.py instances.csv --out instances.png
//
// Prints per count: the medians of the library's and the peer's trace times, their ratio
// (library / peer: below 1, the pipeline wins), and how the images differ: pixels hit in one only
// (coverage; also as a share of the silhouette pixels, where float rounding of each side's
// object-space ray decides a grazing ray), and pixels hit in both but shaded more than 2 levels
// apart; then the frame's distance evaluations (the peer counts them; the library, marching the
// same rays with the same code, makes the same), each side's evaluations per second and, given
// the flops per evaluation and the device's peak, the share of the peak each reaches. Exit status
// 1 when more than 1% are shaded apart or 10% of the silhouette flips: the peer would not be
// marching the same scene.
#include "bench_cli.hpp"
#include "compute.hpp"

#include <proceduray/proceduray.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>


namespace pr = proceduray;

namespace instances {

struct Colour {
  glm::vec3 rgb;
};
PROCEDURAY_STRUCT(Colour, scalar, rgb);
struct Constants {
  pr::Camera camera;
};
PROCEDURAY_STRUCT(Constants, scalar, camera);
/// The compute peer's push constants (instances.comp reads them as `push`).
struct Push {
  pr::Camera camera;
  pr::MarchKnobs knobs;
  std::uint32_t count;
  std::uint32_t width;
  std::uint32_t height;
  float box;  ///< the bulb's box is [-box, box]^3 in object space
};
PROCEDURAY_STRUCT(Push, scalar, camera, knobs, count, width, height, box);
using Interface = pr::ShaderInterface<pr::Payload<Colour>, pr::RootComponent<Constants>, pr::RootArguments<>,
                                      pr::Attributes<pr::FieldHit>>;
using Scene = pr::Scene<Interface>;

constexpr pr::UniformSlot<Constants> constants_slot{.binding = 2, .name = "constants"};
constexpr float box = 1.25f;       // the paper scene's Mandelbulb box
constexpr std::uint32_t iterations = 8;

/// Instance i of n: translation xyz, uniform scale w, on a ceil(sqrt(n)) square grid in z = 0
/// spanning [-1.3, 1.3]^2, boxes not overlapping.
std::vector<glm::vec4> placements(std::uint32_t n) {
  const auto side = static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  const float cell = 2.6f / static_cast<float>(side), scale = cell / (2.0f * box * 1.04f);
  std::vector<glm::vec4> out;
  for (std::uint32_t i = 0; i < n; ++i) {
    const float x = -1.3f + cell * (static_cast<float>(i % side) + 0.5f);
    const float y = 1.3f - cell * (static_cast<float>(i / side) + 0.5f);
    out.emplace_back(x, y, 0.0f, scale);
  }
  return out;
}

Scene scene(const std::vector<glm::vec4>& where) {
  Scene s;
  const auto primary = s.add_ray<Colour>("primary", {.miss = "instances.rmiss"});
  s.set_global_signature(pr::default_global_signature({constants_slot}));
  s.add_raygen("instances.rgen");
  std::vector<pr::InstanceTransform> transforms;
  for (const glm::vec4& p : where) {
    transforms.push_back(pr::instance_transform(glm::translate(glm::mat4(1.0f), glm::vec3(p)) *
                                                glm::scale(glm::mat4(1.0f), glm::vec3(p.w))));
  }
  pr::add_distance_field(s, "bulb", {.glsl = "instances.glsl", .function = "bench_bulb",
                                     .aabb = {glm::vec3(-box), glm::vec3(box)}, .lipschitz = 1.0f,
                                     .iterations = iterations, .instances = std::move(transforms),
                                     .closest_hit = {{primary, "instances.rchit"}}});
  return s;
}


/// How two images of the scene differ: pixels hit in one only (at a silhouette, where float
/// rounding of the object-space ray decides), pixels hit in both whose shade differs by more than
/// 2 levels in a channel, and the silhouette pixels of the library's image (a hit beside a miss).
struct Difference {
  std::size_t coverage = 0;
  std::size_t shade = 0;
  std::size_t silhouette = 0;
};

Difference compare(const std::vector<std::uint8_t>& a, const std::uint32_t* b, std::uint32_t width, std::uint32_t height) {
  const auto hit_a = [&](std::size_t i) { return (a[4 * i] | a[4 * i + 1] | a[4 * i + 2]) != 0; };
  Difference d;
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const std::size_t i = std::size_t{y} * width + x;
      const bool ha = hit_a(i), hb = (b[i] & 0xFFFFFFu) != 0;
      if (ha != hb) ++d.coverage;
      bool far = false;
      for (int c = 0; ha && hb && c < 3; ++c) far = far || std::abs(int(a[4 * i + c]) - int((b[i] >> (8 * c)) & 255u)) > 2;
      d.shade += far;
      bool edge = false;
      if (x > 0) edge = edge || hit_a(i - 1) != ha;
      if (x + 1 < width) edge = edge || hit_a(i + 1) != ha;
      if (y > 0) edge = edge || hit_a(i - width) != ha;
      if (y + 1 < height) edge = edge || hit_a(i + width) != ha;
      d.silhouette += edge && ha;
    }
  }
  return d;
}

/// `text` as one CSV field: quoted, quotes doubled (a device name has commas: "llvmpipe (LLVM 15, 256 bits)").
std::string csv_field(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}


}  // namespace instances

int main(int argc, char** argv) {
  using namespace instances;
  std::string device = "auto", size = "512x512", csv;
  std::vector<std::uint32_t> counts{1, 10, 100, 1000, 10000};
  std::uint32_t frames = 5;
  bool validation = false;
  double flops_per_eval = 0.0, peak_gflops = 0.0;
  CLI::App app{"Frame time against marched instances: the library's pipeline and a compute peer"};
  app.add_option("--device", device, "cpu (lavapipe), gpu or auto")->check(CLI::IsMember({"cpu", "gpu", "auto"}));
  app.add_option("--size", size, "image WxH")->capture_default_str();
  app.add_option("--counts", counts, "instance counts")->delimiter(',')->check(CLI::Range(1u, 1000000u));
  app.add_option("--frames", frames, "timed frames per side and count (median)")->check(CLI::Range(1u, 1000u));
  app.add_option("--csv", csv, "also write the rows as CSV (instances_chart.py charts it)");
  app.add_flag("--validation", validation, "the Khronos validation layer on; a message fails the run");
  app.add_option("--flops-per-eval", flops_per_eval, "flops one Mandelbulb evaluation costs (bench_flops counts them)")
      ->check(CLI::PositiveNumber);
  app.add_option("--peak-gflops", peak_gflops, "the device's FP32 peak (bench_peak): prints the share of it each side reaches")
      ->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);
  if ((flops_per_eval > 0.0) != (peak_gflops > 0.0)) {
    std::fprintf(stderr, "bench_instances: --flops-per-eval and --peak-gflops go together (the share of the peak needs both)\n");
    return 2;
  }
  unsigned width = 0, height = 0;
  if (!bench::parse_size(size, "bench_instances", "512x512", width, height)) return 2;
  try {
    pr::vk::Context ctx({.device = bench::device_preference(device), .validation = validation});
    if (ctx.timestamp_period_ns() <= 0.0) throw std::runtime_error("bench_instances: the queue writes no timestamps");
    const std::filesystem::path dir = bench::shader_dir();
    const Constants constants{pr::look_at({0.0f, 0.0f, 3.2f}, {0.0f, 0.0f, 0.0f}, 50.0f, width, height)};
    const pr::MarchKnobs knobs = pr::fractal_capabilities(iterations).defaults;
    const std::string preamble = pr::glsl_declarations(std::vector<const pr::TypeOps*>{&pr::type_ops<Push>}, false) +
                                 pr::glsl_push_constant(pr::type_ops<Push>, "push");
    const std::vector<std::uint32_t> spirv = pr::vk::compile_glsl(
        {.stage = pr::ShaderStage::compute, .name = (dir / "instances.comp").string(),
         .code = bench::read_text(dir / "instances.comp", "bench_instances"),
         .include_dirs = {dir, pr::vk::library_shader_dir()}, .preamble = preamble});
    std::FILE* out = csv.empty() ? nullptr : std::fopen(csv.c_str(), "w");
    if (!csv.empty() && out == nullptr) throw std::runtime_error("bench_instances: cannot write " + csv);
    if (out != nullptr) {
      std::fprintf(out, "device,width,height,instances,library_ms,peer_ms,ratio,coverage,shade,coverage_of_silhouette,"
                        "evaluations,library_evals_per_s,peer_evals_per_s\n");
    }
    std::printf("device: %s; %ux%u camera rays, Mandelbulbs (%u iterations), %u frames per side (medians)\n",
                ctx.name().c_str(), width, height, iterations, frames);
    std::printf("%10s %12s %12s %8s %10s %10s %12s %9s %9s %9s%s\n", "instances", "library ms", "peer ms", "ratio",
                "coverage", "shade", "of silhouette", "Mevals", "lib Ge/s", "peer Ge/s",
                peak_gflops > 0.0 ? "  lib peak peer peak" : "");
    int status = 0;
    for (const std::uint32_t n : counts) {
      const std::vector<glm::vec4> where = placements(n);
      pr::vk::Renderer library(ctx, scene(where), {.shader_dirs = {dir}});
      library.set(constants_slot, constants);
      library.set_pixel_angle(constants.camera.pixel_angle);
      library.set_field_knobs(library.plan().fields()[0].geometry, knobs);
      bench::ComputeKernel peer(ctx, spirv,
                                {VkDeviceSize{width} * height * 4, where.size() * sizeof(glm::vec4), VkDeviceSize{width} * height * 4},
                                sizeof(Push), "bench_instances");
      std::vector<glm::vec4> to_object;  // instances.comp's world-to-object transforms
      for (const glm::vec4& p : where) to_object.emplace_back(-glm::vec3(p) * (1.0f / p.w), 1.0f / p.w);
      std::memcpy(peer.buffer(1), to_object.data(), to_object.size() * sizeof(glm::vec4));
      const Push push{constants.camera, knobs, n, width, height, box};
      const std::uint32_t gx = (width + 7) / 8, gy = (height + 7) / 8;
      library.render(width, height, false);  // warm-up: lazy compiles, the pipeline
      peer.run(gx, gy, &push);
      std::vector<double> lib_ms, peer_ms;
      pr::vk::Frame last;
      for (std::uint32_t f = 0; f < frames; ++f) {
        last = library.render(width, height, f + 1 == frames);
        lib_ms.push_back(last.trace_ms);
        peer_ms.push_back(peer.run(gx, gy, &push));
      }
      const Difference d = compare(last.rgba, static_cast<const std::uint32_t*>(peer.buffer(0)), width, height);
      const double pixels = static_cast<double>(width) * height;
      const double l = bench::median(lib_ms), p = bench::median(peer_ms);
      const auto* counts_px = static_cast<const std::uint32_t*>(peer.buffer(2));
      double evals = 0.0;
      for (std::size_t i = 0; i < std::size_t{width} * height; ++i) evals += counts_px[i];
      // Evaluations per second of each side (the same evaluations: same rays, same marcher), and
      // with the flops per evaluation and the device's peak, the share of the peak each reaches.
      const double lib_rate = evals / (l * 1.0e-3), peer_rate = evals / (p * 1.0e-3);
      const double lib_peak = peak_gflops > 0.0 ? flops_per_eval * lib_rate / (peak_gflops * 1.0e9) : 0.0;
      const double peer_peak = peak_gflops > 0.0 ? flops_per_eval * peer_rate / (peak_gflops * 1.0e9) : 0.0;
      const double coverage = static_cast<double>(d.coverage) / pixels, shade = static_cast<double>(d.shade) / pixels;
      const double of_silhouette = static_cast<double>(d.coverage) / static_cast<double>(std::max<std::size_t>(d.silhouette, 1));
      std::printf("%10u %12.3f %12.3f %8.3f %9.3f%% %9.3f%% %11.1f%% %9.2f %9.3f %9.3f", n, l, p, l / p, 100.0 * coverage,
                  100.0 * shade, 100.0 * of_silhouette, evals * 1.0e-6, lib_rate * 1.0e-9, peer_rate * 1.0e-9);
      if (peak_gflops > 0.0) std::printf(" %8.1f%% %8.1f%%", 100.0 * lib_peak, 100.0 * peer_peak);
      std::printf("\n");
      if (out != nullptr) {
        std::fprintf(out, "%s,%u,%u,%u,%.4f,%.4f,%.4f,%.6f,%.6f,%.6f,%.0f,%.6g,%.6g\n", csv_field(ctx.name()).c_str(), width,
                     height, n, l, p, l / p, coverage, shade, of_silhouette, evals, lib_rate, peer_rate);
      }
      // Shades must agree where both hit; coverage may flip only on a few silhouette pixels.
      if (shade > 0.01 || of_silhouette > 0.1) {
        std::fprintf(stderr, "bench_instances: at %u instances the images differ (%.2f%% of pixels shaded apart, %.1f%% "
                             "of silhouette pixels hit in one only; bounds 1%% and 10%%): the peer is not marching the "
                             "same scene\n", n, 100.0 * shade, 100.0 * of_silhouette);
        status = 1;
      }
    }
    if (out != nullptr) std::fclose(out);
    if (!bench::validation_clean(ctx, "bench_instances")) status = 1;
    return status;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
