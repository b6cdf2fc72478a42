// Benchmark (not a test): the library's frame loop against a raw-Vulkan reference (raw_tracer.hpp)
// tracing the same scene with the same SPIR-V, interleaved in one process: blocks of frames
// A B A B ... so both see the same machine state.
//
//   bench_frame_loop [--device cpu|gpu|auto] [--sizes 1024,4096] [--frames 120] [--block 20]
//                    [--frames-in-flight 2] [--boxes 64]
//
// The scene: a boxes x boxes grid of small boxes in one geometry, one instance, rays along +z
// (tools/bench/shaders; PROCEDURAY_BENCH_SHADER_DIR overrides the built-in path). Both loops do
// the same per iteration: submit frame i, then wait for frame i-1 and, with readback, copy its
// RGBA8 pixels into a caller-owned vector ("rgba8 copy") or only looks at them where they are
// ("rgba8 view": Renderer::rgba's span, the raw side's mapped pointer; both read the first and
// last byte). Prints per size and readback mode the medians of the
// iteration's wall time and of the trace's GPU time (timestamps) for each side and their ratios
// (library / raw), the raw side's GPU copy time, and the library's host time per frame.
// Fails (exit 1) when the two sides' pixels differ.
#include "raw_tracer.hpp"

#include <proceduray/proceduray.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#ifndef PROCEDURAY_BENCH_SHADER_DIR
#define PROCEDURAY_BENCH_SHADER_DIR "tools/bench/shaders"
#endif

namespace pr = proceduray;

namespace bench {
struct Colour {
  glm::vec3 rgb;
};
PROCEDURAY_STRUCT(Colour, scalar, rgb);
using BenchSceneInterface = proceduray::ShaderInterface<proceduray::Payload<Colour>, proceduray::RootComponent<>, proceduray::RootArguments<>,
                                   proceduray::Attributes<>>;
using BenchScene = proceduray::Scene<BenchSceneInterface>;
}  // namespace bench

namespace {

using Clock = std::chrono::steady_clock;
double ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// A grid of n x n small boxes over [-1, 1]^2, half a cell wide: half the rays hit one.
std::vector<pr::Aabb> grid(std::uint32_t n) {
  std::vector<pr::Aabb> boxes;
  const float cell = 2.0f / static_cast<float>(n);
  for (std::uint32_t y = 0; y < n; ++y) {
    for (std::uint32_t x = 0; x < n; ++x) {
      const glm::vec3 c(-1.0f + cell * (static_cast<float>(x) + 0.5f), -1.0f + cell * (static_cast<float>(y) + 0.5f),
                        0.0f);
      boxes.push_back({c - glm::vec3(cell * 0.35f, cell * 0.35f, 0.05f), c + glm::vec3(cell * 0.35f, cell * 0.35f, 0.05f)});
    }
  }
  return boxes;
}

VkShaderStageFlagBits stage_bit(pr::ShaderStage s) {
  switch (s) {
    case pr::ShaderStage::raygen: return VK_SHADER_STAGE_RAYGEN_BIT_KHR;
    case pr::ShaderStage::miss: return VK_SHADER_STAGE_MISS_BIT_KHR;
    case pr::ShaderStage::closest_hit: return VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR;
    case pr::ShaderStage::intersection: return VK_SHADER_STAGE_INTERSECTION_BIT_KHR;
    default: throw std::runtime_error("bench_frame_loop: unexpected stage");
  }
}

struct Side {
  std::vector<double> wall, gpu, copy, host;
};

enum class Mode { none, copy, view };

/// The scene both sides trace: a grid of boxes, one ray, one hit group.
bench::BenchScene box_scene(const std::vector<pr::Aabb>& boxes) {
  bench::BenchScene scene;
  const auto primary = scene.add_ray<bench::Colour>("primary", {.miss = "bench.rmiss"});
  const auto group = scene.add_hit_group("box", {.kind = pr::HitGroupKind::procedural, .closest_hit = "bench.rchit",
                                                  .intersection = "bench.rint"});
  scene.add_geometry("boxes", pr::GeometryDesc::procedural(boxes));
  scene.set_global_signature({.bindings = {{pr::BindingKind::acceleration_structure, 0, 0, 1, "tlas"},
                                            {pr::BindingKind::storage_image, 1, 0, 1, "image"}}});
  scene.add_raygen("bench.rgen");
  scene.set_default_hit(primary, group);
  return scene;
}

/// The raw side's shaders: the same SPIR-V (the plan's stages with their generated declarations).
std::array<raw::Shader, 4> raw_shaders(const pr::Plan& plan, const std::filesystem::path& dir) {
  std::array<raw::Shader, 4> shaders;
  const pr::ShaderStage order[4] = {pr::ShaderStage::raygen, pr::ShaderStage::miss, pr::ShaderStage::closest_hit,
                                    pr::ShaderStage::intersection};
  for (std::size_t i = 0; i < 4; ++i) {
    for (const pr::PlannedStage& s : plan.pipeline().stages) {
      if (s.stage != order[i]) continue;
      shaders[i] = {stage_bit(s.stage), pr::vk::compile_glsl_file(s.stage, dir / s.shader, s.declarations)};
    }
  }
  return shaders;
}

/// One block of n library frames: frame i submitted, then frame i-1 waited for (and read), so the
/// host records one frame while the device traces the one before; with one frame in flight there
/// is no before: frame i is waited for itself.
void library_block(pr::vk::Renderer& library, std::uint32_t size, Mode mode, int n, std::uint32_t in_flight, Side& lib,
                   std::vector<std::uint8_t>& pixels, unsigned& touched) {
  const auto submit = [&] {
    return library.submit(size, size, mode != Mode::none ? pr::vk::Readback::rgba : pr::vk::Readback::none);
  };
  pr::vk::FrameTicket prev = in_flight > 1 ? submit() : pr::vk::FrameTicket{};
  for (int i = 0; i < n; ++i) {
    const auto start = Clock::now();
    const pr::vk::FrameTicket t = submit();
    const pr::vk::FrameTicket done_frame = in_flight > 1 ? prev : t;
    if (mode == Mode::copy) library.read_rgba(done_frame, pixels);
    if (mode == Mode::view) {
      const std::span<const std::uint8_t> view = library.rgba(done_frame);
      touched += view.front() + view.back();
    }
    const pr::vk::Frame f = library.wait(done_frame);
    lib.wall.push_back(ms(start, Clock::now()));
    lib.gpu.push_back(f.trace_ms);
    lib.host.push_back(f.host_ms);
    prev = t;
  }
  library.wait(prev);
}

/// The same block on the raw side.
void raw_block(raw::RawTracer& reference, std::uint32_t size, Mode mode, int n, std::uint32_t in_flight, Side& ref,
               std::vector<std::uint8_t>& pixels, unsigned& touched) {
  const bool readback = mode != Mode::none;
  raw::RawTracer::Ticket prev = in_flight > 1 ? reference.submit(size, size, readback) : raw::RawTracer::Ticket{};
  for (int i = 0; i < n; ++i) {
    const auto start = Clock::now();
    const raw::RawTracer::Ticket t = reference.submit(size, size, readback);
    const raw::RawTracer::Ticket done_frame = in_flight > 1 ? prev : t;
    if (mode == Mode::copy) reference.read(done_frame, pixels);
    if (mode == Mode::view) {
      const std::span<const std::uint8_t> view = reference.view(done_frame);
      touched += view.front() + view.back();
    }
    const auto [trace, copy_ms] = reference.gpu_ms(done_frame);
    ref.wall.push_back(ms(start, Clock::now()));
    ref.gpu.push_back(trace);
    ref.copy.push_back(copy_ms);
    prev = t;
  }
  reference.gpu_ms(prev);
}

/// Both sides at one size, in each readback mode, blocks interleaved; a line per mode. Returns 1
/// when their pixels differ.
int compare_size(pr::vk::Renderer& library, raw::RawTracer& reference, std::uint32_t size, int frames, int block,
                 std::uint32_t in_flight) {
  std::vector<std::uint8_t> lib_pixels(std::size_t{size} * size * 4), raw_pixels(lib_pixels.size());
  int status = 0;
  // Same pixels first: the comparison is of the same work.
  library.read_rgba(library.submit(size, size), lib_pixels);
  reference.read(reference.submit(size, size, true), raw_pixels);
  if (lib_pixels != raw_pixels) {
    std::fprintf(stderr, "bench_frame_loop: the library's and the raw reference's pixels differ at %ux%u\n", size, size);
    status = 1;
  }
  for (const Mode mode : {Mode::none, Mode::view, Mode::copy}) {
    Side lib, ref;
    unsigned touched = 0;  // what the view reads, printed so it is not optimised away
    for (int done = 0; done < frames; done += block) {
      const int n = std::min(block, frames - done);
      library_block(library, size, mode, n, in_flight, lib, lib_pixels, touched);
      raw_block(reference, size, mode, n, in_flight, ref, raw_pixels, touched);
    }
    const double lw = median(lib.wall), rw = median(ref.wall), lg = median(lib.gpu), rg = median(ref.gpu);
    const char* name = mode == Mode::none ? "none" : mode == Mode::copy ? "rgba8 copy" : "rgba8 view";
    std::printf("%6u %10s | %10.3f %10.3f %6.3f | %10.3f %10.3f %6.3f | %9.3f %9.4f   (%u)\n", size, name, lw, rw,
                lw / rw, lg, rg, lg / rg, median(ref.copy), median(lib.host), touched % 10);
    std::fflush(stdout);
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The library's frame loop against a raw-Vulkan reference, interleaved"};
  std::string device = "auto";
  std::vector<std::uint32_t> sizes{1024, 4096};
  int frames = 120, block = 20;
  std::uint32_t in_flight = 2, boxes_per_side = 64;
  app.add_option("--device", device, "cpu, gpu or auto")->check(CLI::IsMember({"cpu", "gpu", "auto"}));
  app.add_option("--sizes", sizes, "square frame sizes")->delimiter(',');
  app.add_option("--frames", frames, "timed frames per side, size and readback mode")->check(CLI::Range(2, 100000));
  app.add_option("--block", block, "frames per block before switching sides")->check(CLI::Range(2, 100000));
  app.add_option("--frames-in-flight", in_flight, "both sides")->check(CLI::Range(1u, pr::vk::max_frames_in_flight));
  app.add_option("--boxes", boxes_per_side, "boxes per side of the grid")->check(CLI::Range(1u, 1024u));
  CLI11_PARSE(app, argc, argv);

  const pr::vk::DevicePreference preference = device == "gpu"   ? pr::vk::DevicePreference::gpu
                                              : device == "cpu" ? pr::vk::DevicePreference::cpu
                                                                : pr::vk::DevicePreference::automatic;
  pr::vk::Context ctx({.device = preference});
  const std::vector<pr::Aabb> boxes = grid(boxes_per_side);
  const char* env_dir = std::getenv("PROCEDURAY_BENCH_SHADER_DIR");  // for binaries carried to another machine
  const std::filesystem::path dir = env_dir != nullptr ? env_dir : PROCEDURAY_BENCH_SHADER_DIR;
  pr::vk::RendererOptions options{.shader_dirs = {dir}};
  options.frames_in_flight = in_flight;
  pr::vk::Renderer library(ctx, box_scene(boxes), options);
  std::vector<raw::Box> raw_boxes;
  for (const pr::Aabb& b : boxes) raw_boxes.push_back({{b.min.x, b.min.y, b.min.z}, {b.max.x, b.max.y, b.max.z}});
  raw::RawTracer reference(ctx.device(), ctx.physical_device(), ctx.queue(), ctx.queue_family(),
                           raw_shaders(library.plan(), dir), raw_boxes, in_flight);

  std::printf("device: %s; %ux%u boxes, %u frames in flight, %d frames per side in blocks of %d\n", ctx.name().c_str(),
              boxes_per_side, boxes_per_side, in_flight, frames, block);
  std::printf("%6s %10s | %10s %10s %6s | %10s %10s %6s | %9s %9s\n", "size", "readback", "lib wall", "raw wall",
              "ratio", "lib gpu", "raw gpu", "ratio", "raw copy", "lib host");
  int status = 0;
  for (const std::uint32_t size : sizes) status |= compare_size(library, reference, size, frames, block, in_flight);
  return status;
}
