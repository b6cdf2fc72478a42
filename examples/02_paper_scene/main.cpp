// The report's figure 3: a plane, two CSG Pac-men, a Julia set cut by a plane and a
// Mandelbulb, with shadows and reflections; animated over --frames. Prints timings and the SBT.
#include "../common/run.hpp"
#include "paper_scene.hpp"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  examples::Options o = examples::parse(argc, argv, "02_paper_scene", {.width = 1024, .height = 768, .frames = 1});
  if (o.exit) return *o.exit;
  try {
    proceduray::check_writable(o.out);
    proceduray::vk::Context ctx({.device = o.device, .validation = o.validation});
    paper::PaperScene scene;
    const proceduray::ShaderBindingTable& sbt = scene.build(ctx.limits());
    proceduray::vk::Renderer renderer(ctx, sbt, paper::renderer_options(o.cache));
    renderer.set(paper::constants_slot, paper::default_constants(o.width, o.height, 0.0f));
    examples::print_build(ctx, renderer);
    const examples::Run run = examples::run_frames(renderer, o, [&](std::uint32_t f) {
      renderer.set(paper::constants_slot, paper::default_constants(o.width, o.height, 0.1f * static_cast<float>(f)));
    });
    examples::print_run(run, o);
    std::printf("%s", proceduray::format_sbt(sbt).c_str());
    examples::write_last(run, o);
    return ctx.validation_messages().empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "02_paper_scene: %s\n", e.what());
    return 1;
  }
}
