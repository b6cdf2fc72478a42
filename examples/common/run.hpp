// What every example does around its scene: time the build, trace frames, report medians,
// write the last frame.
//
//   examples::print_build(ctx, renderer);
//   auto run = examples::run_frames(renderer, o, [&](std::uint32_t f) { renderer.set(slot, constants(o, f)); });
//   examples::print_run(run, o);
//   examples::write_last(run, o);   // PNG, then its path
//
//   // or all of the above for a proceduray::Scene<Interface> with renderer_options(cache), in one call:
//   return examples::run_scene(argc, argv, "my_example", {.width = 1024, .height = 768}, slot,
//                              [](const examples::Options& o, std::uint32_t frame) { return constants(o, frame); },
//                              [] { return MyScene(); },   // made once the options are parsed
//                              {});                         // or its own options: [&](CLI::App& app) {...}
#pragma once

#include "cli.hpp"
#include "set_constants.hpp"

#include <proceduray/image/png.hpp>
#include <proceduray/scene/sbt_printer.hpp>
#include <proceduray/scene/uniform_slot.hpp>
#include <proceduray/vk/renderer.hpp>
#include <proceduray/vk/timing.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <vector>

namespace examples {

/// The median of a non-empty list (proceduray::vk::stats, the installed timing helper).
inline double median(const std::vector<double>& v) { return proceduray::vk::stats(v).median; }

/// Prints the device, the acceleration-structure, compile and pipeline times, and the warm-up.
inline void print_build(const proceduray::vk::Context& ctx, proceduray::vk::Renderer& renderer) {
  const auto& t = renderer.timings();
  std::printf("device: %s\nacceleration structures: %.1f ms\nshaders: %.1f ms (%u from the SPIR-V cache, %u compiled)\n"
              "pipeline: %.1f ms (%s)\nshader and pipeline work: %.1f ms\n",
              ctx.name().c_str(), t.acceleration_ms, t.compile_ms, t.spirv_cached, t.spirv_compiled, t.pipeline_ms,
              t.pipeline_cached ? "pipeline cache warm" : "pipeline cache cold", t.compile_ms + t.pipeline_ms);
  std::printf("warm-up: %.1f ms\n", renderer.warm_up());
  if (t.rebuilds > 0) std::printf("pipeline built again for changed field knobs: %u time(s), %.1f ms\n", t.rebuilds, t.rebuild_ms);
}

/// The frames of one run: medians of their GPU and host times, whether any refit the TLAS, the last frame.
using Run = proceduray::vk::FrameTimes;

/// Traces o.frames frames, calling update(frame index) before each; reads back the last one only.
/// The warm-up is print_build's (Renderer::warm_up), so none here.
template <class Update>
Run run_frames(proceduray::vk::Renderer& renderer, const Options& o, Update update) {
  return proceduray::vk::time_frames(renderer, o.width, o.height, {.frames = o.frames, .warm_up = 0, .read_last = true},
                                     update);
}

/// Prints the median trace and host times, primary rays per second, and whether the TLAS was refit.
inline void print_run(const Run& run, const Options& o) {
  std::printf("trace: %.2f ms median of %u frames at %ux%u (%.1f Mrays/s primary); TLAS refit: %s\n"
              "host per frame: %.3f ms\n",
              run.trace_ms.median, o.frames, o.width, o.height, run.mrays_per_s(1.0), run.tlas_refit ? "yes" : "no",
              run.host_ms.median);
}

/// Writes the run's last frame to o.out and prints the file's path.
inline void write_last(const Run& run, const Options& o) {
  proceduray::write_png(o.out, o.width, o.height, run.last.rgba);
  std::printf("%s\n", std::filesystem::absolute(o.out).string().c_str());
}

/// A scene example's whole program: options (the shared ones and `extra`'s), device, the renderer of
/// make_scene()'s scene (a proceduray::Scene<Interface> with renderer_options(cache)), the build
/// report, o.frames frames with `slot` set to constants(o, frame) before each (and before the
/// warm-up), their medians, the SBT and the PNG. Returns the exit code: 1 on an exception (printed
/// with the program's name) or a validation message, else 0.
template <class T, class Constants, class MakeScene>
int run_scene(int argc, char** argv, const char* program, Options defaults, proceduray::UniformSlot<T> slot,
              Constants constants, MakeScene make_scene, const std::function<void(CLI::App&)>& extra = {}) {
  const Options o = parse(argc, argv, program, defaults, extra);
  if (o.exit) return *o.exit;
  try {
    proceduray::check_writable(o.out);  // fail before the expensive part
    proceduray::vk::Context ctx({.device = o.device, .validation = o.validation});
    const auto scene = make_scene();
    proceduray::vk::Renderer renderer(ctx, scene, renderer_options(o, scene.renderer_options(o.cache)));
    set_constants(renderer, slot, constants(o, 0u));
    print_build(ctx, renderer);
    const Run run = run_frames(renderer, o, [&](std::uint32_t f) { set_constants(renderer, slot, constants(o, f)); });
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
