// What every example does around its scene: time the build, trace frames, report medians,
// write the last frame.
//
//   examples::print_build(ctx, renderer);
//   auto run = examples::run_frames(renderer, o, [&](std::uint32_t f) { renderer.set(slot, constants(o, f)); });
//   examples::print_run(run, o);
//   examples::write_last(run, o);   // PNG, then its path
//
//   // or all of the above for a proceduray::Scene type with renderer_options(cache), in one call:
//   return examples::run_scene<MyScene>(argc, argv, "my_example", {.width = 1024, .height = 768}, slot,
//                                       [](const examples::Options& o, std::uint32_t frame) { return constants(o, frame); });
#pragma once

#include "cli.hpp"

#include <proceduray/image/png.hpp>
#include <proceduray/scene/sbt_printer.hpp>
#include <proceduray/scene/uniform_slot.hpp>
#include <proceduray/vk/renderer.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <vector>

namespace examples {

/// The median of a non-empty list.
inline double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

/// Prints the device, the acceleration-structure, compile and pipeline times, and the warm-up.
inline void print_build(const proceduray::vk::Context& ctx, proceduray::vk::Renderer& renderer) {
  const auto& t = renderer.timings();
  std::printf("device: %s\nacceleration structures: %.1f ms\nshaders: %.1f ms (%u from the SPIR-V cache, %u compiled)\n"
              "pipeline: %.1f ms (%s)\nshader and pipeline work: %.1f ms\n",
              ctx.name().c_str(), t.acceleration_ms, t.compile_ms, t.spirv_cached, t.spirv_compiled, t.pipeline_ms,
              t.pipeline_cached ? "pipeline cache warm" : "pipeline cache cold", t.compile_ms + t.pipeline_ms);
  std::printf("warm-up: %.1f ms\n", renderer.warm_up());
}

/// The frames of one run: their GPU and host times, whether any refit the TLAS, the last frame.
struct Run {
  std::vector<double> trace_ms;
  std::vector<double> host_ms;
  bool refit = false;
  proceduray::vk::Frame last;
};

/// Traces o.frames frames, calling update(frame index) before each; reads back the last one only.
template <class Update>
Run run_frames(proceduray::vk::Renderer& renderer, const Options& o, Update update) {
  Run run;
  for (std::uint32_t f = 0; f < o.frames; ++f) {
    update(f);
    run.last = renderer.render(o.width, o.height, f + 1 == o.frames);
    run.trace_ms.push_back(run.last.trace_ms);
    run.host_ms.push_back(run.last.host_ms);
    run.refit = run.refit || run.last.tlas_refit;
  }
  return run;
}

/// Prints the median trace and host times, primary rays per second, and whether the TLAS was refit.
inline void print_run(const Run& run, const Options& o) {
  const double trace = median(run.trace_ms);
  std::printf("trace: %.2f ms median of %u frames at %ux%u (%.1f Mrays/s primary); TLAS refit: %s\n"
              "host per frame: %.3f ms\n",
              trace, o.frames, o.width, o.height, o.width * o.height / (trace * 1e3), run.refit ? "yes" : "no",
              median(run.host_ms));
}

/// Writes the run's last frame to o.out and prints the file's path.
inline void write_last(const Run& run, const Options& o) {
  proceduray::write_png(o.out, o.width, o.height, run.last.rgba);
  std::printf("%s\n", std::filesystem::absolute(o.out).string().c_str());
}

/// A scene example's whole program: options, device, the renderer of Scene (a proceduray::Scene with
/// renderer_options(cache)), the build report, o.frames frames with `slot` set to constants(o, frame)
/// before each (and before the warm-up), their medians, the SBT and the PNG. Returns the exit code:
/// 1 on an exception (printed with the program's name) or a validation message, else 0.
template <class Scene, class T, class Constants>
int run_scene(int argc, char** argv, const char* program, Options defaults, proceduray::UniformSlot<T> slot,
              Constants constants) {
  const Options o = parse(argc, argv, program, defaults);
  if (o.exit) return *o.exit;
  try {
    proceduray::check_writable(o.out);  // fail before the expensive part
    proceduray::vk::Context ctx({.device = o.device, .validation = o.validation});
    Scene scene;
    proceduray::vk::Renderer renderer(ctx, scene, scene.renderer_options(o.cache));
    renderer.set(slot, constants(o, 0u));
    print_build(ctx, renderer);
    const Run run = run_frames(renderer, o, [&](std::uint32_t f) { renderer.set(slot, constants(o, f)); });
    print_run(run, o);
    std::printf("%s", proceduray::format_sbt(renderer.plan(), renderer.sbt().layout()).c_str());
    write_last(run, o);
    return ctx.validation_messages().empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", program, e.what());
    return 1;
  }
}

}  // namespace examples
