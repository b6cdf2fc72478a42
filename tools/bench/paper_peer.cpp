// Benchmark (not a test): the paper scene (examples/02_paper_scene) through the library's
// ray-tracing pipeline against a compute peer (shaders/paper_peer.comp): every ray tests every
// object, with the library's primitives, marchers, knobs and march setup, shaded as the example's
// iterative raygen loop shades (Phong, a shadow ray, Schlick reflections). Interleaved frame by
// frame, timed with GPU timestamps; the last images compared pixel by pixel.
//
//   bench_paper_peer [--device cpu|gpu|auto] [--size 1024x768] [--frames 5] [--time 0.4] [--validation]
//
// Prints the medians of both trace times and their ratio (library / peer: the bound is
// 1.1), the peer's distance evaluations per frame (every ray of every pixel) and per second, and
// the shares of pixels more than 2 and more than 8 levels apart. Exit status 1 when more than 1%
// are more than 8 levels apart: the peer would not be rendering the same scene.
#include "bench_cli.hpp"
#include "compute.hpp"

#include "02_paper_scene/frame.hpp"

#include <proceduray/proceduray.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>


namespace pr = proceduray;

namespace paper_peer {

/// The peer's push constants (paper_peer.comp reads them as `push`).
struct Push {
  pr::MarchKnobs julia;
  pr::MarchKnobs bulb;
  std::uint32_t width;
  std::uint32_t height;
};
PROCEDURAY_STRUCT(Push, scalar, julia, bulb, width, height);


/// The consts paper_peer.comp takes from the scene (the library's shaders get them from glsl_for).
std::string scene_consts() {
  const auto u = [](const char* name, std::uint32_t v) { return "const uint " + std::string(name) + " = " + std::to_string(v) + "u;\n"; };
  std::string s = u("flag_shadows", paper::flag_shadows) + u("flag_reflections", paper::flag_reflections) +
                  u("max_depth_limit", paper::max_depth_limit) + u("plane_id", paper::plane_id) +
                  u("pacman0_id", paper::pacman0_id) + u("julia_id", paper::julia_id) +
                  u("mandelbulb_id", paper::mandelbulb_id);
  char plane[160];
  std::snprintf(plane, sizeof plane, "const vec2 plane_min = vec2(%.9g, %.9g);\nconst vec2 plane_max = vec2(%.9g, %.9g);\n",
                static_cast<double>(paper::plane_min.x), static_cast<double>(paper::plane_min.y),
                static_cast<double>(paper::plane_max.x), static_cast<double>(paper::plane_max.y));
  return s + plane;
}

/// World-to-object rows of the Pac-men, the Julia set and the Mandelbulb, in that order.
std::vector<glm::vec4> object_rows() {
  std::vector<glm::vec4> rows;
  for (const pr::Placement& p : {paper::pacman_placements[0], paper::pacman_placements[1], paper::julia_placement,
                                 paper::mandelbulb_placement}) {
    const glm::mat4 m = glm::inverse(p.matrix());
    for (int r = 0; r < 3; ++r) rows.emplace_back(m[0][r], m[1][r], m[2][r], m[3][r]);
  }
  return rows;
}


}  // namespace paper_peer

int main(int argc, char** argv) {
  using namespace paper_peer;
  std::string device = "auto", size = "1024x768";
  std::uint32_t frames = 5;
  float time = 0.4f;
  bool validation = false;
  CLI::App app{"The paper scene: the library's pipeline against a compute peer"};
  app.add_option("--device", device, "cpu (lavapipe), gpu or auto")->check(CLI::IsMember({"cpu", "gpu", "auto"}));
  app.add_option("--size", size, "image WxH")->capture_default_str();
  app.add_option("--frames", frames, "timed frames per side (median)")->check(CLI::Range(1u, 1000u));
  app.add_option("--time", time, "the scene's time (s)")->check(CLI::Range(0.0f, 1000.0f));
  app.add_flag("--validation", validation, "the Khronos validation layer on; a message fails the run");
  CLI11_PARSE(app, argc, argv);
  unsigned width = 0, height = 0;
  if (!bench::parse_size(size, "bench_paper_peer", "1024x768", width, height)) return 2;
  try {
    pr::vk::Context ctx({.device = bench::device_preference(device), .validation = validation});
    if (ctx.timestamp_period_ns() <= 0.0) throw std::runtime_error("bench_paper_peer: the queue writes no timestamps");
    const std::filesystem::path dir = bench::shader_dir();
    const std::filesystem::path paper_dir = examples::examples_dir() / "02_paper_scene" / "shaders";
    const paper::Frame f = paper::default_frame(width, height, time);

    const paper::PaperScene scene;
    pr::vk::Renderer library(ctx, scene, scene.renderer_options());
    paper::set_frame(library, f);

    const std::vector<const pr::TypeOps*> types{&pr::type_ops<paper::SceneConstants>, &pr::type_ops<paper::MaterialRecord>,
                                                &pr::type_ops<Push>};
    const std::string preamble = pr::glsl_declarations(types, false) + pr::glsl_push_constant(pr::type_ops<Push>, "push") +
                                 scene_consts();
    const std::vector<std::uint32_t> spirv = pr::vk::compile_glsl(
        {.stage = pr::ShaderStage::compute, .name = (dir / "paper_peer.comp").string(),
         .code = bench::read_text(dir / "paper_peer.comp", "bench_paper_peer"),
         .include_dirs = {dir, paper_dir, pr::vk::library_shader_dir()},
         .preamble = preamble});
    const VkDeviceSize pixels = VkDeviceSize{width} * height;
    std::vector<paper::MaterialRecord> materials(6);
    materials[paper::plane_id] = paper::plane_material;
    materials[paper::pacman0_id] = paper::pacman_materials[0];
    materials[paper::pacman1_id] = paper::pacman_materials[1];
    materials[paper::julia_id] = paper::julia_material;
    materials[paper::mandelbulb_id] = paper::mandelbulb_material;
    const std::vector<glm::vec4> rows = object_rows();
    bench::ComputeKernel peer(ctx, spirv,
                              {pixels * 4, sizeof(paper::SceneConstants), rows.size() * sizeof(glm::vec4),
                               materials.size() * sizeof(paper::MaterialRecord), pixels * 4},
                              sizeof(Push), "bench_paper_peer");
    const paper::SceneConstants& constants = f;
    std::memcpy(peer.buffer(1), &constants, sizeof constants);
    std::memcpy(peer.buffer(2), rows.data(), rows.size() * sizeof(glm::vec4));
    std::memcpy(peer.buffer(3), materials.data(), materials.size() * sizeof(paper::MaterialRecord));
    const Push push{f.knobs[paper::julia_id], f.knobs[paper::mandelbulb_id], width, height};
    const std::uint32_t gx = (width + 7) / 8, gy = (height + 7) / 8;

    library.render(width, height, false);  // warm-up: lazy compiles
    peer.run(gx, gy, &push);
    std::vector<double> lib_ms, peer_ms;
    pr::vk::Frame last;
    for (std::uint32_t i = 0; i < frames; ++i) {
      last = library.render(width, height, i + 1 == frames);
      lib_ms.push_back(last.trace_ms);
      peer_ms.push_back(peer.run(gx, gy, &push));
    }
    const auto* rgba = static_cast<const std::uint32_t*>(peer.buffer(0));
    const auto* counts = static_cast<const std::uint32_t*>(peer.buffer(4));
    std::size_t over2 = 0, over8 = 0;
    double evals = 0.0;
    for (std::size_t i = 0; i < pixels; ++i) {
      int worst = 0;
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(last.rgba[4 * i + c]) - int((rgba[i] >> (8 * c)) & 255u)));
      over2 += worst > 2;
      over8 += worst > 8;
      evals += counts[i];
    }
    const double l = bench::median(lib_ms), p = bench::median(peer_ms), n = static_cast<double>(pixels);
    std::printf("device: %s; paper scene %ux%u at t = %g s, %u frames per side (medians)\n", ctx.name().c_str(), width,
                height, static_cast<double>(time), frames);
    std::printf("library %.3f ms, compute peer %.3f ms, library / peer %.3f\n", l, p, l / p);
    std::printf("peer: %.2f M distance evaluations per frame, %.3f G per second\n", evals * 1.0e-6, evals / (p * 1.0e-3) * 1.0e-9);
    std::printf("pixels apart: %.3f%% by more than 2 levels, %.3f%% by more than 8\n", 100.0 * over2 / n, 100.0 * over8 / n);
    int status = 0;
    if (over8 > pixels / 100) {
      std::fprintf(stderr, "bench_paper_peer: %.2f%% of the pixels are more than 8 levels apart (bound 1%%): the peer is "
                           "not rendering the library's scene\n", 100.0 * over8 / n);
      status = 1;
    }
    if (!bench::validation_clean(ctx, "bench_paper_peer")) status = 1;
    return status;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
