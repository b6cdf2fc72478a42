// The CIS 565 project's scene: ground, three spheres, an animated metaball blob, Phong, hard
// shadows and reflections, shaded by the library's shading/lights.glsl. Prints timings and
// writes the last frame.
//   --depth N       radiance rays per path, 1 (no reflection) to 5 (default 3)
//   --depth-sweep   frame time per depth 1..5 at --size (median of --frames after 2 warm-up
//                   frames, GPU timestamps): the project's analysis of frame time against depth
#include "../common/run.hpp"
#include "cis565_scene.hpp"

#include <CLI/CLI.hpp>  // this example adds options of its own

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  std::uint32_t depth = 3;
  bool sweep = false;
  const examples::Options o = examples::parse(argc, argv, "04_cis565_scene", {.width = 960, .height = 540},
                                              [&](CLI::App& app) {
                                                app.add_option("--depth", depth, "radiance rays per path (1: no reflection)")
                                                    ->check(CLI::Range(1u, 5u))->capture_default_str();
                                                app.add_flag("--depth-sweep", sweep, "frame time per depth 1..5");
                                              });
  if (o.exit) return *o.exit;
  try {
    proceduray::check_writable(o.out);
    proceduray::vk::Context ctx({.device = o.device, .validation = o.validation});
    cis565::Cis565Scene scene(5);  // one pipeline for every depth: the frame's uniform picks it
    proceduray::vk::Renderer renderer(ctx, scene, examples::renderer_options(o, scene.renderer_options(o.cache)));
    renderer.set(cis565::constants_slot, cis565::default_constants(o.width, o.height, 0.0f, depth));
    examples::print_build(ctx, renderer);
    if (sweep) {
      std::printf("depth  trace ms (median of %u)  vs depth 1  Mrays/s (camera rays)\n", o.frames);
      double first = 0;
      for (std::uint32_t d = 1; d <= 5; ++d) {
        renderer.set(cis565::constants_slot, cis565::default_constants(o.width, o.height, 0.0f, d));
        const auto t = proceduray::vk::time_frames(renderer, o.width, o.height, {.frames = o.frames, .warm_up = 2});
        if (d == 1) first = t.trace_ms.median;
        std::printf("%5u  %22.3f  %9.2fx  %10.1f\n", d, t.trace_ms.median, t.trace_ms.median / first, t.mrays_per_s());
      }
    }
    const examples::Run run = examples::run_frames(renderer, o, [&](std::uint32_t f) {
      renderer.set(cis565::constants_slot, cis565::default_constants(o.width, o.height, 0.1f * float(f), depth));
    });
    examples::print_run(run, o);
    examples::write_last(run, o);
    return ctx.validation_messages().empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "04_cis565_scene: %s\n", e.what());
    return 1;
  }
}
